#include "scenegen/textures_3d.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace taa::scenes {

glm::vec3 bricks(glm::dvec2 p, double w, double h, double mortar, glm::vec3 brick,
                 glm::vec3 joint) {
  const double row = std::floor(p.y / h);
  const double x = p.x + (std::fmod(std::fabs(row), 2.0) == 1.0 ? 0.5 * w : 0.0);
  const double fx = periodFraction(x, w) * w, fy = periodFraction(p.y, h) * h;
  if (fx < mortar || fy < mortar) return joint;
  // A per-brick tint so that the wall is not a perfect repeat.
  const double id = std::floor(x / w) * 12.9898 + row * 78.233;
  const float tint = float(0.8 + 0.4 * periodFraction(std::sin(id) * 43758.5453, 1.0));
  return brick * tint;
}

bool chainLink(glm::dvec2 p, double spacing, double width) {
  const double u = periodFraction(p.x + p.y, spacing) * spacing;
  const double v = periodFraction(p.x - p.y, spacing) * spacing;
  return u < width || v < width;
}

glm::vec3 lambert(glm::vec3 albedo, glm::dvec3 normal) {
  static const glm::dvec3 sun = glm::normalize(glm::dvec3(0.45, 0.8, 0.4));
  const double cosine = std::max(0.0, glm::dot(normal, sun));
  return albedo * float(0.3 + 0.9 * cosine);
}

glm::vec3 fog(glm::vec3 color, glm::vec3 far, double distance, double range) {
  const float keep = float(std::exp(-(distance / range) * (distance / range)));
  return far + (color - far) * keep;
}

glm::vec3 daySky(glm::dvec3 d) {
  const double up = std::clamp(d.y, -1.0, 1.0);
  const glm::vec3 horizon(0.9f, 0.95f, 1.05f), zenith(0.25f, 0.45f, 0.9f);
  const float t = float(std::sqrt(std::max(0.0, up)));
  const float clouds = 0.08f * std::sin(float(7.0 * d.x + 3.0 * d.z)) * std::sin(float(11.0 * up));
  return horizon + (zenith - horizon) * t + glm::vec3(clouds);
}

}  // namespace taa::scenes
