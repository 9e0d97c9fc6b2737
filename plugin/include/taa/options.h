// Options of the resolve, one struct with defaults. Every field says its range and meaning.
// Fields marked [program] change the resolve shader's #defines: changing them between frames
// rebuilds the GL program; the others are uniforms and cost nothing to change.
#pragma once

#include <string>

#include "taa/version.h"

TAA_NAMESPACE_BEGIN

enum class JitterSource {
  Halton,  // Halton(2,3) at an index derived from the frame number (the default)
  None,    // the renderer did not jitter: samples sit at pixel centres
};

struct JitterOptions {
  JitterSource source = JitterSource::Halton;
  // Halton index = frame + indexOffset. Any integer; use it when the renderer's jitter index
  // is not the frame number (e.g. -1001 for a sequence starting at 1001 whose index starts at 0).
  int indexOffset = 0;
  // 0: the index grows forever. P > 0: the index cycles through 1..P (Halton's index 0, the
  // corner (-0.5, -0.5), is skipped, as game engines do with their 8- or 16-sample cycles).
  int period = 0;
};

// The OpenColorIO tonemap bracket (DESIGN.md section 5): the resolve runs on colour converted
// from `colorspaceIn` into the `bracket` working space, and its result is converted from the
// working space into `colorspaceOut`. All fields are [program].
struct ColorOptions {
  // An OCIO config file. Empty: $OCIO if set, else taa's shipped config (ocio/config.ocio,
  // embedded in the library).
  std::string ocioConfig;
  // Colorspace (or role) of the input colour.
  std::string colorspaceIn = "scene_linear";
  // Working space of the resolve: a colorspace or named transform of the config, or "none"
  // (no bracket: the resolve runs on input values).
  std::string bracket = "none";
  // Colorspace (or role) of the output. Empty: the same as colorspaceIn.
  std::string colorspaceOut;
};

enum class Rectify { None, Clamp, Clip };
enum class BoxSpace { RGB, YCoCg };

struct ResolveOptions {
  // Weight of the current frame in the exponential blend, in (0, 1]. Smaller accumulates more
  // frames (smoother, more ghosting risk); 1 turns accumulation off.
  float blend = 0.1f;
  // [program] How history is brought back inside the current 3x3 neighbourhood's colour box,
  // which rejects stale history after disocclusion or lighting change:
  //   Clip  move it toward the filtered current colour until it enters the box (keeps hue)
  //   Clamp clamp each component to the box (the textbook version; shifts hue)
  //   None  keep it (diagnosis only: ghosts)
  Rectify rectify = Rectify::Clip;
  // [program] Colour space of the neighbourhood box: YCoCg hugs natural colours tighter.
  BoxSpace boxSpace = BoxSpace::YCoCg;
  // [program] Take the motion vector from the closest-depth pixel of the 3x3 neighbourhood, so
  // that foreground edges carry their own motion into the background's silhouette. Needs depth.
  bool dilateMotion = true;
  // How each frame's samples were offset from pixel centres.
  JitterOptions jitter;
  // [program] The tonemap bracket around the resolve.
  ColorOptions color;
};

TAA_NAMESPACE_END
