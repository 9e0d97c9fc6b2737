// How a shot is split among farm tasks and what one task resolves (DESIGN.md section 6, Farm).
// A shot is the list of frames one taatool run would resolve; a chunk is a run of consecutive
// entries of it. Chunks never overlap, so two tasks never write the same frame.
//
// Window mode: each frame depends only on the frames within K of it, which taatool reads around
// whatever it is asked for, so a chunk resolves just its frames not yet complete, bit-identical
// to a whole-shot run.
// History mode: a frame depends on every frame before it in its history, so a chunk first
// resolves up to `preroll` frames before its start, read-only. The pre-roll is fixed per chunk
// (it does not move with the frames already complete), so a task that is killed and rerun gives
// the frames the first run would have; it stops at a history start (the shot's first frame, a
// gap, a reset frame), where the chunk is exact.
#pragma once

#include <set>
#include <vector>

namespace taa::farm {

// `shot` split into chunks of `chunkSize` frames (the last may be shorter). chunkSize >= 1.
std::vector<std::vector<int>> splitIntoChunks(const std::vector<int>& shot, int chunkSize);

// The frames of `shot` within [first, last] (a scheduler's range may run past the shot's end).
std::vector<int> framesWithin(const std::vector<int>& shot, int first, int last);

// Whether `shot[index]` starts a history in a run over the whole shot: the first frame, one
// whose predecessor in the list is not frame - 1, or a reset frame.
bool startsHistory(const std::vector<int>& shot, std::size_t index, const std::set<int>& resets);

struct ChunkWork {
  std::vector<int> resolve;   // frames to resolve, ascending
  std::set<int> preroll;      // of those, the ones only resolved for history, never written
  std::vector<int> write;     // of those, the ones written: the chunk's frames not complete
};

// History mode: `pending` (the chunk's frames not complete, ascending, a subset of `chunk`)
// resolved after up to `preroll` frames of the shot before the chunk's first frame.
ChunkWork planHistoryChunk(const std::vector<int>& shot, const std::vector<int>& chunk,
                           const std::vector<int>& pending, int preroll,
                           const std::set<int>& resets);

// Window mode: only `pending`.
ChunkWork planWindowChunk(const std::vector<int>& pending);

}  // namespace taa::farm
