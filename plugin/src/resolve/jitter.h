// Per-frame sub-pixel jitter: the offset of a frame's sample from the pixel centre, in pixels,
// x right, y down, each in [-0.5, 0.5) (DESIGN.md section 3).
#pragma once

#include <glm/vec2.hpp>

#include <string>

#include "taa/error.h"
#include "taa/options.h"

namespace taa {

// Radical inverse of `index` in `base` (the Halton sequence): 1 -> 1/2, 2 -> 1/4, 3 -> 3/4 ...
// for base 2. Index 0 gives 0. Negative indices are an error (returns 0).
double radicalInverse(long long index, int base);

// The Halton index used for `frame`, after offset and period: 64 bits, so that every frame
// number and offset has its own (frame + offset reaches past the int range).
long long haltonIndex(int frame, const JitterOptions& options);

// The jitter of `frame`: (halton2(i) - 0.5, halton3(i) - 0.5) times options.scale, or (0, 0)
// for None.
glm::vec2 frameJitter(int frame, const JitterOptions& options);

// The largest jitter taken from outside, in pixels along either axis: a sample belongs to its
// pixel's 3x3 neighbourhood. 1e38 was taken and made every reconstruction weight 0.
inline constexpr float kMaxJitter = 1.0f;

// `jitter` when both offsets are finite and within kMaxJitter; else throws taa::Error
// "jitter (x, y) from `source` is not a finite number of pixels" (or "is more than 1 pixel
// from the pixel centre") with `context`. A NaN or Inf offset (a header attribute, a sidecar,
// a host) would make every reconstruction weight NaN and the whole frame non-finite.
glm::vec2 checkedJitter(glm::vec2 jitter, const std::string& source,
                        const ErrorContext& context = {});

}  // namespace taa
