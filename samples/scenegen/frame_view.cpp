#include "scenegen/frame_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace taa::scenes {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kTile = 8;             // tile side, px
constexpr double kTileMargin = 1.0;  // px each tile's test reaches past its edges: rays just
                                     // outside the raster (the truth's outer ring) and rounding
constexpr int kBatch = 64;           // rays traced together
constexpr double kTMin = 1e-6;       // hits nearer than this along a ray are ignored

enum class Reach { Nowhere, Box, Everywhere };

// Where on the raster an object can be hit: within the projected corners of its local bounds
// (a convex hull in front of the camera projects into the hull of its projected corners);
// nowhere when the bounds lie wholly behind the camera (camera rays have t, the planar depth,
// above kTMin); anywhere when unbounded or reaching behind the camera.
Reach rasterBounds(const Camera& camera, const glm::dmat4& toWorld, const Shape& shape,
                   glm::dvec2* lo, glm::dvec2* hi) {
  const glm::dvec3 half = localBounds(shape);
  if (!std::isfinite(half.x + half.y + half.z)) return Reach::Everywhere;
  *lo = glm::dvec2(kInf);
  *hi = glm::dvec2(-kInf);
  int behind = 0;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? half.x : -half.x, k & 2 ? half.y : -half.y,
                            k & 4 ? half.z : -half.z);
    double depth = 0.0;
    const glm::dvec2 p = camera.project(glm::dvec3(toWorld * glm::dvec4(corner, 1.0)), &depth);
    if (!(depth > kTMin)) ++behind;
    *lo = glm::min(*lo, p);
    *hi = glm::max(*hi, p);
  }
  return behind == 8 ? Reach::Nowhere : behind > 0 ? Reach::Everywhere : Reach::Box;
}

// Whether m maps unit vectors to unit vectors (rotations: every transform the scenes use).
bool isRotation(const glm::dmat3& m) {
  const glm::dmat3 product = glm::transpose(m) * m;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (std::fabs(product[c][r] - (c == r ? 1.0 : 0.0)) > 1e-12) return false;
    }
  }
  return true;
}

}  // namespace

FrameView::FrameView(const RaySceneSpec& spec, int frame, int width, int height)
    : spec_(&spec), camera_(spec.camera(frame), width, height), width_(width), height_(height) {
  const glm::dvec3 origin = camera_.ray({0.0, 0.0}).direction;
  world_ = {origin, camera_.ray({1.0, 0.0}).direction - origin,
            camera_.ray({0.0, 1.0}).direction - origin};
  const glm::dvec3 eye = camera_.position();
  for (const SceneObject& object : spec.objects) {
    const glm::dmat4 toWorld = object.objectToWorld ? object.objectToWorld(frame) : glm::dmat4(1.0);
    const glm::dmat4 toLocal = glm::inverse(toWorld);
    const glm::dmat3 direction(toLocal);
    const glm::dmat3 normalToWorld = glm::transpose(direction);
    objects_.push_back(
        {&object,
         toWorld,
         {direction * world_.origin, direction * world_.perX, direction * world_.perY},
         normalToWorld,
         isRotation(normalToWorld),
         ShapeFromEye(object.shape, glm::dvec3(toLocal * glm::dvec4(eye, 1.0)))});
  }
  buildTiles();
}

void FrameView::buildTiles() {
  tilesX_ = (width_ + kTile - 1) / kTile;
  tilesY_ = (height_ + kTile - 1) / kTile;
  struct Box {
    Reach reach;
    glm::dvec2 lo, hi;
  };
  std::vector<Box> boxes(objects_.size());
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    Box& box = boxes[k];
    box.reach =
        rasterBounds(camera_, objects_[k].toWorld, objects_[k].object->shape, &box.lo, &box.hi);
  }
  tileStart_.assign(1, 0);
  for (int ty = 0; ty < tilesY_; ++ty) {
    for (int tx = 0; tx < tilesX_; ++tx) {
      const glm::dvec2 lo(tx * kTile - kTileMargin, ty * kTile - kTileMargin);
      const glm::dvec2 hi((tx + 1) * kTile + kTileMargin, (ty + 1) * kTile + kTileMargin);
      for (std::size_t k = 0; k < boxes.size(); ++k) {
        const Box& box = boxes[k];
        if (box.reach == Reach::Everywhere ||
            (box.reach == Reach::Box && box.lo.x <= hi.x && box.hi.x >= lo.x && box.lo.y <= hi.y &&
             box.hi.y >= lo.y)) {
          tileObjects_.push_back(int(k));
        }
      }
      tileStart_.push_back(int(tileObjects_.size()));
    }
  }
  for (std::size_t k = 0; k < objects_.size(); ++k) tileObjects_.push_back(int(k));
  tileStart_.push_back(int(tileObjects_.size()));
  // Unbounded objects only (a floor, the sky): every tile holds all, no need to look any up.
  everyTileHoldsAll_ = tileObjects_.size() == objects_.size() * (tilesX_ * tilesY_ + 1);
}

int FrameView::tileOf(glm::dvec2 raster) const {
  // Tiles cover the raster and the margin around it; any other ray tries every object.
  if (everyTileHoldsAll_ || !(raster.x >= -kTileMargin && raster.x < width_ + kTileMargin &&
                              raster.y >= -kTileMargin && raster.y < height_ + kTileMargin)) {
    return tilesX_ * tilesY_;
  }
  // Shifted by a tile so that truncation is floor (positions in the margin are negative).
  const int x = int(raster.x / kTile + 1.0) - 1, y = int(raster.y / kTile + 1.0) - 1;
  return std::clamp(y, 0, tilesY_ - 1) * tilesX_ + std::clamp(x, 0, tilesX_ - 1);
}

template <typename Intersect>
void FrameView::closestOfKind(int index, const glm::dvec2* raster, int count, double* nearest,
                              int* object, Intersect intersect) const {
  const Placed& placed = objects_[index];
  const AffineDirection& d = placed.local;
  const auto& cutout = placed.object->cutout;
  for (int k = 0; k < count; ++k) {
    // Scalars: GCC would store a dvec3 built here piecewise and reload it whole, a
    // store-forwarding stall costing as much as the intersection.
    const double x = d.origin.x + raster[k].x * d.perX.x + raster[k].y * d.perY.x;
    const double y = d.origin.y + raster[k].x * d.perX.y + raster[k].y * d.perY.y;
    const double z = d.origin.z + raster[k].x * d.perX.z + raster[k].y * d.perY.z;
    double t = 0.0;
    if (!intersect(x, y, z, nearest[k], &t)) continue;
    if (cutout && !cutout(placed.shape.hitAt(glm::dvec3(x, y, z), t).point)) continue;
    nearest[k] = t;
    object[k] = index;
  }
}

void FrameView::closest(int index, const glm::dvec2* raster, int count, double* nearest,
                        int* object) const {
  const ShapeFromEye& shape = objects_[index].shape;
  switch (shape.kind()) {
    case ShapeKind::Rectangle:
      return closestOfKind(index, raster, count, nearest, object,
                           [&](double x, double y, double z, double tMax, double* t) {
                             return shape.rectangle(x, y, z, kTMin, tMax, t);
                           });
    case ShapeKind::Box:
      return closestOfKind(index, raster, count, nearest, object,
                           [&](double x, double y, double z, double tMax, double* t) {
                             return shape.box(x, y, z, kTMin, tMax, t);
                           });
    case ShapeKind::Sphere:
      return closestOfKind(index, raster, count, nearest, object,
                           [&](double x, double y, double z, double tMax, double* t) {
                             return shape.sphere(x, y, z, kTMin, tMax, t);
                           });
    case ShapeKind::Cylinder:
      return closestOfKind(index, raster, count, nearest, object,
                           [&](double x, double y, double z, double tMax, double* t) {
                             return shape.cylinder(x, y, z, kTMin, tMax, t);
                           });
  }
}

bool FrameView::trace(glm::dvec2 raster, Hit* hit) const {
  const int tile = tileOf(raster);
  double t = kInf;
  hit->object = -1;
  for (int k = tileStart_[tile]; k < tileStart_[tile + 1]; ++k) {
    closest(tileObjects_[k], &raster, 1, &t, &hit->object);
  }
  if (hit->object < 0) return false;
  const Placed& placed = objects_[hit->object];
  hit->local = placed.shape.hitAt(placed.local.at(raster), t);
  return true;
}

glm::vec3 FrameView::shade(const glm::dvec2& raster, int index, double t) const {
  const Placed& placed = objects_[index];
  const LocalHit hit = placed.shape.hitAt(placed.local.at(raster), t);
  const glm::dvec3 direction = world_.at(raster);
  SurfacePoint point;
  point.local = hit.point;
  point.localNormal = hit.normal;
  point.cameraPosition = camera_.position();
  point.world = point.cameraPosition + t * direction;
  point.worldNormal = placed.normalToWorld * hit.normal;
  if (!placed.rigid) point.worldNormal = glm::normalize(point.worldNormal);
  if (glm::dot(point.worldNormal, direction) > 0.0) point.worldNormal = -point.worldNormal;
  return placed.object->shade(point);
}

// Flattened: with the tracing and shading inlined the hit reaches the shader in registers and
// whole-vector stores; called, GCC stores it in halves that the shader reloads whole, stalling
// store forwarding (measured: a third of the truth's time).
[[gnu::flatten]] void FrameView::radiance(const glm::dvec2* raster, int count,
                                          glm::vec3* rgb) const {
  double nearest[kBatch];
  int object[kBatch];
  for (int begin = 0; begin < count;) {
    // A batch: the rays from `begin` in the same tile, kBatch at most.
    const int tile = tileOf(raster[begin]);
    int end = begin + 1;
    while (end < count && end - begin < kBatch && tileOf(raster[end]) == tile) ++end;
    const int n = end - begin;
    std::fill(nearest, nearest + n, kInf);
    std::fill(object, object + n, -1);
    for (int k = tileStart_[tile]; k < tileStart_[tile + 1]; ++k) {
      closest(tileObjects_[k], raster + begin, n, nearest, object);
    }
    for (int k = 0; k < n; ++k) {
      const glm::dvec2& p = raster[begin + k];
      if (object[k] >= 0) {
        rgb[begin + k] = shade(p, object[k], nearest[k]);
      } else {
        rgb[begin + k] = spec_->sky ? spec_->sky(glm::normalize(world_.at(p))) : glm::vec3(0.0f);
      }
    }
    begin = end;
  }
}

glm::vec3 FrameView::radiance(glm::dvec2 raster) const {
  glm::vec3 rgb;
  radiance(&raster, 1, &rgb);
  return rgb;
}

}  // namespace taa::scenes
