#include "resolve/resolve_input.h"

#include <optional>
#include <string>

#include "taa/error.h"

namespace taa {

void checkPlane(const ImageView& plane, const ImageView& color, int channels, const char* name) {
  if (!plane) return;
  if (plane.width != color.width || plane.height != color.height) {
    throw Error(std::string(name) + " is " + std::to_string(plane.width) + "x" +
                    std::to_string(plane.height) + " but color is " +
                    std::to_string(color.width) + "x" + std::to_string(color.height),
                {"", std::nullopt, name});
  }
  if (plane.channels != channels) {
    throw Error(std::string(name) + " must have " + std::to_string(channels) +
                    " channels, has " + std::to_string(plane.channels),
                {"", std::nullopt, name});
  }
}

GLenum glType(SampleType type) { return type == SampleType::Half ? GL_HALF_FLOAT : GL_FLOAT; }

}  // namespace taa
