#include "farm/chunk_plan.h"

#include <algorithm>

#include "util/frame_span.h"

namespace taa::farm {

std::vector<std::vector<int>> splitIntoChunks(const std::vector<int>& shot, int chunkSize) {
  std::vector<std::vector<int>> chunks;
  for (std::size_t begin = 0; begin < shot.size(); begin += std::size_t(chunkSize)) {
    const std::size_t end = std::min(shot.size(), begin + std::size_t(chunkSize));
    chunks.emplace_back(shot.begin() + std::ptrdiff_t(begin), shot.begin() + std::ptrdiff_t(end));
  }
  return chunks;
}

std::vector<int> framesWithin(const std::vector<int>& shot, int first, int last) {
  std::vector<int> frames;
  for (int frame : shot) {
    if (frame >= first && frame <= last) frames.push_back(frame);
  }
  return frames;
}

bool startsHistory(const std::vector<int>& shot, std::size_t index, const std::set<int>& resets) {
  return index == 0 || !isNextFrame(shot[index - 1], shot[index]) || resets.count(shot[index]) > 0;
}

ChunkWork planHistoryChunk(const std::vector<int>& shot, const std::vector<int>& chunk,
                           const std::vector<int>& pending, int preroll,
                           const std::set<int>& resets) {
  ChunkWork work;
  if (pending.empty()) return work;
  const std::size_t chunkStart =
      std::size_t(std::find(shot.begin(), shot.end(), chunk.front()) - shot.begin());
  const std::size_t lastPending =
      std::size_t(std::find(shot.begin(), shot.end(), pending.back()) - shot.begin());
  std::size_t start = chunkStart;
  while (start > 0 && chunkStart - start < std::size_t(preroll) &&
         !startsHistory(shot, start, resets)) {
    --start;
  }
  const std::set<int> written(pending.begin(), pending.end());
  for (std::size_t i = start; i <= lastPending; ++i) {
    work.resolve.push_back(shot[i]);
    if (!written.count(shot[i])) work.preroll.insert(shot[i]);
  }
  work.write = pending;
  return work;
}

ChunkWork planWindowChunk(const std::vector<int>& pending) {
  return {pending, {}, pending};
}

}  // namespace taa::farm
