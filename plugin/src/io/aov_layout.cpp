#include "io/aov_layout.h"

#include <cctype>

#include "taa/error.h"

namespace taa::io {

AovLayout cyclesLayout(const std::string& colorPattern, const std::string& layer) {
  // Cycles names passes "<layer>.<pass>.<channel>"; an empty layer name drops the prefix.
  const std::string prefix = layer.empty() ? std::string() : layer + ".";
  AovLayout layout;
  layout.color = {colorPattern,
                  {prefix + "Combined.R", prefix + "Combined.G", prefix + "Combined.B",
                   prefix + "Combined.A"}};
  layout.depth = AovSource{"", {prefix + "Depth.Z"}};
  layout.motion = AovSource{"", {prefix + "Vector.X", prefix + "Vector.Y"}};
  // Vector.XY = previous - current in pixels with y up (verified on a Blender render).
  layout.motionConvention.yUp = true;
  layout.motionConvention.toPrevious = true;
  layout.motionConvention.scale = 1.0f;
  layout.depthConvention.noHitAbove = 1e9f;  // Cycles writes 1e10 where a ray hits nothing
  return layout;
}

std::vector<std::string> parseChannelList(const std::string& text) {
  std::vector<std::string> names;
  std::size_t itemBegin = 0;
  while (itemBegin <= text.size()) {
    std::size_t itemEnd = text.find(',', itemBegin);
    if (itemEnd == std::string::npos) itemEnd = text.size();
    std::size_t begin = itemBegin;
    std::size_t end = itemEnd;
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    if (begin == end) {
      throw Error("malformed channel list \"" + text + "\": empty channel name");
    }
    names.push_back(text.substr(begin, end - begin));
    itemBegin = itemEnd + 1;
  }
  return names;
}

}  // namespace taa::io
