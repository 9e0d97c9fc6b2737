// Analytic ray intersection with the primitives of the 3D scenes, in the shape's own (local)
// space. The ray direction need not be unit length: t is in the caller's parametrisation, so a
// ray transformed into local space by an affine map keeps its t.
#pragma once

#include <glm/vec3.hpp>

namespace taa::scenes {

enum class ShapeKind {
  Rectangle,  // the plane z = 0, |x| <= size.x, |y| <= size.y (size <= 0: unbounded)
  Box,        // |x| <= size.x, |y| <= size.y, |z| <= size.z
  Sphere,     // radius size.x around the origin
  Cylinder,   // radius size.x around the y axis, |y| <= size.y, open ends (wires, poles)
};

struct Shape {
  ShapeKind kind = ShapeKind::Sphere;
  glm::dvec3 size{1.0};
};

struct LocalHit {
  double t = 0.0;
  glm::dvec3 point{0.0};   // local
  glm::dvec3 normal{0.0};  // local, unit, facing the ray's side not guaranteed
};

// The nearest hit with tMin < t < tMax; false when there is none.
bool intersect(const Shape& shape, glm::dvec3 origin, glm::dvec3 direction, double tMin,
               double tMax, LocalHit* hit);

// Radius of a local sphere around the origin holding the whole shape; +inf for unbounded ones.
double boundingRadius(const Shape& shape);

}  // namespace taa::scenes
