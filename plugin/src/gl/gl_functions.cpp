#include "gl/gl_functions.h"

#include <string>

#include "taa/error.h"

namespace taa::gl {

void Functions::load(ProcLoader loader, void* userData, const char* backendName) {
  // Resolve everything first, then report the first gap, so the message names one entry point.
  const char* missing = nullptr;
#define TAA_GL_FUNCTION(type, name)                                  \
  name = reinterpret_cast<type>(loader("gl" #name, userData));       \
  if (!name && !missing) missing = "gl" #name;
#include "gl/gl_function_list.inc"
#undef TAA_GL_FUNCTION
#define TAA_GL_FUNCTION(type, name) name = reinterpret_cast<type>(loader("gl" #name, userData));
#include "gl/gl_optional_function_list.inc"
#undef TAA_GL_FUNCTION
  if (missing) {
    throw Error(std::string(backendName) + ": OpenGL entry point " + missing +
                " is not available");
  }
}

}  // namespace taa::gl
