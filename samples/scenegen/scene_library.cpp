#include "scenegen/scene_library.h"

#include <algorithm>

#include "scenegen/layered_scene.h"
#include "scenegen/patterns.h"
#include "scenegen/scenes_3d.h"
#include "taa/error.h"

namespace taa::scenes {
namespace {

constexpr float kBackgroundDepth = 10.0f;
constexpr float kObjectDepth = 4.0f;

Layer backgroundLayer(glm::dvec2 velocity) {
  Layer layer;
  layer.texture = finePattern;
  layer.velocity = velocity;
  layer.depth = kBackgroundDepth;
  return layer;
}

std::unique_ptr<Scene> makeMovingObject(int width, int height) {
  const glm::dvec2 scale(width / 320.0, height / 180.0);
  Layer object;
  object.texture = objectPattern;
  const double radius = 45.0 * std::min(scale.x, scale.y);
  object.shape = DiscShape{radius};
  object.boundsMin = glm::dvec2(-radius);
  object.boundsMax = glm::dvec2(radius);
  object.velocity = movingObjectVelocity(width, height);
  // At frame 1 the disc sits left of centre; by frame 24 it has crossed to the right.
  object.originAtFrame0 = glm::dvec2(90.0, 70.0) * scale - object.velocity;
  object.depth = kObjectDepth;
  return std::make_unique<LayeredScene>("moving_object", width, height,
                                        std::vector<Layer>{backgroundLayer({0.0, 0.0}), object});
}

}  // namespace

const std::vector<SceneInfo>& sceneList() {
  static const std::vector<SceneInfo> list = [] {
    std::vector<SceneInfo> all = {
        {"static", "static high-frequency HDR pattern, no motion, constant depth"},
        {"translate", "the pattern translating rigidly at (1.37, 0.61) px/frame"},
        {"moving_object", "static pattern (depth 10) with a textured disc (depth 4) crossing it"},
    };
    for (const SceneInfo& info : scene3dList()) all.push_back(info);
    return all;
  }();
  return list;
}

glm::dvec2 translateVelocity() { return {1.37, 0.61}; }

glm::dvec2 movingObjectVelocity(int width, int height) {
  // Non-integer so that successive frames land on different sub-pixel phases.
  return glm::dvec2(6.37 * width / 320.0, 1.23 * height / 180.0);
}

std::unique_ptr<Scene> makeScene(const std::string& name, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw Error("scene size must be positive, got " + std::to_string(width) + "x" +
                std::to_string(height));
  }
  if (name == "static") {
    return std::make_unique<LayeredScene>(name, width, height,
                                          std::vector<Layer>{backgroundLayer({0.0, 0.0})});
  }
  if (name == "translate") {
    return std::make_unique<LayeredScene>(name, width, height,
                                          std::vector<Layer>{backgroundLayer(translateVelocity())});
  }
  if (name == "moving_object") return makeMovingObject(width, height);
  if (auto scene = makeScene3d(name, width, height)) return scene;
  std::string known;
  for (const SceneInfo& info : sceneList()) known += (known.empty() ? "" : ", ") + info.name;
  throw Error("unknown scene '" + name + "' (known: " + known + ")");
}

}  // namespace taa::scenes
