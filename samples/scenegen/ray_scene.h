// 3D scenes: a small analytic ray caster over rectangles, boxes, spheres and thin cylinders with
// procedural textures, seen by a camera that may move every frame; objects may move too. Depth,
// motion and disocclusion are exact at pixel centres; the truth is an adaptive box-filtered
// average (16 x 16 jittered grid, cells on edges refined further).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scenegen/camera.h"
#include "scenegen/ray_shapes.h"
#include "scenegen/scene.h"

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

class RayScene : public Scene {
 public:
  RayScene(std::string name, int width, int height, RaySceneSpec spec);

  Camera camera(int frame) const;
  int shot(int frame) const { return spec_.shot ? spec_.shot(frame) : 0; }

  SceneFrame render(int frame, const RenderSettings& settings) const override;

  // The truth of pixels [x0, x0 + w) x [y0, y0 + h) of `frame` alone (RGBA), as render()
  // computes it: lets tests check convergence on a crop without rendering whole frames.
  Image truthRegion(int frame, const RenderSettings& settings, int x0, int y0, int w,
                    int h) const;

  // What the ray through a continuous raster position sees at `frame`.
  struct View {
    int object = -1;  // index into the spec's objects; -1: sky
    double depth = 0.0;
    glm::dvec3 local{0.0};  // hit point in the object's space
    glm::vec3 rgb{0.0f};
  };
  View view(int frame, glm::dvec2 raster) const;

 private:
  // An object placed for one frame, with what every camera ray of that frame shares.
  struct PlacedObject {
    const SceneObject* object;
    glm::dmat4 toWorld, toLocal;
    glm::dmat3 localDirection;  // world direction -> local direction
    glm::dmat3 normalToWorld;   // local normal -> world normal (unnormalised)
    glm::dvec3 localEye;        // the camera position in local space
    glm::dvec3 eyeToCentre;     // camera to the bounding sphere's centre, world
    double radiusSquared;       // of the bounding sphere; +inf: unbounded
  };
  struct FrameState {
    int frame;
    Camera camera;
    std::vector<PlacedObject> objects;
  };
  struct Trace {
    int object = -1;
    LocalHit hit;  // local point and normal; t is planar depth
  };

  FrameState state(int frame) const;
  // The nearest hit along a camera ray of `state` (all rays start at its camera).
  static bool trace(const FrameState& state, const Ray& ray, Trace* out);
  glm::vec3 shade(const FrameState& state, const Ray& ray, const Trace& trace) const;
  glm::vec3 radiance(const FrameState& state, glm::dvec2 raster) const;
  glm::vec4 pixelTruth(const FrameState& state, int i, int j, std::uint32_t seed,
                       int samplesPerAxis) const;
  // Motion and disocclusion of what the pixel centre sees, toward frame `other`.
  struct CentreMotion {
    glm::dvec2 written{0.0};  // what a renderer writes (sky: zero)
    glm::dvec2 exact{0.0};    // the flow, sky included
    int disocclusion = kVisibleBefore;
  };
  CentreMotion centreMotion(const FrameState& other, glm::dvec2 centre, const Ray& ray,
                            const Trace& trace) const;

  RaySceneSpec spec_;
};

}  // namespace taa::scenes
