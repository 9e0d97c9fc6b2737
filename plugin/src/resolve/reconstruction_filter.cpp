#include "resolve/reconstruction_filter.h"

#include <cmath>

namespace taa {
namespace {

float lanczos2(float x) {
  x = std::abs(x);
  if (x < 1e-5f) return 1.0f;
  if (x >= 2.0f) return 0.0f;
  const double px = 3.14159265358979323846 * double(x);
  return float(2.0 * std::sin(px) * std::sin(0.5 * px) / (px * px));
}

}  // namespace

float blackmanHarrisWeight(glm::vec2 offset) {
  return std::exp(-2.29f * (offset.x * offset.x + offset.y * offset.y));
}

float lanczos2Weight(glm::vec2 offset) { return lanczos2(offset.x) * lanczos2(offset.y); }

std::array<float, 9> reconstructionWeights(Reconstruction filter, glm::vec2 jitter) {
  std::array<float, 9> weights{};
  weights[4] = 1.0f;
  if (filter == Reconstruction::Centre) return weights;
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const glm::vec2 offset = glm::vec2(float(dx), float(dy)) + jitter;
      const float w = filter == Reconstruction::BlackmanHarris ? blackmanHarrisWeight(offset)
                                                               : lanczos2Weight(offset);
      weights[std::size_t(3 * (dy + 1) + dx + 1)] = w;
      sum += w;
    }
  }
  // A jitter far outside the pixel leaves no weight; a non-finite one (refused where jitter
  // enters: resolve/jitter.h) would leave NaN. Either way the centre sample stands alone.
  if (!(std::abs(sum) > 1e-4)) {
    weights = {};
    weights[4] = 1.0f;
    return weights;
  }
  for (float& w : weights) w = float(w / sum);
  return weights;
}

}  // namespace taa
