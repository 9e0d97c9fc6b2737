// The window resolve's weight of a source frame by its distance in frames.
#include "resolve/window_frame_weight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace taa {
namespace {

TEST(WindowFrameWeight, EveryFrameAlikeWithoutFalloffOrTaper) {
  WindowOptions options;
  options.falloff = 0.0f;
  for (int frames : {-4, -1, 1, 3, 4}) EXPECT_EQ(windowFrameWeight(frames, options), 1.0f);
}

TEST(WindowFrameWeight, TheDefaultFalloffWeighsTheWindowsEndsLess) {
  const WindowOptions options;  // K 16, falloff 14 (docs/TUNING.md, "The tile test")
  EXPECT_FLOAT_EQ(windowFrameWeight(14, options), std::exp(-1.0f));
  EXPECT_GT(windowFrameWeight(2, options), 0.97f);
}

TEST(WindowFrameWeight, FalloffIsAGaussianInFrames) {
  WindowOptions options;
  options.falloff = 2.0f;
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), std::exp(-1.0f));
  EXPECT_FLOAT_EQ(windowFrameWeight(-2, options), std::exp(-1.0f));
  EXPECT_FLOAT_EQ(windowFrameWeight(4, options), std::exp(-4.0f));
}

TEST(WindowFrameWeight, TaperIsAHannWindowOverKPlusOneFrames) {
  WindowOptions options;
  options.taper = true;
  options.radius = 3;
  options.falloff = 0.0f;
  EXPECT_FLOAT_EQ(windowFrameWeight(0, options), 1.0f);
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), 0.5f);  // cos^2(pi/4)
  EXPECT_NEAR(windowFrameWeight(-4, options), 0.0f, 1e-7f);
  options.falloff = 2.0f;  // the two multiply
  EXPECT_FLOAT_EQ(windowFrameWeight(2, options), 0.5f * std::exp(-1.0f));
}

}  // namespace
}  // namespace taa
