// Procedural textures and lighting of the 3D scenes. Hard-edged ones alias on purpose; HDR
// features have smooth profiles so that the truth converges (an edge worth 1000 would need
// millions of samples per pixel).
#pragma once

#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace taa::scenes {

// periodFraction, checker and smoothBump are inline: the truth evaluates them for every sample.

// Fraction of x's period `period` at which x lies, in [0, 1).
inline double periodFraction(double x, double period) {
  const double t = x / period;
  return t - std::floor(t);
}

// Checker of square cells of side `cell`: a on even cells, b on odd ones.
inline glm::vec3 checker(glm::dvec2 p, double cell, glm::vec3 a, glm::vec3 b) {
  const long long k = (long long)(std::floor(p.x / cell)) + (long long)(std::floor(p.y / cell));
  return (k & 1) ? b : a;
}

// Running-bond bricks (w x h) with mortar joints of width `mortar`.
glm::vec3 bricks(glm::dvec2 p, double w, double h, double mortar, glm::vec3 brick,
                 glm::vec3 joint);

// Chain-link fence: two families of diagonal wires `spacing` apart, `width` wide.
bool chainLink(glm::dvec2 p, double spacing, double width);

// A smooth bump: 1 at r = 0 falling to 0 at r = radius, (1 - (r/R)^2)^2, C1 at the rim.
inline double smoothBump(double r, double radius) {
  if (r >= radius) return 0.0;
  const double q = 1.0 - (r / radius) * (r / radius);
  return q * q;
}

// Diffuse lighting under the scenes' one sun and sky: albedo * (ambient + sun * cos).
glm::vec3 lambert(glm::vec3 albedo, glm::dvec3 normal);

// Mixes `color` toward `far` with distance (fog), Gaussian in distance / range.
glm::vec3 fog(glm::vec3 color, glm::vec3 far, double distance, double range);

// A smooth daylight sky: horizon-to-zenith gradient, soft low-contrast cloud bands.
glm::vec3 daySky(glm::dvec3 direction);

}  // namespace taa::scenes
