// moving_object: a static background (depth 10) and a disc (depth 4) crossing it.
#include <gtest/gtest.h>

#include "scene_test_util.h"
#include "scenegen/scene_library.h"

namespace taa::scenes::test {
namespace {

bool isStill(const SceneFrame& frame, int i, int j) {
  return frame.motion.at(i, j)[0] == 0.0f && frame.motion.at(i, j)[1] == 0.0f;
}

// No pixel centre within 2 pixels moves: then the disc (radius > 1) cannot reach into the
// pixel's box, since a disc touching the box holds a unit disc that holds a nearby centre.
bool stillAround(const SceneFrame& frame, int i, int j) {
  for (int dj = -2; dj <= 2; ++dj) {
    for (int di = -2; di <= 2; ++di) {
      const int x = i + di, y = j + dj;
      if (x < 0 || y < 0 || x >= frame.motion.width || y >= frame.motion.height) continue;
      if (!isStill(frame, x, y)) return false;
    }
  }
  return true;
}

TEST(MovingObjectScene, DepthAndMotionPerSurface) {
  const auto scene = makeLayeredScene("moving_object", 320, 180);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const SceneFrame frame = scene->render(12, settings);
  const glm::vec2 velocity(movingObjectVelocity(320, 180));
  int background = 0, object = 0;
  for (int j = 0; j < frame.depth.height; ++j) {
    for (int i = 0; i < frame.depth.width; ++i) {
      const float depth = frame.depth.at(i, j)[0];
      const float* mv = frame.motion.at(i, j);
      if (depth == 10.0f) {
        ++background;
        ASSERT_EQ(mv[0], 0.0f);
        ASSERT_EQ(mv[1], 0.0f);
      } else {
        ++object;
        ASSERT_EQ(depth, 4.0f) << "pixel " << i << "," << j;
        ASSERT_NEAR(mv[0], -velocity.x, 1e-5);
        ASSERT_NEAR(mv[1], -velocity.y, 1e-5);
      }
    }
  }
  // The disc has radius 45 px: about 6360 pixels.
  EXPECT_NEAR(object, 6360, 200);
  EXPECT_GT(background, 40000);
}

TEST(MovingObjectScene, StillBackgroundKeepsItsTruth) {
  const auto scene = makeLayeredScene("moving_object", 320, 180);
  for (int t : {2, 13, 24}) {
    const SceneFrame before = scene->render(t - 1, RenderSettings{});
    const SceneFrame current = scene->render(t, RenderSettings{});
    int compared = 0, changed = 0;
    for (int j = 0; j < current.truth.height; ++j) {
      for (int i = 0; i < current.truth.width; ++i) {
        const bool clear = stillAround(current, i, j) && stillAround(before, i, j);
        for (int c = 0; c < 4; ++c) {
          const float a = current.truth.at(i, j)[c], b = before.truth.at(i, j)[c];
          if (clear) {
            ASSERT_EQ(a, b) << "frame " << t << " pixel " << i << "," << j;
          } else if (a != b) {
            ++changed;
          }
        }
        compared += clear;
      }
    }
    EXPECT_GT(compared, 40000) << "frame " << t;
    EXPECT_GT(changed, 1000) << "frame " << t << ": the object should change some pixels";
  }
}

// The object moves far enough to uncover background on one side and cover it on the other.
TEST(MovingObjectScene, ObjectUncoversAndCoversBackground) {
  const auto scene = makeLayeredScene("moving_object", 320, 180);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const SceneFrame first = scene->render(1, settings);
  const SceneFrame last = scene->render(24, settings);
  int uncovered = 0, covered = 0;
  for (int j = 0; j < first.depth.height; ++j) {
    for (int i = 0; i < first.depth.width; ++i) {
      const bool wasObject = first.depth.at(i, j)[0] == 4.0f;
      const bool isObject = last.depth.at(i, j)[0] == 4.0f;
      uncovered += wasObject && !isObject;
      covered += !wasObject && isObject;
    }
  }
  EXPECT_GT(uncovered, 3000);
  EXPECT_GT(covered, 3000);
}

}  // namespace
}  // namespace taa::scenes::test
