// 3D scenes: a small analytic ray caster over rectangles, boxes, spheres and thin cylinders with
// procedural textures, seen by a camera that may move every frame; objects may move too. Depth,
// motion and disocclusion are exact at pixel centres; the truth is an adaptive box-filtered
// average (truth_sampler.h).
#pragma once

#include <string>

#include "scenegen/camera.h"
#include "scenegen/frame_view.h"
#include "scenegen/ray_scene_spec.h"
#include "scenegen/scene.h"

namespace taa::scenes {

class RayScene : public Scene {
 public:
  RayScene(std::string name, int width, int height, RaySceneSpec spec);

  Camera camera(int frame) const;
  int shot(int frame) const { return spec_.shot ? spec_.shot(frame) : 0; }

  SceneFrame render(int frame, const RenderSettings& settings) const override;

  // The truth of pixels [x0, x0 + w) x [y0, y0 + h) of `frame` alone (RGBA), exactly as
  // render() computes them: lets tests check convergence without rendering whole frames.
  Image truthRegion(int frame, const RenderSettings& settings, int x0, int y0, int w,
                    int h) const;

 private:
  // Motion and disocclusion of what the pixel centre sees, toward frame `other`.
  struct CentreMotion {
    glm::dvec2 written{0.0};  // what a renderer writes (sky: zero)
    glm::dvec2 exact{0.0};    // the flow, sky included
    int disocclusion = kVisibleBefore;
  };
  CentreMotion centreMotion(const FrameView& other, glm::dvec2 centre, glm::dvec3 direction,
                            const FrameView::Hit& hit) const;

  RaySceneSpec spec_;
};

}  // namespace taa::scenes
