#include "scenegen/layered_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "scenegen/parallel_for.h"
#include "taa/error.h"

namespace taa::scenes {

LayeredScene::LayeredScene(std::string name, int width, int height, std::vector<Layer> layers)
    : Scene(std::move(name), width, height), layers_(std::move(layers)) {
  if (width <= 0 || height <= 0) throw Error("scene size must be positive: " + this->name());
  for (const Layer& layer : layers_) {
    if (!layer.texture || !(layer.depth > 0.0f)) throw Error("bad layer in scene " + this->name());
  }
  // Stable, so layers at equal depth keep the caller's order (first wins).
  std::stable_sort(layers_.begin(), layers_.end(),
                   [](const Layer& a, const Layer& b) { return a.depth < b.depth; });
}

LayeredScene::Placement LayeredScene::place(int frame, bool staticOnly) const {
  Placement placement;
  for (const Layer& layer : layers_) {
    if (!staticOnly || layer.isStatic()) placement.push_back({&layer, layer.origin(frame)});
  }
  return placement;
}

const LayeredScene::PlacedLayer* LayeredScene::visibleLayer(const Placement& placement,
                                                            glm::dvec2 position) {
  for (const PlacedLayer& placed : placement) {
    if (!placed.layer->shape || placed.layer->shape(position - placed.origin)) return &placed;
  }
  return nullptr;
}

glm::vec4 LayeredScene::colorAt(const Placement& placement, glm::dvec2 position) {
  const PlacedLayer* placed = visibleLayer(placement, position);
  if (!placed) return glm::vec4(0.0f);
  return glm::vec4(placed->layer->texture(position - placed->origin), 1.0f);
}

std::vector<glm::dvec2> LayeredScene::truthPattern(int n) {
  // One point per cell of an n x n grid, jittered within its cell. Jittering (rather than cell
  // centres) keeps the samples along an axis-aligned edge from all flipping together, so the
  // error on edges falls as n^-1.5 instead of n^-1. The same pattern serves every pixel and
  // frame: a whole-pixel shift of the scene shifts the truth exactly, and static layers render
  // identically in every frame.
  std::vector<glm::dvec2> pattern;
  pattern.reserve(std::size_t(n) * n);
  std::uint32_t state = 0x9e3779b9u;
  auto unitRandom = [&state] {
    // xorshift32: deterministic everywhere, unlike std::uniform_real_distribution.
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return (state >> 8) * (1.0 / 16777216.0);
  };
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) {
      const double u = unitRandom(), v = unitRandom();
      pattern.emplace_back((a + u) / n, (b + v) / n);
    }
  }
  return pattern;
}

glm::vec4 LayeredScene::pixelTruth(const Placement& placement, int i, int j,
                                   const std::vector<glm::dvec2>& pattern) {
  glm::dvec4 sum(0.0);
  const glm::dvec2 corner(i, j);
  for (const glm::dvec2& offset : pattern) sum += glm::dvec4(colorAt(placement, corner + offset));
  return glm::vec4(sum / double(pattern.size()));
}

bool LayeredScene::movingLayerTouches(const Placement& placement, int i, int j) {
  for (const PlacedLayer& placed : placement) {
    if (placed.layer->isStatic()) continue;
    const glm::dvec2 lo = placed.origin + placed.layer->boundsMin;
    const glm::dvec2 hi = placed.origin + placed.layer->boundsMax;
    if (lo.x <= i + 1 && hi.x >= i && lo.y <= j + 1 && hi.y >= j) return true;
  }
  return false;
}

const Image& LayeredScene::staticTruth(const RenderSettings& settings) const {
  std::lock_guard<std::mutex> lock(staticTruthMutex_);
  const int n = settings.truthSamplesPerAxis;
  if (staticTruthSamples_ != n) {
    const Placement placement = place(0, /*staticOnly=*/true);
    const std::vector<glm::dvec2> pattern = truthPattern(n);
    Image truth(width(), height(), 4);
    parallelFor(height(), settings.threads, [&](int j) {
      for (int i = 0; i < width(); ++i) {
        const glm::vec4 value = pixelTruth(placement, i, j, pattern);
        std::copy(&value[0], &value[0] + 4, truth.at(i, j));
      }
    });
    staticTruth_ = std::move(truth);
    staticTruthSamples_ = n;
  }
  return staticTruth_;
}

bool LayeredScene::staticTruthHelps() const {
  bool anyStatic = false;
  for (const Layer& layer : layers_) {
    if (layer.isStatic()) {
      anyStatic = true;
    } else if (std::isinf(layer.boundsMin.x) || std::isinf(layer.boundsMin.y) ||
               std::isinf(layer.boundsMax.x) || std::isinf(layer.boundsMax.y)) {
      return false;  // a moving layer that may be anywhere touches every pixel
    }
  }
  return anyStatic;
}

SurfaceSample LayeredScene::sample(int frame, glm::dvec2 position) const {
  return sampleAt(place(frame, false), frame, position);
}

SurfaceSample LayeredScene::sampleAt(const Placement& placement, int frame, glm::dvec2 position) {
  SurfaceSample result;
  result.depth = std::numeric_limits<float>::infinity();
  const PlacedLayer* placed = visibleLayer(placement, position);
  if (!placed) return result;
  const Layer& layer = *placed->layer;
  result.rgb = layer.texture(position - placed->origin);
  result.alpha = 1.0f;
  result.depth = layer.depth;
  // A rigid layer's points move exactly as its origin does.
  result.motion = glm::vec2(layer.origin(frame - 1) - placed->origin);
  result.nextMotion = glm::vec2(layer.origin(frame + 1) - placed->origin);
  return result;
}

int LayeredScene::disocclusionAt(const Placement& now, const Placement& previous,
                                 glm::dvec2 centre, glm::dvec2 motion, int width, int height) {
  const glm::dvec2 before = centre + motion;
  if (before.x < 0.0 || before.y < 0.0 || before.x >= width || before.y >= height) {
    return kOutsideBefore;
  }
  const PlacedLayer* seen = visibleLayer(now, centre);
  const PlacedLayer* seenBefore = visibleLayer(previous, before);
  const bool same = seen && seenBefore ? seen->layer == seenBefore->layer : seen == seenBefore;
  return same ? kVisibleBefore : kOccludedBefore;
}

SceneFrame LayeredScene::render(int frame, const RenderSettings& settings) const {
  const int n = settings.truthSamplesPerAxis;
  if (n < 1) throw Error("truth samples per axis must be at least 1", {"", frame, ""});
  const int w = width(), h = height();
  SceneFrame out = blankFrame(frame, w, h, settings, true);
  const glm::dvec2 jitter(out.jitter);
  const Placement placement = place(frame, false);
  const Placement previous = place(frame - 1, false);
  const std::vector<glm::dvec2> pattern = truthPattern(n);
  const Image* cachedTruth = staticTruthHelps() ? &staticTruth(settings) : nullptr;

  parallelFor(h, settings.threads, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const glm::dvec2 centre(i + 0.5, j + 0.5);
      const glm::vec4 color = colorAt(placement, centre + jitter);
      std::copy(&color[0], &color[0] + 4, out.color.at(i, j));

      const SurfaceSample atCentre = sampleAt(placement, frame, centre);
      out.depth.at(i, j)[0] = atCentre.depth;
      out.motion.at(i, j)[0] = atCentre.motion.x;
      out.motion.at(i, j)[1] = atCentre.motion.y;
      out.nextMotion.at(i, j)[0] = atCentre.nextMotion.x;
      out.nextMotion.at(i, j)[1] = atCentre.nextMotion.y;
      // Layers are flat and rigid: the written motion is exact everywhere.
      out.flow.at(i, j)[0] = atCentre.motion.x;
      out.flow.at(i, j)[1] = atCentre.motion.y;
      out.disocclusion.at(i, j)[0] =
          float(disocclusionAt(placement, previous, centre, glm::dvec2(atCentre.motion), w, h));

      if (cachedTruth && !movingLayerTouches(placement, i, j)) {
        std::copy(cachedTruth->at(i, j), cachedTruth->at(i, j) + 4, out.truth.at(i, j));
      } else {
        const glm::vec4 truth = pixelTruth(placement, i, j, pattern);
        std::copy(&truth[0], &truth[0] + 4, out.truth.at(i, j));
      }
    }
  });
  return out;
}

}  // namespace taa::scenes
