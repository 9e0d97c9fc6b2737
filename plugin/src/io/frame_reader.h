// Reads one frame's AOVs through OpenImageIO and converts them to internal conventions.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

#include <optional>

#include "io/aov_layout.h"
#include "resolve/camera.h"
#include "util/image.h"

namespace taa::io {

struct FrameData {
  int frame = 0;
  Image color;   // RGBA, premultiplied as stored; NaN/Inf replaced by 0
  Image depth;   // 1 channel, planar, +inf = no hit; empty if the layout has no depth
  Image motion;  // 2 channels, pixels, y down, to previous; empty if the layout has no motion
  int nonFiniteColorValues = 0;   // how many color values were NaN/Inf and scrubbed to 0
  Image nonFiniteMask;            // 1 channel: 1 where a color value was scrubbed, else 0
  std::optional<FrameCamera> camera;  // from the color header's worldToCamera + worldToNDC
  RasterWindow window;            // the data window's place in the display window
  OIIO::ImageSpec colorSpec;      // the color file's header: windows and metadata for output
  std::string colorPath;
};

// Reads frame `frame`. All images cover the color file's data window. An AOV with an empty
// pattern is read from the color file, which is opened once. Channels are looked up by name in
// subimage 0, in the order the layout lists them (not the file's order).
// Conversions: color NaN/Inf -> 0 (counted), 3 channels -> A = 1; depth at or above
// noHitAbove, NaN or +-Inf -> +inf; motion per MotionConvention, then NaN/Inf -> 0.
// Throws taa::Error naming file, frame and channel for: a missing or unreadable file, a non-EXR
// (e.g. a PNG, whatever its name), truncated or corrupt file, a missing channel (listing those
// available), a wrong channel count for an AOV, depth/motion windows that differ from color's
// (stating both).
FrameData readFrame(const AovLayout& layout, int frame);

}  // namespace taa::io
