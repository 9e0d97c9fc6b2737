// The temporal resolve node: owns the GL programs and the history for one sequence, and turns
// each incoming frame (already in internal conventions) into a resolved RGBA image.
#pragma once

#include <glm/vec2.hpp>

#include <memory>
#include <vector>

#include "gl/context.h"
#include "resolve/camera.h"
#include "taa/options.h"
#include "util/image.h"

namespace taa {

// One frame's inputs, in internal conventions (DESIGN.md section 3), all the same size. Each
// takes a pointer to an Image, HalfImage or TypedImage (util/image.h); half or float, the
// resolve samples the same values (half colour is uploaded as half, never widened on the CPU).
struct ResolveInput {
  ImageView color;   // RGBA, required
  ImageView depth;   // 1 channel, optional (dilation, disocclusion, camera motion)
  ImageView motion;  // 2 channels, optional (absent = camera motion or static)
  glm::vec2 jitter{0.0f};         // this frame's sample offset, pixels, y down
  const FrameCamera* camera = nullptr;  // optional: enables camera motion with the previous one
  RasterWindow window;            // where the pixels sit in the display window (for the camera)
  NdcConvention ndc = NdcConvention::ZeroOneYDown;
  // Window mode: the frame's pass values, RGBA half or float per group (resolve/pass_plan),
  // as many as WindowResolver::setPasses said.
  std::vector<ImageView> passGroups;
  // And each Cryptomatte set's first rank layer, RGBA float (resolve/pass_plan).
  std::vector<ImageView> cryptomatte;
};

// Per-pixel diagnostics of the last frame (setDebugOutput): RGBA = (weight given to history,
// rejection reason, velocity x, velocity y). Reasons: 0 history kept, 1 no history (first frame,
// reset, cut), 2 off-screen, 3 disoccluded (depth).
enum class Rejection { Kept = 0, NoHistory = 1, OffScreen = 2, Disoccluded = 3 };

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
  // The same, read back as `outputType`: half is rounded to nearest even by GL, exactly as
  // narrowing the float result would, at half the read-back cost and none on the writer's side.
  TypedImage resolve(const ResolveInput& input, SampleType outputType);

  // Forget history (a cut, or a gap in the frame sequence).
  void resetHistory();

  const ResolveOptions& options() const;
  // Options that only change uniforms take effect on the next frame; [program] ones rebuild.
  // Throws (keeping the old options) when the new ones are unusable, e.g. an unknown bracket.
  void setOptions(const ResolveOptions& options);

  // Keep each frame's diagnostics for lastDebug() (one more read-back per frame).
  void setDebugOutput(bool enabled);
  const Image& lastDebug() const;
  // True when cut detection reset history on the last frame.
  bool lastFrameWasCut() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace taa
