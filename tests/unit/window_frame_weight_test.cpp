// The window resolve's weight of a source frame by its distance in frames.
#include "resolve/window_frame_weight.h"

#include <gtest/gtest.h>

namespace taa {
namespace {

TEST(WindowFrameWeight, EveryFrameAlikeByDefault) {
  const WindowOptions options;
  for (int frames : {-4, -1, 1, 3, 4}) EXPECT_EQ(windowFrameWeight(frames, options), 1.0f);
}

TEST(WindowFrameWeight, FalloffHalvesTheWeightAtItsDistance) {
  WindowOptions options;
  options.falloff = 2.0f;
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), 0.5f);
  EXPECT_FLOAT_EQ(windowFrameWeight(-2, options), 0.5f);
  EXPECT_FLOAT_EQ(windowFrameWeight(4, options), 0.2f);
}

TEST(WindowFrameWeight, TaperIsAHannWindowOverKPlusOneFrames) {
  WindowOptions options;
  options.taper = true;
  options.radius = 3;
  EXPECT_FLOAT_EQ(windowFrameWeight(0, options), 1.0f);
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), 0.5f);  // cos^2(pi/4)
  EXPECT_NEAR(windowFrameWeight(-4, options), 0.0f, 1e-7f);
  options.falloff = 2.0f;  // the two multiply
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), 0.25f);
}

}  // namespace
}  // namespace taa
