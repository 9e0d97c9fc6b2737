// Options of the resolve, one struct with defaults. Every field says its range and meaning.
// Fields marked [program] change the resolve shader's #defines: changing them between frames
// rebuilds the GL program; the others are uniforms and cost nothing to change.
#pragma once

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

struct ResolveOptions {
  // Weight of the current frame in the exponential blend, in (0, 1]. Smaller accumulates more
  // frames (smoother, more ghosting risk); 1 turns accumulation off.
  float blend = 0.1f;
  // Clip history toward the current 3x3 neighbourhood's YCoCg bounding box (rejects stale
  // history on disocclusion and lighting change). Off only for diagnosis.
  bool clipHistory = true;
  // [program] Take the motion vector from the closest-depth pixel of the 3x3 neighbourhood, so
  // that foreground edges carry their own motion into the background's silhouette. Needs depth.
  bool dilateMotion = true;
  // How each frame's samples were offset from pixel centres.
  JitterOptions jitter;
};

TAA_NAMESPACE_END
