// translate: motion is exact everywhere and consistent with the images it comes with.
#include <cmath>

#include <gtest/gtest.h>

#include "scene_test_util.h"
#include "scenegen/scene_library.h"

namespace taa::scenes::test {
namespace {

TEST(TranslateScene, MotionIsMinusVelocityEverywhere) {
  const auto scene = makeLayeredScene("translate", 48, 27);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const glm::vec2 velocity(translateVelocity());
  const SceneFrame frame = scene->render(4, settings);
  for (int j = 0; j < frame.motion.height; ++j) {
    for (int i = 0; i < frame.motion.width; ++i) {
      ASSERT_NEAR(frame.motion.at(i, j)[0], -velocity.x, 1e-6);
      ASSERT_NEAR(frame.motion.at(i, j)[1], -velocity.y, 1e-6);
      ASSERT_NEAR(frame.nextMotion.at(i, j)[0], velocity.x, 1e-6);
      ASSERT_NEAR(frame.nextMotion.at(i, j)[1], velocity.y, 1e-6);
      ASSERT_EQ(frame.depth.at(i, j)[0], frame.depth.at(0, 0)[0]);
    }
  }
}

// Point level: the surface at p now is the one at p + mv in the previous frame.
TEST(TranslateScene, PointSamplesFollowMotion) {
  const auto scene = makeLayeredScene("translate", 320, 180);
  int mismatches = 0, total = 0;
  for (int frame = 2; frame <= 6; ++frame) {
    for (double y = 3.1; y < 177; y += 0.37) {
      for (double x = 2.9; x < 317; x += 0.41) {
        const SurfaceSample now = scene->sample(frame, {x, y});
        const glm::dvec2 previous = glm::dvec2(x, y) + glm::dvec2(now.motion);
        const SurfaceSample before = scene->sample(frame - 1, previous);
        ++total;
        if (now.rgb != before.rgb) ++mismatches;  // only a sample on an edge may flip
      }
    }
  }
  EXPECT_LT(mismatches, total / 10000) << mismatches << " of " << total;
}

// Image level, exactly: 100 frames of (1.37, 0.61) px is a whole-pixel shift, so the truth of
// frame t at pixel p + 100 mv must equal the truth of frame t - 100 at p with no resampling.
TEST(TranslateScene, TruthMatchesAfterWholePixelShift) {
  const auto scene = makeLayeredScene("translate", 200, 100);
  const SceneFrame now = scene->render(150, RenderSettings{});
  const SceneFrame before = scene->render(50, RenderSettings{});
  const int dx = int(std::lround(100.0 * now.motion.at(0, 0)[0]));
  const int dy = int(std::lround(100.0 * now.motion.at(0, 0)[1]));
  ASSERT_EQ(dx, -137);
  ASSERT_EQ(dy, -61);
  double worst = 0.0;
  for (int j = 0; j < now.truth.height + dy; ++j) {
    for (int i = 0; i < now.truth.width + dx; ++i) {
      for (int c = 0; c < 4; ++c) {
        const double difference = now.truth.at(i - dx, j - dy)[c] - before.truth.at(i, j)[c];
        worst = std::max(worst, std::fabs(difference));
      }
    }
  }
  // One of 256 truth samples flipping across an edge would show as up to 4/256.
  EXPECT_LT(worst, 1e-4);
}

// Image level, sub-pixel: truth of frame t-1 sampled bilinearly at pos + mv predicts the truth
// of frame t. The truth is box filtered, not band limited, so no interpolator reproduces it at
// a sub-pixel shift; a 1 px Gaussian on both quiets that aliasing. Then the true motion must
// predict well, and better than any motion off by a quarter or half pixel, or none.
TEST(TranslateScene, TruthReprojectsWithMotion) {
  const auto scene = makeLayeredScene("translate", 160, 90);
  const Image before = gaussianBlur(scene->render(9, RenderSettings{}).truth, 1.0);
  const SceneFrame now = scene->render(10, RenderSettings{});
  const Image nowTruth = gaussianBlur(now.truth, 1.0);
  const glm::vec2 mv(now.motion.at(0, 0)[0], now.motion.at(0, 0)[1]);
  auto relativeError = [&](glm::vec2 offset) {
    double error = 0.0, magnitude = 0.0;
    for (int j = 8; j < nowTruth.height - 8; ++j) {
      for (int i = 8; i < nowTruth.width - 8; ++i) {
        const double x = i + 0.5 + mv.x + offset.x, y = j + 0.5 + mv.y + offset.y;
        for (int c = 0; c < 3; ++c) {
          error += std::fabs(bilinear(before, x, y, c) - nowTruth.at(i, j)[c]);
          magnitude += std::fabs(nowTruth.at(i, j)[c]);
        }
      }
    }
    return error / magnitude;
  };
  const double withMotion = relativeError({0.0f, 0.0f});
  EXPECT_LT(withMotion, 0.1);
  EXPECT_LT(2.0 * withMotion, relativeError(-mv)) << "no motion";
  for (float dy = -0.5f; dy <= 0.5f; dy += 0.25f) {
    for (float dx = -0.5f; dx <= 0.5f; dx += 0.25f) {
      if (dx == 0.0f && dy == 0.0f) continue;
      EXPECT_LT(withMotion, relativeError({dx, dy})) << "motion off by " << dx << "," << dy;
    }
  }
}

}  // namespace
}  // namespace taa::scenes::test
