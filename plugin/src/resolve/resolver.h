// The temporal resolve node: owns the GL programs and the history for one sequence, and turns
// each incoming frame (already in internal conventions) into a resolved RGBA image.
#pragma once

#include <glm/vec2.hpp>

#include <memory>

#include "gl/context.h"
#include "taa/options.h"
#include "util/image.h"

namespace taa {

// One frame's inputs, in internal conventions (DESIGN.md section 3), all the same size.
struct ResolveInput {
  const Image* color = nullptr;   // RGBA, required
  const Image* depth = nullptr;   // 1 channel, optional (enables motion dilation)
  const Image* motion = nullptr;  // 2 channels, optional (absent = static scene)
  glm::vec2 jitter{0.0f};         // this frame's sample offset, pixels, y down
};

class Resolver {
 public:
  // The context must be current on the calling thread for every call, destructor included.
  Resolver(gl::Context& context, const ResolveOptions& options);
  ~Resolver();
  Resolver(const Resolver&) = delete;
  Resolver& operator=(const Resolver&) = delete;

  // Resolves the next frame of the sequence and returns RGBA of the input's size. The first
  // frame, a frame after resetHistory() and a frame whose size differs from the last one use
  // the current frame alone. Throws taa::Error on malformed input or a GL failure.
  Image resolve(const ResolveInput& input);

  // Forget history (a cut, or a gap in the frame sequence).
  void resetHistory();

  const ResolveOptions& options() const;
  // Options that only change uniforms take effect on the next frame; [program] ones rebuild.
  void setOptions(const ResolveOptions& options);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace taa
