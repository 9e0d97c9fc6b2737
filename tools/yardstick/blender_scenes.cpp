#include "yardstick/blender_scenes.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "io/camera_sidecar.h"
#include "taa/error.h"
#include "yardstick/cycles_reference.h"
#include "yardstick/exr_files.h"
#include "yardstick/metrics.h"
#include "yardstick/process.h"

namespace taa::yardstick {
namespace fs = std::filesystem;
namespace {

std::string framePath(const fs::path& dir, const std::string& stem, int frame) {
  char name[64];
  std::snprintf(name, sizeof name, "%s.%04d.exr", stem.c_str(), frame);
  return (dir / name).string();
}

std::vector<std::string> blenderCommand(const BlenderSettings& settings) {
  return {settings.blender, "-b", "--factory-startup", "-noaudio", "-P", settings.script, "--"};
}

// The part of a log written after `offset`.
std::string logSince(const std::string& logPath, std::streamoff offset) {
  std::ifstream file(logPath);
  file.seekg(offset);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::streamoff logSize(const std::string& logPath) {
  std::error_code ec;
  const auto size = fs::file_size(logPath, ec);
  return ec ? 0 : std::streamoff(size);
}

CyclesCentres readCentres(const fs::path& dir, int frame, const io::CameraSidecar& cameras) {
  const std::string path = framePath(dir, "aux", frame);
  return {readExrChannels(path, {"ViewLayer.Depth.Z"}),
          readExrChannels(path, {"ViewLayer.Vector.X", "ViewLayer.Vector.Y",
                                 "ViewLayer.Vector.Z", "ViewLayer.Vector.W"}),
          cameras.camera(frame)};
}

// The moving object and its shadow, where the scene has one (render_scene.py's nomoving
// product and the aux render's object index): the object where the pixel centre sees it; its
// shadow where, elsewhere, the truth is at most 70% of the truth without the object (its
// contact shadow and the light it blocks), on surfaces that are lit without it.
std::optional<Image> movingRegions(const fs::path& dir, int frame, const Image& linearTruth) {
  const std::string without = framePath(dir, "nomoving", frame);
  if (!fs::exists(without)) return std::nullopt;
  const Image index = readExrChannels(framePath(dir, "aux", frame), {"ViewLayer.IndexOB.X"});
  const Image free = readExrChannels(without, {"R", "G", "B"});
  Image regions(linearTruth.width, linearTruth.height, 2);
  auto luma = [](const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; };
  for (int y = 0; y < regions.height; ++y) {
    for (int x = 0; x < regions.width; ++x) {
      const bool object = index.at(x, y)[0] > 0.5f;
      const float lit = luma(free.at(x, y)), shaded = luma(linearTruth.at(x, y));
      regions.at(x, y)[0] = object ? 1.0f : 0.0f;
      regions.at(x, y)[1] = !object && lit > 0.02f && shaded < 0.7f * lit ? 1.0f : 0.0f;
    }
  }
  return regions;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> listBlenderScenes(
    const BlenderSettings& settings, const std::string& logPath) {
  std::vector<std::string> command = blenderCommand(settings);
  command.push_back("--list");
  const std::streamoff start = logSize(logPath);
  const int status = runProcess(command, logPath);
  if (status == -1) {
    throw Error("cannot run Blender '" + settings.blender +
                "' (install Debian's blender package, or measure only --scenes analytic)");
  }
  if (status != 0) {
    throw Error("Blender could not list the scenes (see " + logPath + "): " +
                commandLine(command));
  }
  std::vector<std::pair<std::string, std::string>> scenes;
  std::istringstream lines(logSince(logPath, start));
  std::string line;
  while (std::getline(lines, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos && line.rfind("cycles_", 0) == 0) {
      scenes.emplace_back(line.substr(0, tab), line.substr(tab + 1));
    }
  }
  if (scenes.empty()) throw Error("Blender listed no scenes (see " + logPath + ")");
  return scenes;
}

std::string blenderSceneDir(const BlenderSettings& settings, const BlenderRequest& request) {
  return (fs::path(settings.cache) /
          (request.scene + "-" + std::to_string(request.width) + "x" +
           std::to_string(request.height) + "-" + std::to_string(request.firstFrame) + "-" +
           std::to_string(request.lastFrame)))
      .string();
}

PreparedScene prepareBlenderScene(const BlenderSettings& settings, const BlenderRequest& request,
                                  const std::string& description, const std::string& logPath,
                                  const ScoreOptions& options) {
  PreparedScene scene;
  scene.name = request.scene;
  scene.description = description;
  const fs::path dir = blenderSceneDir(settings, request);

  std::string counts;
  for (int n : settings.ssaa) counts += (counts.empty() ? "" : ",") + std::to_string(n);
  std::vector<std::string> command = blenderCommand(settings);
  command.insert(command.end(),
                 {"--scene", request.scene, "--out", dir.string(), "--size",
                  std::to_string(request.width) + "x" + std::to_string(request.height),
                  "--frames",
                  std::to_string(request.firstFrame) + "-" + std::to_string(request.lastFrame),
                  "--truth-samples", std::to_string(settings.truthSamples), "--ssaa", counts});
  const auto start = std::chrono::steady_clock::now();
  const std::streamoff logStart = logSize(logPath);
  if (runProcess(command, logPath) != 0) {
    throw Error("Blender failed to render " + request.scene + " (see " + logPath + "): " +
                commandLine(command));
  }
  scene.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  scene.made = logSince(logPath, logStart).find(" rendered") != std::string::npos;

  // Rendered through taa's Blender add-on: each frame's camera and jitter are in its header,
  // read with no flag but the preset. The sidecar serves the reference's flow only.
  scene.taatoolInputs = {(dir / "input.####.exr").string(), "--preset", "cycles"};
  const io::CameraSidecar cameras = io::CameraSidecar::load((dir / "camera.json").string());
  std::vector<ReferenceFrame> frames;
  std::optional<CyclesCentres> previous;
  for (int f = request.firstFrame; f <= request.lastFrame; ++f) {
    ReferenceFrame frame;
    frame.frame = f;
    const Image linearTruth = readExrChannels(framePath(dir, "truth", f), {"R", "G", "B"});
    frame.truth = tonemap(linearTruth);
    if (auto regions = movingRegions(dir, f, linearTruth)) frame.regions = std::move(*regions);
    frame.raw = tonemap(readExrChannels(
        framePath(dir, "input", f),
        {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"}));
    CyclesCentres centres = readCentres(dir, f, cameras);
    if (previous) {
      frame.flow = flowToPrevious(centres, previous->camera);
      frame.disocclusion =
          disocclusionFromFlows(frame.flow, flowToNext(*previous, centres.camera));
    } else {
      // The first frame has nothing before it: no motion to follow, everything is new.
      frame.flow = Image(frame.truth.width, frame.truth.height, 2);
      frame.disocclusion = Image(frame.truth.width, frame.truth.height, 1);
      for (float& v : frame.disocclusion.pixels) v = 1.0f;
    }
    previous = std::move(centres);
    frames.push_back(std::move(frame));
  }
  scene.reference = prepareReference(std::move(frames), options);

  for (int n : settings.ssaa) {
    PreparedScene::FixedRow row{"ssaa-" + std::to_string(n), n, {}};
    for (int f = request.firstFrame; f <= request.lastFrame; ++f) {
      row.frames.push_back(
          tonemap(readExrChannels(framePath(dir, "ssaa" + std::to_string(n), f), {"R", "G", "B"})));
    }
    scene.fixedRows.push_back(std::move(row));
  }
  return scene;
}

}  // namespace taa::yardstick
