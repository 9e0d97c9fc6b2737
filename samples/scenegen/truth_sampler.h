// The truth of the 3D scenes (DESIGN.md section 7): each pixel's box-filtered average from a
// jittered grid of N x N cells, where a cell whose sample differs from a neighbour's (an edge,
// or a steep HDR slope) is replaced by the mean of its own jittered sub-grid, 2 x 2 to 6 x 6 by
// how much it differs. Strata are jittered in mirrored pairs (see stratumOffset).
//
// The cell grid spans the frame: a cell's jitter depends only on the seed and its place, so a
// region's pixels are exactly the whole frame's, and the cells bordering a pixel, which the
// comparison needs, are its neighbours' own cells rather than extra samples.
#pragma once

#include <cstdint>

#include "scenegen/frame_view.h"
#include "util/image.h"

namespace taa::scenes {

struct TruthSampling {
  int samplesPerAxis = 16;  // N >= 1
  std::uint32_t seed = 0;   // picks the jittered pattern
  int threads = 0;          // as parallelFor
};

// The truth of pixels [x0, x0 + w) x [y0, y0 + h) (RGBA, alpha 1).
Image renderTruth(const FrameView& view, int x0, int y0, int w, int h,
                  const TruthSampling& sampling);

}  // namespace taa::scenes
