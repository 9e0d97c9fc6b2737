// Access to the GLSL sources embedded from glsl/ at build time (cmake/EmbedShaders.cmake).
#pragma once

#include <string>
#include <vector>

namespace taa::gl {

struct EmbeddedShader {
  const char* name;    // file name inside glsl/, e.g. "resolve.frag"
  const char* source;  // the file's text
};

// Every embedded shader, in glsl/ order. Defined in the generated embedded_shaders.cpp.
const std::vector<EmbeddedShader>& embeddedShaders();

// The source of one embedded file with `#include "other.glsl"` lines expanded (recursively,
// each file once). `#line` directives keep the driver's line numbers meaningful; fileNames
// receives the list that maps the driver's source-string numbers to file names.
// Throws taa::Error for an unknown name.
std::string expandedShaderSource(const std::string& name, std::vector<std::string>* fileNames);

}  // namespace taa::gl
