// Renderer presets: each renderer's AOV channel names and value conventions, as data. What is
// verified and what is assumed, with sources, is in README.md ("Renderer presets"); every field
// can be overridden by taatool's explicit flags.
#pragma once

#include <string>
#include <vector>

#include "io/aov_layout.h"

namespace taa::io {

struct RendererPreset {
  std::string name;      // --preset value, e.g. "nuke"
  std::string renderer;  // e.g. "Foundry Nuke (ScanlineRender, VectorGenerator)"
  // Channel names; "{layer}" is replaced by "<layer>." (or nothing for an empty layer).
  std::vector<std::string> colorChannels, depthChannels, motionChannels;
  MotionConvention motionConvention;
  DepthConvention depthConvention;
};

// Every preset, in a stable order (cycles first).
const std::vector<RendererPreset>& rendererPresets();

// "cycles, nuke, ...".
std::string presetNames();

// The layout of preset `name` with every AOV in the color file `colorPattern` (override file
// patterns afterwards for renderers writing one file per AOV). `layer` fills "{layer}".
// Throws taa::Error for an unknown name, listing the known ones.
AovLayout presetLayout(const std::string& name, const std::string& colorPattern,
                       const std::string& layer = "ViewLayer");

}  // namespace taa::io
