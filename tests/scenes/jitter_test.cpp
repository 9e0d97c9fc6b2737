// The colour of each frame is sampled at exactly frameJitter's offset, so the resolve can
// unjitter it; depth and motion are not jittered.
#include <gtest/gtest.h>

#include "resolve/jitter.h"
#include "scene_test_util.h"

namespace taa::scenes::test {
namespace {

void expectColorAtJitter(const LayeredScene& scene, const SceneFrame& frame) {
  for (int j = 0; j < scene.height(); ++j) {
    for (int i = 0; i < scene.width(); ++i) {
      const glm::dvec2 position = glm::dvec2(i + 0.5, j + 0.5) + glm::dvec2(frame.jitter);
      const SurfaceSample expected = scene.sample(frame.frame, position);
      const float* color = frame.color.at(i, j);
      ASSERT_EQ(color[0], expected.rgb.r) << "pixel " << i << "," << j;
      ASSERT_EQ(color[1], expected.rgb.g);
      ASSERT_EQ(color[2], expected.rgb.b);
      ASSERT_EQ(color[3], 1.0f);
    }
  }
}

TEST(SceneJitter, ColorIsSampledAtFrameJitter) {
  const auto scene = makeLayeredScene("moving_object", 64, 36);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  for (int frame = 1; frame <= 8; ++frame) {
    const SceneFrame rendered = scene->render(frame, settings);
    const glm::vec2 expected = frameJitter(frame, JitterOptions{});
    EXPECT_EQ(rendered.jitter.x, expected.x) << "frame " << frame;
    EXPECT_EQ(rendered.jitter.y, expected.y) << "frame " << frame;
    expectColorAtJitter(*scene, rendered);
  }
}

TEST(SceneJitter, FollowsJitterOptions) {
  const auto scene = makeLayeredScene("static", 32, 18);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  settings.jitter.indexOffset = 5;
  settings.jitter.period = 8;
  for (int frame = -3; frame <= 12; ++frame) {
    const SceneFrame rendered = scene->render(frame, settings);
    const glm::vec2 expected = frameJitter(frame, settings.jitter);
    EXPECT_EQ(rendered.jitter.x, expected.x) << "frame " << frame;
    EXPECT_EQ(rendered.jitter.y, expected.y) << "frame " << frame;
    expectColorAtJitter(*scene, rendered);
  }
}

TEST(SceneJitter, NoneSamplesAtPixelCentres) {
  const auto scene = makeLayeredScene("static", 32, 18);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  settings.jitter.source = JitterSource::None;
  const SceneFrame rendered = scene->render(3, settings);
  EXPECT_EQ(rendered.jitter, glm::vec2(0.0f));
  expectColorAtJitter(*scene, rendered);
}

TEST(SceneJitter, DepthAndMotionAreTakenAtPixelCentres) {
  const auto scene = makeLayeredScene("moving_object", 64, 36);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const SceneFrame rendered = scene->render(6, settings);
  ASSERT_NE(rendered.jitter, glm::vec2(0.0f));
  for (int j = 0; j < scene->height(); ++j) {
    for (int i = 0; i < scene->width(); ++i) {
      const SurfaceSample centre = scene->sample(6, glm::dvec2(i + 0.5, j + 0.5));
      ASSERT_EQ(rendered.depth.at(i, j)[0], centre.depth);
      ASSERT_EQ(rendered.motion.at(i, j)[0], centre.motion.x);
      ASSERT_EQ(rendered.motion.at(i, j)[1], centre.motion.y);
      ASSERT_EQ(rendered.nextMotion.at(i, j)[0], centre.nextMotion.x);
      ASSERT_EQ(rendered.nextMotion.at(i, j)[1], centre.nextMotion.y);
    }
  }
}

}  // namespace
}  // namespace taa::scenes::test
