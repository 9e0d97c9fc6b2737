// What a 3D scene is made of: objects (a shape, its motion, an optional cutout and a shader), a
// camera path, a sky and shots. scenes_3d.cpp describes the named scenes with these.
#pragma once

#include <functional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenegen/camera.h"
#include "scenegen/ray_shapes.h"

namespace taa::scenes {

// What a texture sees of the point it colours.
struct SurfacePoint {
  glm::dvec3 local;        // in the object's own space (moves with the object)
  glm::dvec3 localNormal;  // unit
  glm::dvec3 world;
  glm::dvec3 worldNormal;  // unit, facing the camera
  glm::dvec3 cameraPosition;
};

struct SceneObject {
  Shape shape;
  // Object-to-world transform at a frame; empty: identity (static geometry in world space).
  std::function<glm::dmat4(int frame)> objectToWorld;
  // Where the surface exists, at a local point (fences); empty: everywhere. Use on rectangles
  // only: a cut-away hit is a miss, the ray does not go on to the shape's far side.
  std::function<bool(glm::dvec3 local)> cutout;
  // Linear RGB leaving the point toward the camera (texture and lighting together).
  std::function<glm::vec3(const SurfacePoint&)> shade;
};

struct RaySceneSpec {
  std::function<CameraPose(int frame)> camera;
  std::vector<SceneObject> objects;
  std::function<glm::vec3(glm::dvec3 direction)> sky;  // unit world direction; empty: black
  std::function<int(int frame)> shot;                  // empty: one shot
};

}  // namespace taa::scenes
