// A hint for a file that lacks the channels asked for, from what its header says about the
// renderer that wrote it: a Blender multilayer file read without --preset cycles lists dozens
// of channel names and no way forward otherwise (issue 24).
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace taa::io {

// "" when the header says nothing useful. For a Blender multilayer file (header attribute
// BlenderMultiChannel) whose missing channels are not the Cycles preset's: that --preset cycles
// reads it, with the view layers the file holds; for the preset's channels with another view
// layer in the file: the --layer that names it.
std::string layoutHint(const OIIO::ImageSpec& spec, const std::vector<std::string>& missing);

}  // namespace taa::io
