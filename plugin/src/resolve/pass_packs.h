// How the window gather's pass groups lie in GL memory (issue 21): several groups of one type
// side by side in one ring (a pack), group i of a pack of n at texel x * n + i for pixel x, so a
// sample's groups are neighbours in memory and the pass draw reads a few streams of memory
// rather than one a group (docs/PERFORMANCE.md, "Pass groups side by side").
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "util/image.h"

namespace taa {

struct PassPackLayout {
  struct Pack {
    bool half = false;        // RGBA16F, else RGBA32F
    std::vector<int> groups;  // the groups it holds, in their places
    std::size_t texelBytes() const { return half ? 8 : 16; }  // a group's place
    std::size_t pixelBytes() const { return texelBytes() * groups.size(); }
  };
  struct Place {
    int pack = 0, index = 0;
  };
  std::vector<Pack> packs;
  std::vector<Place> places;  // per group
};

// Groups of one type (`halfGroups`, per group) packed in group order, as many a pack as
// `holds(groups, half)` says a ring can take (the driver's widest and largest texture).
PassPackLayout packPassGroups(const std::vector<bool>& halfGroups,
                              const std::function<bool(int, bool)>& holds);

// Rows firstRow..firstRow+rows-1 of `group` (RGBA of the pack's type) into place `index` of a
// band of `pack`'s rows (`out`: rows x width x pack.pixelBytes(), the band's first row first).
// Other places are left as they are.
void interleaveGroupRows(const ImageView& group, int firstRow, int rows, int index,
                         const PassPackLayout::Pack& pack, unsigned char* out);

// The gather's defines for a draw of groups firstGroup..firstGroup+count-1 (window_gather.frag:
// PASS_PACKS, PASS_PACK_OF, PASS_INDEX_OF, PASS_WIDTH_OF), and in `packsInDraw` the packs it
// reads, in the order of its samplers.
std::vector<std::string> passPackDefines(const PassPackLayout& layout, int firstGroup, int count,
                                         std::vector<int>* packsInDraw);

}  // namespace taa
