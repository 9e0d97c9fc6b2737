// Analytic textures for the test scenes, in layer-local pixel coordinates. They are built to
// alias: features near and above the Nyquist rate, thin lines, and mildly HDR values (0..4).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace taa::scenes {

// Background: a fine checker (1.7 px cells), diagonal stripes (3.3 px period) that tint it,
// and bright thin lines (0.3 px wide) on a coarse grid. Values in [0.02, 4].
glm::vec3 finePattern(glm::dvec2 p);

// Object texture around its own origin: concentric rings (2.6 px period) cut by spokes, with a
// bright thin ring at radius 25 px, in cool colours distinct from the background.
// Values in [0.05, 3.5].
glm::vec3 objectPattern(glm::dvec2 p);

// A disc of `radius` around the layer origin.
struct DiscShape {
  double radius = 1.0;
  bool operator()(glm::dvec2 p) const { return p.x * p.x + p.y * p.y < radius * radius; }
};

}  // namespace taa::scenes
