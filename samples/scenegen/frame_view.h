// One frame of a 3D scene as its camera sees it: every object placed for the frame with what
// all camera rays share, and per screen tile the objects a ray there can hit at all. Every ray
// the generator casts is a camera ray through a raster position, so this is all it traces with.
// The truth casts hundreds per pixel: they go in batches, traced one object at a time (tight
// loops over one shape kind), then shaded one by one.
#pragma once

#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scenegen/camera.h"
#include "scenegen/ray_scene_spec.h"

namespace taa::scenes {

class FrameView {
 public:
  // `spec` must outlive the view.
  FrameView(const RaySceneSpec& spec, int frame, int width, int height);

  struct Hit {
    int object = -1;  // index into the spec's objects; -1: nothing (sky)
    LocalHit local;   // local point and normal; t is planar depth
  };

  const Camera& camera() const { return camera_; }
  // Object-to-world transform of spec object `object` at this frame.
  const glm::dmat4& toWorld(int object) const { return objects_[object].toWorld; }

  // The nearest hit along the camera ray through `raster`; false (object -1) when none.
  bool trace(glm::dvec2 raster, Hit* hit) const;
  // Linear RGB the camera rays through raster[0, count) bring back: their hits shaded, or the
  // sky. Positions next to each other in one tile make the batches.
  void radiance(const glm::dvec2* raster, int count, glm::vec3* rgb) const;
  glm::vec3 radiance(glm::dvec2 raster) const;

 private:
  // A camera ray's direction is affine in its raster position.
  struct AffineDirection {
    glm::dvec3 origin, perX, perY;
    glm::dvec3 at(const glm::dvec2& raster) const {
      return origin + raster.x * perX + raster.y * perY;
    }
  };
  struct Placed {
    const SceneObject* object;
    glm::dmat4 toWorld;
    AffineDirection local;     // camera ray directions in local space
    glm::dmat3 normalToWorld;  // local normal -> world normal
    bool rigid;                // normalToWorld keeps unit normals unit
    ShapeFromEye shape;        // the shape seen from the camera, in local space
  };

  int tileOf(glm::dvec2 raster) const;
  // Lowers nearest[k] to the hit of object `index` along ray k where it is nearer, and sets
  // object[k] to `index` there.
  void closest(int index, const glm::dvec2* raster, int count, double* nearest, int* object) const;
  template <typename Intersect>
  void closestOfKind(int index, const glm::dvec2* raster, int count, double* nearest, int* object,
                     Intersect intersect) const;
  glm::vec3 shade(const glm::dvec2& raster, int index, double t) const;
  void buildTiles();

  const RaySceneSpec* spec_;
  Camera camera_;
  AffineDirection world_;  // camera ray directions in world space
  int width_, height_;
  std::vector<Placed> objects_;
  int tilesX_ = 0, tilesY_ = 0;
  // Tile t's objects are tileObjects_[tileStart_[t], tileStart_[t + 1]), ascending so that ties
  // resolve as over all objects; the extra last tile holds every object, for rays outside.
  std::vector<int> tileStart_;
  std::vector<int> tileObjects_;
  bool everyTileHoldsAll_ = false;
};

}  // namespace taa::scenes
