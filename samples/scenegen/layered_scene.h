// 2D layered scenes: flat textured layers at constant depths, each translating rigidly at a
// constant velocity. Everything is analytic, so depth and motion are exact at any point and the
// truth is limited only by the supersampling grid.
#pragma once

#include <functional>
#include <limits>
#include <mutex>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scenegen/scene.h"

namespace taa::scenes {

struct Layer {
  std::function<glm::vec3(glm::dvec2)> texture;  // linear RGB at a layer-local point
  std::function<bool(glm::dvec2)> shape;         // does the layer cover a layer-local point;
                                                 // empty: the whole plane
  // A layer-local box holding every point `shape` covers. The default (the whole plane) is
  // always right; a tight one lets the truth of static layers be rendered once per scene.
  glm::dvec2 boundsMin{-std::numeric_limits<double>::infinity()};
  glm::dvec2 boundsMax{std::numeric_limits<double>::infinity()};
  glm::dvec2 originAtFrame0{0.0};  // raster position of the layer-local origin at frame 0
  glm::dvec2 velocity{0.0};        // px per frame, y down
  float depth = 1.0f;              // planar distance, > 0

  glm::dvec2 origin(int frame) const { return originAtFrame0 + velocity * double(frame); }
  bool isStatic() const { return velocity == glm::dvec2(0.0); }
};

// What a point sample of the scene sees.
struct SurfaceSample {
  glm::vec3 rgb{0.0f};
  float alpha = 0.0f;          // 1 where a layer was hit, 0 where nothing
  float depth = 0.0f;          // +inf where nothing
  glm::vec2 motion{0.0f};      // previous - current, px, y down; 0 where nothing
  glm::vec2 nextMotion{0.0f};  // next - current, px, y down; 0 where nothing
};

class LayeredScene : public Scene {
 public:
  // Layers may be given in any order; the nearest one at a point is the one seen.
  LayeredScene(std::string name, int width, int height, std::vector<Layer> layers);

  // The surface seen at raster position `position` (continuous, pixel (i, j) spans
  // [i, i+1) x [j, j+1)) in `frame`.
  SurfaceSample sample(int frame, glm::dvec2 position) const;

  SceneFrame render(int frame, const RenderSettings& settings) const override;

 private:
  // A layer placed for one frame, so the hot loops do not recompute its origin.
  struct PlacedLayer {
    const Layer* layer;
    glm::dvec2 origin;
  };
  using Placement = std::vector<PlacedLayer>;

  Placement place(int frame, bool staticOnly) const;
  static SurfaceSample sampleAt(const Placement& placement, int frame, glm::dvec2 position);
  static const PlacedLayer* visibleLayer(const Placement& placement, glm::dvec2 position);
  static glm::vec4 colorAt(const Placement& placement, glm::dvec2 position);
  // A Disocclusion value for the surface seen at `centre` (its motion given).
  static int disocclusionAt(const Placement& now, const Placement& previous, glm::dvec2 centre,
                            glm::dvec2 motion, int width, int height);
  // Sub-pixel positions of the truth samples, n x n stratified, in [0, 1)^2.
  static std::vector<glm::dvec2> truthPattern(int n);
  // Box-filtered average over pixel (i, j): the mean of the pattern's samples.
  static glm::vec4 pixelTruth(const Placement& placement, int i, int j,
                              const std::vector<glm::dvec2>& pattern);
  // Does any moving layer's bounds reach into pixel (i, j) in this placement?
  static bool movingLayerTouches(const Placement& placement, int i, int j);
  // Truth of the static layers alone, rendered once per sample count and reused wherever no
  // moving layer reaches a pixel (there it is bit-identical to a fresh render).
  const Image& staticTruth(const RenderSettings& settings) const;
  // Worth it when some layer is static and every moving layer has finite bounds.
  bool staticTruthHelps() const;

  std::vector<Layer> layers_;  // sorted nearest first
  mutable std::mutex staticTruthMutex_;
  mutable Image staticTruth_;
  mutable int staticTruthSamples_ = 0;
};

}  // namespace taa::scenes
