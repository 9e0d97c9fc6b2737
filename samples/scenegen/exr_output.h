// Writes rendered scene frames as EXR sequences in the layouts taa reads: separate files per
// AOV in taa's own conventions, or a Blender Cycles multi-layer file. Float32, ZIP.
#pragma once

#include <string>

#include "scenegen/scene.h"

namespace taa::scenes {

enum class OutputLayout {
  Separate,  // beauty/depth/motion/truth.####.exr, internal conventions (+inf = no hit)
  Cycles,    // render.####.exr (ViewLayer.Combined/Depth/Vector) + truth.####.exr
};

// "<dir>/<stem>.<frame padded to 4 digits>.exr"
std::string framePath(const std::string& dir, const std::string& stem, int frame);

// Creates `dir` if needed and writes the frame's files; throws taa::Error naming the file.
// Headers also carry the jitter ("taa:jitter", v2f, px, y down), the scene name ("taa:scene"),
// the frame ("taa:frame") and shot ("taa:shot") numbers and, for scenes with a camera,
// "worldToCamera" and "worldToNDC" (M44f, row vectors; samples/README.md). Scenes that provide
// them also get flow.####.exr (X, Y: exact motion, sky included) and disocclusion.####.exr (D).
void writeFrame(const SceneFrame& frame, const std::string& sceneName, OutputLayout layout,
                const std::string& dir);

}  // namespace taa::scenes
