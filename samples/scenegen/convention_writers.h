// The same rendered frame written in other renderers' conventions, for the convention-
// equivalence check (taatool with the matching preset or flags must give the same output
// from every variant). The Separate and Cycles layouts are in exr_output.h.
#pragma once

#include <string>

#include "scenegen/scene.h"

namespace taa::scenes {

enum class ConventionVariant {
  // nuke.####.exr: R, G, B, A; depth.Z = 1 / planar depth (0 where nothing is hit);
  // backward.u/v = previous - current and forward.u/v = next - current, pixels, y up.
  // Read with: taatool --preset nuke
  Nuke,
  // color.####.exr (R, G, B, A); depth_ndc.####.exr (Z: depth-buffer value in [0, 1] for the
  // planes in kNdcNear/kNdcFar, 1 where nothing is hit); motion_ndc.####.exr (X, Y: previous -
  // current in NDC units, [-1, 1] across the image, y up). Read with: taatool
  // --depth-kind ndc --depth-near 1 --depth-far 1000 --motion-units ndc --motion-y up
  NdcSeparate,
};

// The depth range of NdcSeparate: every scene depth must lie in [near, far).
constexpr double kNdcNear = 1.0;
constexpr double kNdcFar = 1000.0;

// "nuke" | "ndc" -> variant; false for any other name.
bool parseConventionVariant(const std::string& name, ConventionVariant* variant);

// Creates `dir` if needed and writes the frame's files plus truth.####.exr (R, G, B, A). Headers
// carry taa:jitter (v2f, px, y down), taa:scene, taa:frame and, for scenes with a camera,
// worldToCamera / worldToNDC. Throws taa::Error naming the file.
void writeConventionFrame(const SceneFrame& frame, const std::string& sceneName,
                          ConventionVariant variant, const std::string& dir);

}  // namespace taa::scenes
