#include "resolve/pass_packs.h"

#include <algorithm>
#include <cstring>

#include "taa/error.h"

namespace taa {

PassPackLayout packPassGroups(const std::vector<bool>& halfGroups,
                              const std::function<bool(int, bool)>& holds) {
  PassPackLayout layout;
  layout.places.resize(halfGroups.size());
  for (const bool half : {true, false}) {
    std::vector<int> ofType;
    for (std::size_t g = 0; g < halfGroups.size(); ++g) {
      if (halfGroups[g] == half) ofType.push_back(int(g));
    }
    for (std::size_t next = 0; next < ofType.size();) {
      // One group a pack where not even two fit: that ring is the one a group always had.
      int n = int(ofType.size() - next);
      while (n > 1 && !holds(n, half)) --n;
      PassPackLayout::Pack pack;
      pack.half = half;
      for (int i = 0; i < n; ++i) {
        const int g = ofType[next + std::size_t(i)];
        layout.places[std::size_t(g)] = {int(layout.packs.size()), i};
        pack.groups.push_back(g);
      }
      layout.packs.push_back(std::move(pack));
      next += std::size_t(n);
    }
  }
  return layout;
}

void interleaveGroupRows(const ImageView& group, int firstRow, int rows, int index,
                         const PassPackLayout::Pack& pack, unsigned char* out) {
  if (!group || group.channels != 4 || (group.type == SampleType::Half) != pack.half ||
      firstRow < 0 || firstRow + rows > group.height || index < 0 ||
      index >= int(pack.groups.size())) {
    throw Error("pass packs: a group's rows do not fit its pack");
  }
  const std::size_t texelBytes = pack.texelBytes(), stride = pack.pixelBytes();
  const std::size_t texels = std::size_t(rows) * std::size_t(group.width);
  const auto* from = static_cast<const unsigned char*>(group.data) +
                     std::size_t(firstRow) * std::size_t(group.width) * texelBytes;
  unsigned char* to = out + texelBytes * std::size_t(index);
  for (std::size_t t = 0; t < texels; ++t) {
    std::memcpy(to + t * stride, from + t * texelBytes, texelBytes);
  }
}

std::vector<std::string> passPackDefines(const PassPackLayout& layout, int firstGroup, int count,
                                         std::vector<int>* packsInDraw) {
  packsInDraw->clear();
  std::string packOf, indexOf, widthOf;
  for (int g = firstGroup; g < firstGroup + count; ++g) {
    const PassPackLayout::Place& place = layout.places.at(std::size_t(g));
    auto found = std::find(packsInDraw->begin(), packsInDraw->end(), place.pack);
    if (found == packsInDraw->end()) found = packsInDraw->insert(packsInDraw->end(), place.pack);
    const char* comma = g == firstGroup ? "" : ", ";
    packOf += comma + std::to_string(found - packsInDraw->begin());
    indexOf += comma + std::to_string(place.index);
    widthOf += comma + std::to_string(layout.packs[std::size_t(place.pack)].groups.size());
  }
  return {"#define PASS_PACKS " + std::to_string(packsInDraw->size()),
          "#define PASS_PACK_OF int[](" + packOf + ")",
          "#define PASS_INDEX_OF int[](" + indexOf + ")",
          "#define PASS_WIDTH_OF int[](" + widthOf + ")"};
}

}  // namespace taa
