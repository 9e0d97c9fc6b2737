#include "yardstick/analytic_scenes.h"

#include <chrono>
#include <filesystem>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "yardstick/exr_files.h"
#include "yardstick/metrics.h"

namespace taa::yardstick {

PreparedScene prepareAnalyticScene(const std::string& scenegen, const SceneRequest& request,
                                   const std::string& sceneDir, const std::string& logPath,
                                   const ScoreOptions& options) {
  PreparedScene scene;
  scene.name = request.scene;
  for (const auto& info : taa::scenes::sceneList()) {
    if (info.name == request.scene) scene.description = info.description;
  }
  const auto start = std::chrono::steady_clock::now();
  scene.made = ensureScene(scenegen, request, sceneDir, logPath);
  scene.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path dir(sceneDir);
  scene.taatoolInputs = {(dir / "beauty.####.exr").string(), "--depth",
                         (dir / "depth.####.exr").string(), "--motion",
                         (dir / "motion.####.exr").string()};
  std::vector<ReferenceFrame> frames;
  for (int f = request.firstFrame; f <= request.lastFrame; ++f) {
    auto path = [&](const char* stem) { return taa::scenes::framePath(sceneDir, stem, f); };
    ReferenceFrame frame;
    frame.frame = f;
    const ExrFile truth = readExr(path("truth"));
    frame.shot = truth.shot;
    frame.truth = tonemap(truth.image);
    frame.raw = tonemap(readExr(path("beauty")).image);
    frame.flow = readExr(path("flow")).image;
    frame.disocclusion = readExr(path("disocclusion")).image;
    frames.push_back(std::move(frame));
  }
  scene.reference = prepareReference(std::move(frames), options);
  return scene;
}

}  // namespace taa::yardstick
