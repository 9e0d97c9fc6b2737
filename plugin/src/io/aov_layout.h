// Where a frame's color, depth and motion live in the user's files, and how their values map
// to taa's internal conventions (DESIGN.md section 3). Conversion happens once, on load
// (io/aov_conversion); renderer presets (io/renderer_presets) fill these structs.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/channel_kinds.h"

namespace taa::io {

// One AOV: a file pattern (empty = the color file), the channel names to read from it and, for
// multi-part EXR files, the part (empty = the first part that holds every channel).
struct AovSource {
  AovSource(std::string filePattern = {}, std::vector<std::string> channelNames = {},
            std::string partName = {})
      : pattern(std::move(filePattern)),
        channels(std::move(channelNames)),
        part(std::move(partName)) {}

  std::string pattern;
  std::vector<std::string> channels;
  std::string part;
};

// Units of the motion AOV's values.
enum class MotionUnits {
  Pixels,  // raster pixels
  Ndc,     // [-1, 1] across the display window: 2 units = display width (x) or height (y)
  Uv,      // [0, 1] across the display window: 1 unit = display width (x) or height (y)
};

// How the motion values are stored.
enum class MotionEncoding {
  Signed,   // the value is the motion
  Centred,  // 0.5 = no motion: motion = (value - 0.5) * 2 * centredMax (8/16-bit friendly)
};

// Motion in the file -> internal (pixels, y down, pointing to the previous frame):
//   m = Centred ? (file - 0.5) * 2 * centredMax : file          (per component)
//   m *= units: 1 | display size / 2 | display size              (Pixels | Ndc | Uv)
//   internal.x = scale * m.x * (toPrevious ? 1 : -1)
//   internal.y = scale * m.y * (toPrevious ? 1 : -1) * (yUp ? -1 : 1)
struct MotionConvention {
  bool yUp = false;        // file's y axis points up (Cycles, Nuke)
  bool toPrevious = true;  // vector points from current to previous position; false: forward
                           // in time (current -> next, or previous -> current velocity)
  float scale = 1.0f;      // multiplies the vector (e.g. for a different resolution)
  MotionUnits units = MotionUnits::Pixels;
  MotionEncoding encoding = MotionEncoding::Signed;
  float centredMax = 1.0f;  // Centred: the motion (in `units`) that a value of 1 stands for
};

// What the depth AOV's values measure.
enum class DepthKind {
  Planar,     // distance along the view axis (internal)
  Radial,     // distance from the camera centre along the pixel's ray (needs the camera)
  Ndc,        // depth-buffer value in [0, 1], 0 at near, 1 at far (D3D / GL window depth)
  ReversedZ,  // 1 at near, 0 at far (or at infinity when far is +inf)
  Inverse,    // 1 / planar distance (Nuke)
};

// Depth in the file -> internal (positive planar distance, +inf where nothing was hit).
// Each kind's own sentinel is "no hit": Ndc values >= 1, ReversedZ and Inverse values <= 0;
// NaN and +-inf always. After conversion, planar distances at or above noHitAbove are no hit.
struct DepthConvention {
  DepthKind kind = DepthKind::Planar;
  float noHitAbove = 1e9f;  // Cycles writes 1e10 where a ray hits nothing
  double nearPlane = 0.1;   // Ndc and ReversedZ: the projection's near and far planes (far may
  double farPlane = 1e4;    // be +inf for ReversedZ)
  // Radial: horizontal field of view of a centred pinhole camera over the display window,
  // used when the frame has no camera matrices (header or sidecar).
  std::optional<double> horizontalFovDegrees;
};

struct AovLayout {
  AovSource color;                  // 3 or 4 channels: R, G, B[, A]; missing A reads as 1
  std::optional<AovSource> depth;   // 1 channel
  std::optional<AovSource> motion;  // 2 channels (x, y)
  MotionConvention motionConvention;
  DepthConvention depthConvention;
  // Glob patterns (fnmatch) on channel names of the color file's part: channels copied
  // through to the output untouched (e.g. "ViewLayer.*", "*.Z").
  std::vector<std::string> passthrough;
  // Read every other channel of the color file's part as a pass (io/channel_kinds), to be
  // resolved by its kind; `passRules` come first, pass-through patterns count as "copy".
  bool passes = false;
  std::vector<ChannelKindRule> passRules;
  // A view of a one-part multi-view file (io/views.h): its passes are the channels of this
  // view alone, and their kinds come from their names without the view ("DiffDir.left.R" is
  // a DiffDir). Empty: the file has no views, or one part per view.
  std::string view;
  std::vector<std::string> fileViews;  // the file's views, the default one first
  // A view of a file of one part per view, but the first: its part's names carry no view, so
  // its channels (colour and passes) are written with the view in their names (the output is
  // one multi-view part). Empty otherwise.
  std::string partView;
};

// The Blender Cycles multi-layer layout for render layer `layer` ("ViewLayer"): all AOVs in the
// color file, <layer>.Combined.RGBA, <layer>.Depth.Z (planar, 1e10 = no hit),
// <layer>.Vector.XY (pixels, y up, X/Y = previous - current).
AovLayout cyclesLayout(const std::string& colorPattern, const std::string& layer = "ViewLayer");

// The rules that give the layout's passes their kinds: pass-through patterns as "copy", then
// `passRules`.
std::vector<ChannelKindRule> passRulesOf(const AovLayout& layout);

// Splits "R,G,B,A" into names; empty items are an error (taa::Error).
std::vector<std::string> parseChannelList(const std::string& text);

}  // namespace taa::io
