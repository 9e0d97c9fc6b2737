#include "io/views.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>


namespace taa::io {
namespace {

std::vector<std::string> stringArray(const OIIO::ImageSpec& spec, const char* name) {
  std::vector<std::string> values;
  const OIIO::ParamValue* value = spec.find_attribute(name);
  if (!value || value->type().basetype != OIIO::TypeDesc::STRING) return values;
  const int count = value->type().numelements() * value->nvalues();
  for (int i = 0; i < count; ++i) values.emplace_back(static_cast<const char* const*>(value->data())[i]);
  return values;
}

}  // namespace

FileViews readViews(const std::string& path) {
  // OpenEXR's reader by name, as io::readFrame opens files (any bytes in the name).
  auto input = OIIO::ImageInput::create("openexr");
  OIIO::ImageSpec first;
  if (!input || !input->open(path, first)) {
    OIIO::geterror();  // not an EXR, or damaged: readFrame says so with file, frame, channel
    if (input) input->geterror();
    return {};
  }
  FileViews views;
  views.channels = input->spec().channelnames;
  views.names = stringArray(input->spec(), "multiView");
  if (!views.names.empty()) return views;
  for (int part = 0; input->seek_subimage(part, 0); ++part) {
    const std::string view = input->spec().get_string_attribute("view");
    if (view.empty()) continue;
    views.names.push_back(view);
    std::string name = input->spec().get_string_attribute("name");
    if (name.empty()) name = input->spec().get_string_attribute("oiio:subimagename");
    views.parts.push_back(name);
  }
  if (views.names.size() < 2) views = FileViews{};  // one view in one part: nothing to choose
  return views;
}

std::string viewChannelName(const std::string& channel, const std::string& view) {
  const std::size_t dot = channel.rfind('.');
  return dot == std::string::npos ? view + "." + channel
                                  : channel.substr(0, dot + 1) + view + channel.substr(dot);
}

std::string viewOfChannel(const std::string& channel, const std::vector<std::string>& views) {
  const std::size_t last = channel.rfind('.');
  if (last != std::string::npos && last > 0) {
    const std::size_t before = channel.rfind('.', last - 1);
    const std::size_t start = before == std::string::npos ? 0 : before + 1;
    const std::string component = channel.substr(start, last - start);
    if (std::find(views.begin(), views.end(), component) != views.end()) return component;
  }
  return views.empty() ? "" : views.front();
}

std::string withoutView(const std::string& channel, const std::string& view) {
  const std::size_t last = channel.rfind('.');
  if (view.empty() || last == std::string::npos || last < view.size()) return channel;
  const std::size_t start = last - view.size();
  if (channel.compare(start, view.size(), view) != 0 || (start > 0 && channel[start - 1] != '.')) {
    return channel;
  }
  // "left.R" -> "R"; "Combined.left.R" -> "Combined.R".
  return start == 0 ? channel.substr(last + 1)
                    : channel.substr(0, start - 1) + channel.substr(last);
}

std::vector<std::string> passPlanNames(const std::vector<std::string>& channels,
                                       const AovLayout& layout) {
  std::vector<std::string> names;
  for (const std::string& channel : channels) names.push_back(withoutView(channel, layout.view));
  return names;
}

AovLayout layoutForView(const AovLayout& base, const FileViews& views, std::size_t index) {
  AovLayout layout = base;
  const std::string& view = views.names.at(index);
  auto has = [&](const std::string& name) {
    return std::find(views.channels.begin(), views.channels.end(), name) != views.channels.end();
  };
  // `inColorFile`: the colour itself, or an AOV read from the colour file (no pattern).
  auto forView = [&](AovSource& source, bool inColorFile) {
    if (!views.parts.empty()) {
      if (inColorFile) source.part = views.parts.at(index);
      return;
    }
    for (std::string& channel : source.channels) {
      const std::string named = viewChannelName(channel, view);
      // The default view's channels may carry no view (OpenEXR's convention).
      if (!(index == 0 && !has(named) && has(channel))) channel = named;
    }
  };
  forView(layout.color, true);
  if (layout.depth) forView(*layout.depth, layout.depth->pattern.empty());
  if (layout.motion) forView(*layout.motion, layout.motion->pattern.empty());
  if (index > 0) layout.passthrough.clear();
  if (views.parts.empty()) {
    layout.view = view;
    layout.fileViews = views.names;
  } else if (index > 0) {
    layout.partView = view;
  }
  return layout;
}

}  // namespace taa::io
