// Per-frame sub-pixel jitter: the offset of a frame's sample from the pixel centre, in pixels,
// x right, y down, each in [-0.5, 0.5) (DESIGN.md section 3).
#pragma once

#include <glm/vec2.hpp>

namespace taa {

// Radical inverse of `index` in `base` (the Halton sequence): 1 -> 1/2, 2 -> 1/4, 3 -> 3/4 ...
// for base 2. Index 0 gives 0. Negative indices are an error (returns 0).
double radicalInverse(int index, int base);

enum class JitterSource {
  Halton,  // Halton(2,3) at an index derived from the frame number
  None,    // the renderer did not jitter: sample at the pixel centre
};

struct JitterOptions {
  JitterSource source = JitterSource::Halton;
  int indexOffset = 0;  // index = frame + indexOffset (any integer)
  int period = 0;       // 0: no wrap; P > 0: index cycles through 1..P (Halton index 0, the
                        // corner (-0.5, -0.5), is skipped in that case, as engines do)
};

// The Halton index used for `frame`, after offset and period.
int haltonIndex(int frame, const JitterOptions& options);

// The jitter of `frame`: (halton2(i) - 0.5, halton3(i) - 0.5), or (0, 0) for None.
glm::vec2 frameJitter(int frame, const JitterOptions& options);

}  // namespace taa
