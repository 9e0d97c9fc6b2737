// A node's window ring with passes keeps to taatool's memory rule (resolve/window_budget): where
// 2K+2 frames with their passes would not fit, the ring holds the longest window that does, and
// the node plans its windows with that K, as taatool does. The budget is made tiny here so that
// 8x8 frames meet it.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "capi/status_error.h"
#include "capi/window_frames.h"
#include "gl/context.h"
#include "resolve/window_budget.h"

namespace taa::capi {
namespace {

constexpr int kSize = 8;

class WindowFramesBudget : public ::testing::Test {
 protected:
  void SetUp() override {
    context_ = gl::Context::create(gl::Backend::Auto);
    options_.mode = ResolveMode::Window;
    options_.window.radius = 4;
    options_.window.nearRadius = 1;
  }

  // Pushes frames first..last, each a grey frame with one half light pass (RGB).
  void pushFrames(WindowFrames& frames, int first, int last, bool withPasses) {
    for (int frame = first; frame <= last; ++frame) {
      Image color(kSize, kSize, 4);
      for (float& v : color.pixels) v = 0.25f;
      ResolveInput input;
      input.color = &color;
      FramePasses passes;
      passes.names = {"ViewLayer.DiffDir.R", "ViewLayer.DiffDir.G", "ViewLayer.DiffDir.B"};
      passes.types.assign(3, OIIO::TypeDesc::HALF);
      passes.values = Image(kSize, kSize, 3);
      frames.push(frame, input, frame == first, FrameMatrices{}, withPasses ? &passes : nullptr);
    }
  }

  // Bytes of one 8x8 frame with the pass above (colour 20 + one half group 8, a pixel).
  static double frameBytes() { return 28.0 * kSize * kSize; }

  std::unique_ptr<gl::Context> context_;
  ResolveOptions options_;
};

TEST_F(WindowFramesBudget, PassesThatDoNotFitShortenTheRingAndTheWindow) {
  // Room for the rings of K 2 (6 frames), not K 3.
  WindowFrames frames(*context_, options_, windowRingBytes(2, frameBytes()));
  pushFrames(frames, 1, 9, true);
  // A ring of 2K+1 = 5 frames: pushing 6..9 evicted 1..4, and frame 7's window is 5..9.
  EXPECT_NO_THROW(frames.resolve(7, SampleType::Float));
  try {
    frames.resolve(6, SampleType::Float);
    FAIL() << "frame 6's window (4..8) should miss frame 4";
  } catch (const StatusError& e) {
    EXPECT_EQ(e.status(), TAA_ERROR_MISSING_FRAME);
    EXPECT_NE(std::string(e.what()).find("frame 4 of frame 6's window (frames 4-8)"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("full ring of 5 frames"), std::string::npos)
        << e.what();
  }
}

TEST_F(WindowFramesBudget, ColourAloneKeepsTheWindowAsked) {
  WindowFrames frames(*context_, options_, windowRingBytes(2, frameBytes()));
  pushFrames(frames, 1, 9, false);
  // K 4: frame 7's window is 3..9, all held in the ring of 9 frames.
  EXPECT_NO_THROW(frames.resolve(7, SampleType::Float));
  EXPECT_NO_THROW(frames.resolve(3, SampleType::Float));
}

TEST_F(WindowFramesBudget, NewOptionsKeepTheRingWithinTheBudget) {
  WindowFrames frames(*context_, options_, windowRingBytes(2, frameBytes()));
  pushFrames(frames, 1, 9, true);
  ResolveOptions other = options_;
  other.window.falloff = 3.0f;
  frames.setOptions(other);  // a new, empty ring
  pushFrames(frames, 1, 9, true);
  EXPECT_NO_THROW(frames.resolve(7, SampleType::Float));
  EXPECT_THROW(frames.resolve(6, SampleType::Float), StatusError);
}

}  // namespace
}  // namespace taa::capi
