// Whether the tonemap bracket the settings ask for can be built: the config loads and has the
// named colorspaces and bracket. Run when an instance is made or its colour settings change,
// so that a studio config without taa's bracket is reported on the effect before any render.
#pragma once

#include <string>

#include "ofx/plugin_parameters.h"

namespace taa::ofx {

// "" when the bracket builds, else why not: the config, the missing name and the names the
// config offers instead.
std::string colorSettingsProblem(const PluginSettings& settings);

}  // namespace taa::ofx
