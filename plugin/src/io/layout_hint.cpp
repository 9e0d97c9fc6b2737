#include "io/layout_hint.h"

#include <algorithm>

namespace taa::io {
namespace {

// The view layers of a Blender multilayer file: the prefixes of its "<layer>.Combined.*".
std::vector<std::string> blenderViewLayers(const OIIO::ImageSpec& spec) {
  std::vector<std::string> layers;
  for (const std::string& name : spec.channelnames) {
    const std::size_t at = name.find(".Combined.");
    if (at == std::string::npos || at == 0) continue;
    const std::string layer = name.substr(0, at);
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) layers.push_back(layer);
  }
  return layers;
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

std::string layoutHint(const OIIO::ImageSpec& spec, const std::vector<std::string>& missing) {
  if (!spec.find_attribute("BlenderMultiChannel")) return "";
  const std::vector<std::string> layers = blenderViewLayers(spec);
  const std::string layersText =
      layers.empty() ? "no Combined pass found"
                     : (layers.size() == 1 ? "view layer " : "view layers ") + listed(layers);
  const bool presetChannels = std::any_of(missing.begin(), missing.end(), [](const auto& name) {
    return name.find(".Combined.") != std::string::npos ||
           name.find(".Depth.") != std::string::npos ||
           name.find(".Vector.") != std::string::npos;
  });
  if (!presetChannels) {
    return "the header says Blender wrote it (BlenderMultiChannel): --preset cycles reads its "
           "Combined, Depth and Vector passes (" + layersText +
           (layers.size() == 1 && layers[0] != "ViewLayer" ? "; add --layer " + layers[0] : "") +
           ")";
  }
  if (!layers.empty() &&
      std::none_of(missing.begin(), missing.end(), [&](const std::string& name) {
        return std::any_of(layers.begin(), layers.end(), [&](const std::string& layer) {
          return name.rfind(layer + ".", 0) == 0;
        });
      })) {
    return "the file's " + layersText + ": --layer " + layers.front() + " names " +
           (layers.size() == 1 ? "it" : "the first");
  }
  return "";
}

}  // namespace taa::io
