// Reads one frame's AOVs through OpenImageIO and converts them to internal conventions.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

#include "io/aov_layout.h"
#include "util/image.h"

namespace taa::io {

struct FrameData {
  int frame = 0;
  Image color;   // RGBA, premultiplied as stored; NaN/Inf replaced by 0
  Image depth;   // 1 channel, planar, +inf = no hit; empty if the layout has no depth
  Image motion;  // 2 channels, pixels, y down, to previous; empty if the layout has no motion
  int nonFiniteColorValues = 0;   // how many color values were NaN/Inf and scrubbed to 0
  OIIO::ImageSpec colorSpec;      // the color file's header: windows and metadata for output
  std::string colorPath;
};

// Reads frame `frame`. All images cover the color file's data window. Throws taa::Error naming
// file, frame and channel for: a missing or unreadable file, a non-EXR or truncated file, a
// missing channel (listing those available), depth/motion windows that differ from color's.
FrameData readFrame(const AovLayout& layout, int frame);

}  // namespace taa::io
