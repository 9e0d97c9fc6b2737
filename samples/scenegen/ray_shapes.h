// Analytic ray intersection with the primitives of the 3D scenes, in the shape's own (local)
// space. The ray direction need not be unit length: t is in the caller's parametrisation, so a
// ray transformed into local space by an affine map keeps its t.
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

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

// Half extents of a local box around the origin holding the whole shape; +inf on the axes of
// unbounded ones.
glm::dvec3 localBounds(const Shape& shape);

// A shape seen from one local origin, the camera's, shared by every ray of a frame: what does
// not depend on the direction is worked out once. The intersections are inline: they run for
// every candidate object of every truth sample, in loops over one shape kind at a time. They
// find t alone; hitAt() completes the nearest hit.
class ShapeFromEye {
 public:
  ShapeFromEye(const Shape& shape, glm::dvec3 eye);

  ShapeKind kind() const { return shape_.kind; }
  // The smallest t in (tMin, tMax) at which eye + t * (dx, dy, dz) is on the shape, for the
  // function named after kind(); false if there is none.
  bool rectangle(double dx, double dy, double dz, double tMin, double tMax, double* t) const;
  bool box(double dx, double dy, double dz, double tMin, double tMax, double* t) const;
  bool sphere(double dx, double dy, double dz, double tMin, double tMax, double* t) const {
    return quadric(dx * dx + dy * dy + dz * dz, eye_.x * dx + eye_.y * dy + eye_.z * dz, dy, tMin,
                   tMax, t);
  }
  bool cylinder(double dx, double dy, double dz, double tMin, double tMax, double* t) const {
    return quadric(dx * dx + dz * dz, eye_.x * dx + eye_.z * dz, dy, tMin, tMax, t);
  }

  // The local point and normal at t along `direction` (a t found above).
  LocalHit hitAt(const glm::dvec3& direction, double t) const;

 private:
  bool quadric(double a, double b, double dy, double tMin, double tMax, double* t) const;

  Shape shape_;
  glm::dvec3 eye_;
  double c_ = 0.0;      // sphere and cylinder: the constant term of the quadratic in t
  glm::dvec3 lo_, hi_;  // box: the slabs relative to the eye, -size - eye and size - eye
};

inline bool ShapeFromEye::rectangle(double dx, double dy, double dz, double tMin, double tMax,
                                    double* t) const {
  if (dz == 0.0) return false;
  const double s = -eye_.z / dz;
  if (!(s > tMin && s < tMax)) return false;
  if (shape_.size.x > 0.0 && std::fabs(eye_.x + s * dx) > shape_.size.x) return false;
  if (shape_.size.y > 0.0 && std::fabs(eye_.y + s * dy) > shape_.size.y) return false;
  *t = s;
  return true;
}

inline bool ShapeFromEye::box(double dx, double dy, double dz, double tMin, double tMax,
                              double* t) const {
  const double d[3] = {dx, dy, dz};
  double near = -std::numeric_limits<double>::infinity(), far = -near;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (lo_[k] > 0.0 || hi_[k] < 0.0) return false;  // parallel to the slab, outside it
      continue;
    }
    double a = lo_[k] / d[k], b = hi_[k] / d[k];
    if (a > b) std::swap(a, b);
    near = std::fmax(near, a);
    far = std::fmin(far, b);
  }
  if (near > far) return false;
  // From inside the box the ray leaves through the far face.
  const double s = near > tMin ? near : far;
  if (!(s > tMin && s < tMax)) return false;
  *t = s;
  return true;
}

// a t^2 + 2 b t + c = 0: the smaller root inside (tMin, tMax) on the shape, else the larger one
// (the far side: from inside a sphere, or into an open cylinder's end).
inline bool ShapeFromEye::quadric(double a, double b, double dy, double tMin, double tMax,
                                  double* t) const {
  const double disc = b * b - a * c_;
  if (!(disc >= 0.0) || a == 0.0) return false;
  const double root = std::sqrt(disc);
  for (const double s : {(-b - root) / a, (-b + root) / a}) {
    if (!(s > tMin && s < tMax)) continue;
    if (shape_.kind == ShapeKind::Cylinder && std::fabs(eye_.y + s * dy) > shape_.size.y) {
      continue;
    }
    *t = s;
    return true;
  }
  return false;
}

inline LocalHit ShapeFromEye::hitAt(const glm::dvec3& d, double t) const {
  glm::dvec3 p = eye_ + t * d;
  glm::dvec3 n(0.0);
  const double r = shape_.size.x;
  switch (shape_.kind) {
    case ShapeKind::Rectangle:
      p.z = 0.0;
      n.z = 1.0;
      break;
    case ShapeKind::Box: {
      // The face hit is the axis on which the point is furthest out, relative to the size.
      int axis = 0;
      for (int k = 1; k < 3; ++k) {
        if (std::fabs(p[k]) * shape_.size[axis] > std::fabs(p[axis]) * shape_.size[k]) axis = k;
      }
      n[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
      break;
    }
    case ShapeKind::Sphere:
      n = p / r;
      break;
    case ShapeKind::Cylinder:
      n = glm::dvec3(p.x / r, 0.0, p.z / r);
      break;
  }
  return {t, p, n};
}

}  // namespace taa::scenes
