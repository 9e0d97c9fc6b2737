#include "scenegen/ray_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec4.hpp>

#include "scenegen/parallel_for.h"
#include "scenegen/truth_sampler.h"
#include "taa/error.h"

namespace taa::scenes {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool onRaster(glm::dvec2 p, int width, int height) {
  return p.x >= 0.0 && p.y >= 0.0 && p.x < width && p.y < height;
}

TruthSampling truthSampling(const RenderSettings& settings, int frame) {
  if (settings.truthSamplesPerAxis < 1) {
    throw Error("truth samples per axis must be at least 1", {"", frame, ""});
  }
  return {settings.truthSamplesPerAxis, settings.truthSeed, settings.threads};
}

}  // namespace

RayScene::RayScene(std::string name, int width, int height, RaySceneSpec spec)
    : Scene(std::move(name), width, height), spec_(std::move(spec)) {
  if (width <= 0 || height <= 0) throw Error("scene size must be positive: " + this->name());
  if (!spec_.camera) throw Error("3D scene without a camera: " + this->name());
  for (const SceneObject& object : spec_.objects) {
    if (!object.shade) throw Error("object without a shader in scene " + this->name());
  }
}

Camera RayScene::camera(int frame) const { return Camera(spec_.camera(frame), width(), height()); }

RayScene::CentreMotion RayScene::centreMotion(const FrameView& other, glm::dvec2 centre,
                                              glm::dvec3 direction,
                                              const FrameView::Hit& hit) const {
  CentreMotion result;
  glm::dvec2 there(0.0);
  double depthThere = 0.0;
  bool inFront = true;
  if (hit.object >= 0) {
    // The same material point in the other frame: through this frame's object-to-local and
    // the other frame's object-to-world, then the other frame's camera.
    const glm::dvec3 world(other.toWorld(hit.object) * glm::dvec4(hit.local.point, 1.0));
    there = other.camera().project(world, &depthThere);
    inFront = depthThere > 0.0;
    result.written = inFront ? there - centre : glm::dvec2(0.0);
  } else {
    inFront = other.camera().projectDirection(direction, &there);
    result.written = glm::dvec2(0.0);  // as Cycles: no geometry, no vector
  }
  result.exact = inFront ? there - centre : glm::dvec2(0.0);
  if (!inFront || !onRaster(there, width(), height())) {
    result.disocclusion = kOutsideBefore;
    return result;
  }
  FrameView::Hit before;
  const bool hitBefore = other.trace(there, &before);
  const bool same =
      hit.object < 0 ? !hitBefore
                     : hitBefore && before.object == hit.object &&
                           std::fabs(before.local.t - depthThere) <= 1e-4 * depthThere + 1e-6;
  result.disocclusion = same ? kVisibleBefore : kOccludedBefore;
  return result;
}

Image RayScene::truthRegion(int frame, const RenderSettings& settings, int x0, int y0, int w,
                            int h) const {
  const TruthSampling sampling = truthSampling(settings, frame);
  return renderTruth(FrameView(spec_, frame, width(), height()), x0, y0, w, h, sampling);
}

SceneFrame RayScene::render(int frame, const RenderSettings& settings) const {
  const int w = width(), h = height();
  const TruthSampling sampling = truthSampling(settings, frame);
  SceneFrame out = blankFrame(frame, w, h, settings, false);
  out.shot = shot(frame);
  const FrameView now(spec_, frame, w, h), previous(spec_, frame - 1, w, h),
      next(spec_, frame + 1, w, h);
  out.hasCamera = true;
  out.camera.worldToCamera = glm::mat4(now.camera().worldToCamera());
  out.camera.worldToNDC = glm::mat4(now.camera().worldToNDC());
  const glm::dvec2 jitter(out.jitter);

  parallelFor(h, settings.threads, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const glm::dvec2 centre(i + 0.5, j + 0.5);
      const glm::vec4 color(now.radiance(centre + jitter), 1.0f);
      std::copy(&color[0], &color[0] + 4, out.color.at(i, j));

      FrameView::Hit hit;
      now.trace(centre, &hit);
      out.depth.at(i, j)[0] = hit.object >= 0 ? float(hit.local.t) : float(kInf);
      const glm::dvec3 direction = now.camera().ray(centre).direction;
      const CentreMotion back = centreMotion(previous, centre, direction, hit);
      const CentreMotion forward = centreMotion(next, centre, direction, hit);
      out.motion.at(i, j)[0] = float(back.written.x);
      out.motion.at(i, j)[1] = float(back.written.y);
      out.nextMotion.at(i, j)[0] = float(forward.written.x);
      out.nextMotion.at(i, j)[1] = float(forward.written.y);
      out.flow.at(i, j)[0] = float(back.exact.x);
      out.flow.at(i, j)[1] = float(back.exact.y);
      out.disocclusion.at(i, j)[0] = float(back.disocclusion);
    }
  });
  out.truth = renderTruth(now, 0, 0, w, h, sampling);
  return out;
}

}  // namespace taa::scenes
