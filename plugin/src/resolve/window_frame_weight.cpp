#include "resolve/window_frame_weight.h"

#include <cmath>

namespace taa {

float windowFrameWeight(int frames, const WindowOptions& options) {
  double weight = 1.0;
  if (options.falloff > 0.0f) {
    const double x = double(frames) / double(options.falloff);
    weight = std::exp(-x * x);
  }
  if (options.taper) {
    const double c = std::cos(M_PI / 2.0 * double(frames) / double(options.radius + 1));
    weight *= c * c;
  }
  return float(weight);
}

}  // namespace taa
