// Generated scenes kept between yardstick runs: a scene is regenerated only when the
// generator binary's content or the request (frames, size, truth samples) changed since it
// was written.
#pragma once

#include <string>

namespace taa::yardstick {

struct SceneRequest {
  std::string scene;
  int firstFrame = 1, lastFrame = 24;
  int width = 320, height = 180;
  int truthSamples = 16;  // per axis, before adaptive refinement; below 16 only for tests
};

// Makes `dir` hold the requested scene in the separate-files layout, running `scenegen` if the
// stamp in `dir` does not match; returns true when it generated. Throws taa::Error on failure
// (the generator's output is in `logPath`).
bool ensureScene(const std::string& scenegen, const SceneRequest& request, const std::string& dir,
                 const std::string& logPath);

}  // namespace taa::yardstick
