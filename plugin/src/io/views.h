// Views of a multi-view EXR, by OpenEXR's convention (Blender's and Nuke's stereo files): a
// single part whose header's `multiView` lists the views, the first being the default, and
// whose channel names carry the view before their last component
// ("ViewLayer.Combined.left.R"; the default view's channels may go without it, "R"); or one
// part per view, each with a `view` attribute. Each view is resolved as if alone (its own
// layout), and written back as one multi-view file.
#pragma once

#include <string>
#include <vector>

#include "io/aov_layout.h"

namespace taa::io {

struct FileViews {
  std::vector<std::string> names;  // in the file's order, the default view first; empty: none
  // One part per view: each view's part name, in `names`' order. Empty for a single part.
  std::vector<std::string> parts;
  std::vector<std::string> channels;  // the first part's channel names
};

// The views of the EXR file at `path`: none for a file that is not multi-view, or that cannot
// be read as EXR (reading its frame says why).
FileViews readViews(const std::string& path);

// `channel` of view `view`: the view inserted before the last component ("Combined.R" ->
// "Combined.left.R", "R" -> "left.R").
std::string viewChannelName(const std::string& channel, const std::string& view);

// The view a channel of a one-part multi-view file belongs to: the component before its last
// when that is one of `views`, else the default view (the first: OpenEXR's convention).
std::string viewOfChannel(const std::string& channel, const std::vector<std::string>& views);

// `channel` without `view` before its last component ("Combined.left.R" -> "Combined.R"); as
// it is when it has no such component or `view` is empty.
std::string withoutView(const std::string& channel, const std::string& view);

// Names whose kinds a pass plan reads: `channels` of the layout's view without the view.
std::vector<std::string> passPlanNames(const std::vector<std::string>& channels,
                                       const AovLayout& layout);

// The layout that reads view `index` of `views` with `base`'s AOVs and conventions: channel
// names with the view in them (single part; the default view keeps a name without it where the
// file has no name with it), or the view's part (one part per view: a view but the first is
// written with the view in its names, AovLayout::partView). Pass-through channels go with the
// first view only; passes with each view (its own channels, or its own part's).
AovLayout layoutForView(const AovLayout& base, const FileViews& views, std::size_t index);

}  // namespace taa::io
