// Where a frame's color, depth and motion live in the user's files, and how their values map
// to taa's internal conventions (DESIGN.md section 3). Conversion happens once, on load.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace taa::io {

// One AOV: a file pattern (empty = the color file) and the channel names to read from it.
struct AovSource {
  std::string pattern;
  std::vector<std::string> channels;
};

// Motion in the file -> internal (pixels, y down, pointing to the previous frame):
//   internal.x = scale * file[0] * (toPrevious ? 1 : -1)
//   internal.y = scale * file[1] * (toPrevious ? 1 : -1) * (yUp ? -1 : 1)
struct MotionConvention {
  bool yUp = false;        // file's y axis points up (Cycles, Nuke)
  bool toPrevious = true;  // vector points from current to previous position
  float scale = 1.0f;      // multiplies the vector (e.g. for a different resolution)
};

// Depth in the file -> internal (positive planar distance, +inf where nothing was hit).
struct DepthConvention {
  float noHitAbove = 1e9f;  // values at or above this are "no hit" (Cycles writes 1e10)
};

struct AovLayout {
  AovSource color;                  // 3 or 4 channels: R, G, B[, A]; missing A reads as 1
  std::optional<AovSource> depth;   // 1 channel
  std::optional<AovSource> motion;  // 2 channels (x, y)
  MotionConvention motionConvention;
  DepthConvention depthConvention;
};

// The Blender Cycles multi-layer layout for render layer `layer` ("ViewLayer"): all AOVs in the
// color file, <layer>.Combined.RGBA, <layer>.Depth.Z (planar, 1e10 = no hit),
// <layer>.Vector.XY (pixels, y up, X/Y = previous - current).
AovLayout cyclesLayout(const std::string& colorPattern, const std::string& layer = "ViewLayer");

// Splits "R,G,B,A" into names; empty items are an error (taa::Error).
std::vector<std::string> parseChannelList(const std::string& text);

}  // namespace taa::io
