// The yardstick's real renders: Blender Cycles scenes (samples/blender/render_scene.py), run
// with Debian's blender and cached outside the repository, one folder per scene, size and
// frame range. The script keeps its own per-product stamps, so running it for a cached scene
// costs only Blender's start (about a second).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "yardstick/prepared_scene.h"

namespace taa::yardstick {

struct BlenderSettings {
  std::string blender = "blender";  // the executable
  std::string script;               // samples/blender/render_scene.py
  std::string cache;                // the cache's root folder
  int truthSamples = 1024;          // samples per pixel of the truth
  std::vector<int> ssaa = {2, 4, 8, 16};  // the SSAA-N reference rows
};

struct BlenderRequest {
  std::string scene;
  int firstFrame = 1, lastFrame = 24;
  int width = 320, height = 180;
};

// The scenes the script offers for the yardstick: name -> what it stresses. Throws taa::Error
// when Blender cannot run the script (its output is in `logPath`).
std::vector<std::pair<std::string, std::string>> listBlenderScenes(
    const BlenderSettings& settings, const std::string& logPath);

// Where a request's renders are cached.
std::string blenderSceneDir(const BlenderSettings& settings, const BlenderRequest& request);

// Renders what is not cached yet, then loads the reference: truth and SSAA-N as Blender
// rendered them, the raw input's Combined pass, flow and disocclusion from the unjittered
// "aux" frames and the camera sidecar (cycles_reference.h). The input was rendered through
// taa's Blender add-on: taatool reads it with `--preset cycles` alone, as a user would.
PreparedScene prepareBlenderScene(const BlenderSettings& settings, const BlenderRequest& request,
                                  const std::string& description, const std::string& logPath,
                                  const ScoreOptions& options);

}  // namespace taa::yardstick
