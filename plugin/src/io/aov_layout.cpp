#include "io/aov_layout.h"

#include <cctype>

#include "io/renderer_presets.h"
#include "taa/error.h"

namespace taa::io {

AovLayout cyclesLayout(const std::string& colorPattern, const std::string& layer) {
  return presetLayout("cycles", colorPattern, layer);
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

std::vector<ChannelKindRule> passRulesOf(const AovLayout& layout) {
  std::vector<ChannelKindRule> rules;
  for (const std::string& p : layout.passthrough) rules.push_back({p, ChannelKind::Copy});
  rules.insert(rules.end(), layout.passRules.begin(), layout.passRules.end());
  return rules;
}

}  // namespace taa::io
