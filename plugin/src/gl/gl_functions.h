// The OpenGL entry points taa uses, resolved through the back end's GetProcAddress. taa never
// links libGL/libOpenGL: EGL and OSMesa each hand out their own pointers, and a table per
// context keeps them apart. Add an entry here (and in gl_functions.cpp) before using a new call.
#pragma once

#include <GL/glcorearb.h>

namespace taa::gl {

using ProcLoader = void* (*)(const char* name, void* userData);

struct Functions {
#define TAA_GL_FUNCTION(type, name) type name = nullptr;
#include "gl/gl_function_list.inc"
#include "gl/gl_optional_function_list.inc"
#undef TAA_GL_FUNCTION

  // Resolves every entry; throws taa::Error naming the first entry point of
  // gl_function_list.inc that is missing (gl_optional_function_list.inc's stay null).
  void load(ProcLoader loader, void* userData, const char* backendName);
};

}  // namespace taa::gl
