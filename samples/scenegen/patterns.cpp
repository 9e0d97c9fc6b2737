#include "scenegen/patterns.h"

#include <cmath>
#include <cstdint>

namespace taa::scenes {
namespace {

// Coordinates are shifted by this before splitting into cell and fraction so that truncation
// rounds down for every position a scene uses (|x| / period < 2^30). It also keeps std::floor,
// a library call on baseline x86-64, out of the truth render's hot loop.
constexpr double kShift = 1073741824.0;  // 2^30

struct PeriodSplit {
  std::int64_t cell;  // which period x falls in (offset by a constant)
  double fraction;    // position within the period, in [0, 1)
};

inline PeriodSplit splitPeriod(double x, double period) {
  const double t = x * (1.0 / period) + kShift;
  const auto cell = static_cast<std::int64_t>(t);
  return {cell, t - double(cell)};
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

glm::vec3 finePattern(glm::dvec2 p) {
  // Computed without early exits: branches on a pattern this fine mispredict constantly.
  const bool line =
      splitPeriod(p.x, 11.3).fraction < 0.3 / 11.3 || splitPeriod(p.y, 9.7).fraction < 0.3 / 9.7;
  const bool oddCell = (splitPeriod(p.x, 1.7).cell + splitPeriod(p.y, 1.7).cell) & 1;
  // Diagonal stripes at a non-axis angle so the aliasing has no preferred direction.
  const bool stripe = splitPeriod(p.x + 0.6 * p.y, 3.3).fraction < 0.5;
  // A coarse bright band gives the image large-scale HDR structure as well.
  const bool band = splitPeriod(p.x - 0.35 * p.y, 57.0).fraction < 9.0 / 57.0;

  glm::vec3 color = oddCell ? glm::vec3(0.9f, 0.85f, 0.8f) : glm::vec3(0.02f, 0.03f, 0.05f);
  if (stripe) color *= glm::vec3(1.0f, 0.55f, 0.3f);
  if (band) color *= 2.5f;
  // Thin lines sit on top and are the brightest (HDR) feature.
  return line ? glm::vec3(4.0f, 3.6f, 3.0f) : color;
}

glm::vec3 objectPattern(glm::dvec2 p) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  if (std::fabs(r - 25.0) < 0.25) return {3.5f, 3.5f, 3.5f};
  const double turns = std::atan2(p.y, p.x) * (1.0 / (2.0 * kPi));
  const bool ring = splitPeriod(r, 2.6).fraction < 0.5;
  const bool spoke = splitPeriod(turns, 1.0 / 24.0).fraction < 0.5;
  if (ring != spoke) return {0.1f, 0.45f, 1.6f};
  return {0.05f, 0.08f, 0.1f};
}

}  // namespace taa::scenes
