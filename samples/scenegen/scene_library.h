// The named scenes taa-scenegen and the tests can render.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenegen/scene.h"

namespace taa::scenes {

struct SceneInfo {
  std::string name;
  std::string description;  // one line
};

// Every scene makeScene knows, in a stable order.
const std::vector<SceneInfo>& sceneList();

// The scene called `name` at the given raster size; throws taa::Error for an unknown name or a
// size that is not positive. Scenes whose features scale with the image (the moving object's
// size, path and speed) are laid out for 320x180 and scaled.
std::unique_ptr<Scene> makeScene(const std::string& name, int width, int height);

// Velocities the scenes use, so tests can check motion against them (px per frame, y down).
glm::dvec2 translateVelocity();
glm::dvec2 movingObjectVelocity(int width, int height);

}  // namespace taa::scenes
