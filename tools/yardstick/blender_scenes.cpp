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

  const std::string sidecarPath = (dir / "camera.json").string();
  scene.taatoolInputs = {(dir / "input.####.exr").string(), "--preset", "cycles",
                         "--camera-sidecar", sidecarPath};
  const io::CameraSidecar cameras = io::CameraSidecar::load(sidecarPath);
  std::vector<ReferenceFrame> frames;
  std::optional<CyclesCentres> previous;
  for (int f = request.firstFrame; f <= request.lastFrame; ++f) {
    ReferenceFrame frame;
    frame.frame = f;
    frame.truth = tonemap(readExrChannels(framePath(dir, "truth", f), {"R", "G", "B"}));
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
