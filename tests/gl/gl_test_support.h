// Helpers shared by the GL tests: back-end parameters and one-pass rendering.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/objects.h"

namespace taa::gl::test {

// Test-name suffix for a back-end parameter ("egl", "osmesa").
std::string backendParamName(const ::testing::TestParamInfo<Backend>& info);

// A fragment shader ShaderSource from body text; "#version 410 core" and the output
// `layout(location = 0) out vec4 outColor;` are prepended.
ShaderSource fragmentShader(const std::string& name, const std::string& body);

// Renders `fragment` (with fullscreen.vert) into a width x height RGBA32F framebuffer and
// returns its pixels, row 0 first. `setup` binds textures and sets uniforms before drawing.
std::vector<float> renderPass(const Functions& gl, const ShaderSource& fragment, int width,
                              int height, const std::function<void(const Program&)>& setup = {});

}  // namespace taa::gl::test
