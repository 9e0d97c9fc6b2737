// The window resolve's weight of a source frame by its distance in frames from the resolved one.
#pragma once

#include "taa/options.h"

namespace taa {

// exp(-(frames / falloff)^2) (falloff 0: 1), times, with `taper`, a Hann window over the K
// frames each side, cos^2(pi/2 frames / (K + 1)): frames enter and leave a moving window
// gently, so the output does not step when they do. The same for every pixel: computed once
// per source here rather than per pixel in the gather.
float windowFrameWeight(int frames, const WindowOptions& options);

}  // namespace taa
