#include "scenegen/ray_shapes.h"

#include <limits>

namespace taa::scenes {

glm::dvec3 localBounds(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Rectangle:
      if (shape.size.x <= 0.0 || shape.size.y <= 0.0) {
        return glm::dvec3(std::numeric_limits<double>::infinity());
      }
      return {shape.size.x, shape.size.y, 0.0};
    case ShapeKind::Box:
      return shape.size;
    case ShapeKind::Sphere:
      return glm::dvec3(shape.size.x);
    case ShapeKind::Cylinder:
      return {shape.size.x, shape.size.y, shape.size.x};
  }
  return glm::dvec3(std::numeric_limits<double>::infinity());
}

ShapeFromEye::ShapeFromEye(const Shape& shape, glm::dvec3 eye) : shape_(shape), eye_(eye) {
  const double r = shape.size.x;
  if (shape.kind == ShapeKind::Sphere) c_ = eye.x * eye.x + eye.y * eye.y + eye.z * eye.z - r * r;
  if (shape.kind == ShapeKind::Cylinder) c_ = eye.x * eye.x + eye.z * eye.z - r * r;
  lo_ = -shape.size - eye;
  hi_ = shape.size - eye;
}

}  // namespace taa::scenes
