#include <gtest/gtest.h>

#include "resolve/jitter.h"

namespace taa {
namespace {

TEST(Jitter, RadicalInverseKnownValues) {
  EXPECT_DOUBLE_EQ(radicalInverse(0, 2), 0.0);
  EXPECT_DOUBLE_EQ(radicalInverse(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radicalInverse(3, 2), 0.75);
  EXPECT_DOUBLE_EQ(radicalInverse(6, 2), 0.375);
  EXPECT_DOUBLE_EQ(radicalInverse(1, 3), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 3), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(radicalInverse(4, 3), 4.0 / 9.0);
}

TEST(Jitter, DefaultIsHaltonAtFrameNumberCentred) {
  JitterOptions options;
  const glm::vec2 j = frameJitter(1, options);
  EXPECT_FLOAT_EQ(j.x, 0.0f);                 // 0.5 - 0.5
  EXPECT_FLOAT_EQ(j.y, 1.0f / 3.0f - 0.5f);
  const glm::vec2 j4 = frameJitter(4, options);
  EXPECT_FLOAT_EQ(j4.x, 0.125f - 0.5f);
  EXPECT_FLOAT_EQ(j4.y, 4.0f / 9.0f - 0.5f);
}

TEST(Jitter, StaysInHalfOpenUnitSquare) {
  JitterOptions options;
  for (int frame = -50; frame < 2000; ++frame) {
    const glm::vec2 j = frameJitter(frame, options);
    ASSERT_GE(j.x, -0.5f);
    ASSERT_LT(j.x, 0.5f);
    ASSERT_GE(j.y, -0.5f);
    ASSERT_LT(j.y, 0.5f);
  }
}

TEST(Jitter, OffsetShiftsTheIndex) {
  JitterOptions options;
  options.indexOffset = -1000;
  EXPECT_EQ(haltonIndex(1003, options), 3);
  EXPECT_EQ(frameJitter(1003, options), frameJitter(3, JitterOptions{}));
}

TEST(Jitter, PeriodCyclesThroughOneToP) {
  JitterOptions options;
  options.period = 8;
  EXPECT_EQ(haltonIndex(1, options), 1);
  EXPECT_EQ(haltonIndex(8, options), 8);
  EXPECT_EQ(haltonIndex(9, options), 1);
  EXPECT_EQ(haltonIndex(0, options), 8);
  EXPECT_EQ(haltonIndex(-7, options), 1);
  EXPECT_EQ(frameJitter(17, options), frameJitter(1, options));
}

TEST(Jitter, NoneIsZero) {
  JitterOptions options;
  options.source = JitterSource::None;
  EXPECT_EQ(frameJitter(5, options), glm::vec2(0.0f));
}

TEST(Jitter, ScaleMultipliesTheOffsets) {
  JitterOptions options;
  options.scale = 0.5f;
  for (int frame : {1, 4, 17}) {
    const glm::vec2 full = frameJitter(frame, JitterOptions{});
    const glm::vec2 half = frameJitter(frame, options);
    EXPECT_FLOAT_EQ(half.x, 0.5f * full.x);
    EXPECT_FLOAT_EQ(half.y, 0.5f * full.y);
  }
}

}  // namespace
}  // namespace taa
