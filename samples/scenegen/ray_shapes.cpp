#include "scenegen/ray_shapes.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>

namespace taa::scenes {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The smaller root of a t^2 + 2 b t + c = 0 inside (tMin, tMax), else the larger one.
bool quadraticRoot(double a, double b, double c, double tMin, double tMax, double* t) {
  const double disc = b * b - a * c;
  if (!(disc >= 0.0) || a == 0.0) return false;
  const double s = std::sqrt(disc);
  const double t0 = (-b - s) / a, t1 = (-b + s) / a;
  if (t0 > tMin && t0 < tMax) {
    *t = t0;
    return true;
  }
  if (t1 > tMin && t1 < tMax) {
    *t = t1;
    return true;
  }
  return false;
}

bool rectangle(const Shape& s, glm::dvec3 o, glm::dvec3 d, double tMin, double tMax,
               LocalHit* hit) {
  if (d.z == 0.0) return false;
  const double t = -o.z / d.z;
  if (!(t > tMin && t < tMax)) return false;
  const glm::dvec3 p = o + t * d;
  if (s.size.x > 0.0 && std::fabs(p.x) > s.size.x) return false;
  if (s.size.y > 0.0 && std::fabs(p.y) > s.size.y) return false;
  *hit = {t, glm::dvec3(p.x, p.y, 0.0), {0.0, 0.0, 1.0}};
  return true;
}

bool box(const Shape& s, glm::dvec3 o, glm::dvec3 d, double tMin, double tMax, LocalHit* hit) {
  double near = -kInf, far = kInf;
  int nearAxis = 0, farAxis = 0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (std::fabs(o[k]) > s.size[k]) return false;
      continue;
    }
    double a = (-s.size[k] - o[k]) / d[k], b = (s.size[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    if (a > near) {
      near = a;
      nearAxis = k;
    }
    if (b < far) {
      far = b;
      farAxis = k;
    }
  }
  if (near > far) return false;
  double t = near;
  int axis = nearAxis;
  if (!(t > tMin)) {  // the origin is inside the box: leave through the far face
    t = far;
    axis = farAxis;
  }
  if (!(t > tMin && t < tMax)) return false;
  const glm::dvec3 p = o + t * d;
  glm::dvec3 n(0.0);
  n[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
  *hit = {t, p, n};
  return true;
}

bool sphere(const Shape& s, glm::dvec3 o, glm::dvec3 d, double tMin, double tMax,
            LocalHit* hit) {
  double t = 0.0;
  const double r = s.size.x;
  if (!quadraticRoot(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - r * r, tMin, tMax, &t)) {
    return false;
  }
  const glm::dvec3 p = o + t * d;
  *hit = {t, p, p / r};
  return true;
}

bool cylinder(const Shape& s, glm::dvec3 o, glm::dvec3 d, double tMin, double tMax,
              LocalHit* hit) {
  const double r = s.size.x;
  const double a = d.x * d.x + d.z * d.z;
  const double b = o.x * d.x + o.z * d.z;
  const double c = o.x * o.x + o.z * o.z - r * r;
  const double disc = b * b - a * c;
  if (a == 0.0 || !(disc >= 0.0)) return false;
  const double root = std::sqrt(disc);
  for (const double t : {(-b - root) / a, (-b + root) / a}) {
    if (!(t > tMin && t < tMax)) continue;
    const glm::dvec3 p = o + t * d;
    if (std::fabs(p.y) > s.size.y) continue;
    *hit = {t, p, glm::dvec3(p.x / r, 0.0, p.z / r)};
    return true;
  }
  return false;
}

}  // namespace

bool intersect(const Shape& shape, glm::dvec3 origin, glm::dvec3 direction, double tMin,
               double tMax, LocalHit* hit) {
  switch (shape.kind) {
    case ShapeKind::Rectangle:
      return rectangle(shape, origin, direction, tMin, tMax, hit);
    case ShapeKind::Box:
      return box(shape, origin, direction, tMin, tMax, hit);
    case ShapeKind::Sphere:
      return sphere(shape, origin, direction, tMin, tMax, hit);
    case ShapeKind::Cylinder:
      return cylinder(shape, origin, direction, tMin, tMax, hit);
  }
  return false;
}

double boundingRadius(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Rectangle:
      if (shape.size.x <= 0.0 || shape.size.y <= 0.0) return kInf;
      return std::hypot(shape.size.x, shape.size.y);
    case ShapeKind::Box:
      return glm::length(shape.size);
    case ShapeKind::Sphere:
      return shape.size.x;
    case ShapeKind::Cylinder:
      return std::hypot(shape.size.x, shape.size.y);
  }
  return kInf;
}

}  // namespace taa::scenes
