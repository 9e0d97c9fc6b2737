#include "gl/self_test.h"

#include <vector>

#include "gl/objects.h"
#include "taa/error.h"

namespace taa::gl {

std::array<float, 4> selfTestPattern(int x, int y) {
  return {static_cast<float>(x), static_cast<float>(y),
          static_cast<float>((x * y) % 7) * 0.125f - 0.5f, static_cast<float>(x + 2 * y) * 0.25f};
}

namespace {

std::vector<float> renderPattern(const Functions& gl, int width, int height) {
  Texture target(gl, width, height, GL_RGBA32F);
  Framebuffer framebuffer(gl, target);
  Program program(gl, "fullscreen.vert", "pattern.frag");
  FullscreenTriangle triangle(gl);
  framebuffer.bind();
  program.use();
  triangle.draw("self-test pattern pass");
  std::vector<float> pixels = framebuffer.readRGBA();
  gl.UseProgram(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  return pixels;
}

}  // namespace

SelfTestResult runSelfTest(Context& context, int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  std::vector<float> pixels;
  try {
    context.makeCurrent();
    pixels = renderPattern(context.functions(), width, height);
  } catch (const Error& error) {
    return {false, "self test (" + size + "): " + error.description()};
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::array<float, 4> expected = selfTestPattern(x, y);
      const float* got = &pixels[(static_cast<size_t>(y) * width + x) * 4];
      for (int c = 0; c < 4; ++c) {
        if (got[c] != expected[c]) {
          return {false, "self test (" + size + "): pixel (" + std::to_string(x) + ", " +
                             std::to_string(y) + ") channel " + "RGBA"[c] + " read back " +
                             std::to_string(got[c]) + ", expected " +
                             std::to_string(expected[c])};
        }
      }
    }
  }
  return {true, "rendered a " + size + " RGBA32F pattern and read it back exactly"};
}

}  // namespace taa::gl
