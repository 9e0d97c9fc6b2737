// A quick proof that an OpenGL context renders correctly: draw a known pattern into a float
// framebuffer and compare it exactly with the same pattern computed on the CPU.
#pragma once

#include <array>
#include <string>

#include "gl/context.h"

namespace taa::gl {

struct SelfTestResult {
  bool passed = false;
  std::string detail;  // what was checked, or the first mismatch or error
};

// Makes `context` current on the calling thread, renders glsl/pattern.frag at width x height
// into a GL_RGBA32F framebuffer and reads it back. GL failures become a failed result.
SelfTestResult runSelfTest(Context& context, int width = 37, int height = 23);

// The value glsl/pattern.frag writes at pixel (x, y), row 0 being the first row read back.
std::array<float, 4> selfTestPattern(int x, int y);

}  // namespace taa::gl
