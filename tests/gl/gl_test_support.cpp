#include "gl_test_support.h"

namespace taa::gl::test {

std::string backendParamName(const ::testing::TestParamInfo<Backend>& info) {
  return backendName(info.param);
}

ShaderSource fragmentShader(const std::string& name, const std::string& body) {
  return {name, "#version 410 core\nlayout(location = 0) out vec4 outColor;\n" + body, {}};
}

std::vector<float> renderPass(const Functions& gl, const ShaderSource& fragment, int width,
                              int height, const std::function<void(const Program&)>& setup) {
  Texture target(gl, width, height, GL_RGBA32F);
  Framebuffer framebuffer(gl, target);
  Program program(gl, embeddedShaderSource("fullscreen.vert"), fragment);
  FullscreenTriangle triangle(gl);
  framebuffer.bind();
  program.use();
  if (setup) setup(program);
  triangle.draw("test pass");
  return framebuffer.readRGBA();
}

}  // namespace taa::gl::test
