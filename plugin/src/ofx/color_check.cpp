#include "ofx/color_check.h"

#include <stdexcept>

#include "color/ocio_bracket.h"
#include "taa/error.h"

namespace taa::ofx {

std::string colorSettingsProblem(const PluginSettings& settings) {
  try {
    const color::OcioBracket bracket(colorOptions(settings));
  } catch (const std::exception& e) {  // taa::Error, or colorOptions' own
    return e.what();
  }
  return "";
}

}  // namespace taa::ofx
