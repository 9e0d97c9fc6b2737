// The named 3D scenes of the quality yardstick (DESIGN.md section 7), one per failure case.
// They are laid out for 320x180 at 40 degrees vertical field of view and frames 1-24; any size
// and frame work (features get smaller in pixels at smaller sizes).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenegen/ray_scene.h"
#include "scenegen/scene_library.h"

namespace taa::scenes {

// The 3D scenes, in yardstick order.
const std::vector<SceneInfo>& scene3dList();

// The 3D scene called `name`, or nullptr if there is none.
std::unique_ptr<RayScene> makeScene3d(const std::string& name, int width, int height);

// The first frame of the second shot of the "cut" scene.
constexpr int kCutFrame = 13;

}  // namespace taa::scenes
