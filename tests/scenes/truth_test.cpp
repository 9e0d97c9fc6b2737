// The truth is the box-filtered limit of the colour samples.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "scene_test_util.h"
#include "scenegen/patterns.h"
#include "scenegen/scene_library.h"
#include "scenegen/scenes_3d.h"

namespace taa::scenes::test {
namespace {

// Averaged over frames (different jitters), one sample per pixel converges to the pixel
// average, so the image means agree.
TEST(SceneTruth, MeanMatchesMeanOfColorSamples) {
  for (const SceneInfo& info : sceneList()) {
    const auto scene = makeScene(info.name, 320, 180);
    // Layered scenes only: 3D scenes have their own truth tests (tests/quality), and HDR
    // highlights worth 1000 make a 4-sample mean too noisy for a 2% bound.
    if (!dynamic_cast<const LayeredScene*>(scene.get())) continue;
    glm::dvec4 colorMean(0.0), truthMean(0.0);
    const int frames = 4;
    for (int frame = 1; frame <= frames; ++frame) {
      const SceneFrame rendered = scene->render(frame, RenderSettings{});
      colorMean += channelMeans(rendered.color) / double(frames);
      truthMean += channelMeans(rendered.truth) / double(frames);
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(colorMean[c], truthMean[c], 0.02 * truthMean[c]) << info.name << " c" << c;
    }
    EXPECT_EQ(truthMean[3], 1.0) << info.name << ": every pixel hits the background";
  }
}

// A finer grid changes the truth only a little: 16 x 16 is close to the limit.
TEST(SceneTruth, ConvergesWithMoreSamples) {
  const auto scene = makeScene("moving_object", 96, 54);
  RenderSettings coarse, fine;
  fine.truthSamplesPerAxis = 48;
  const SceneFrame a = scene->render(5, coarse), b = scene->render(5, fine);
  double sum = 0.0, magnitude = 0.0;
  for (std::size_t k = 0; k < a.truth.pixels.size(); ++k) {
    sum += std::fabs(a.truth.pixels[k] - b.truth.pixels[k]);
    magnitude += std::fabs(b.truth.pixels[k]);
  }
  EXPECT_LT(sum / magnitude, 0.01);
}

// The 3D truth's cells lie on one grid over the whole frame: any region, on any number of
// threads, has exactly the whole frame's pixels (so checks on a region hold for the files).
TEST(SceneTruth, RegionOf3dFrameIsThatFramesPixels) {
  const auto scene = makeScene3d("wires", 64, 36);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 4;
  settings.threads = 3;
  const SceneFrame whole = scene->render(7, settings);
  settings.threads = 1;
  const int x0 = 13, y0 = 5;
  const Image region = scene->truthRegion(7, settings, x0, y0, 21, 11);
  for (int j = 0; j < region.height; ++j) {
    for (int i = 0; i < region.width; ++i) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(region.at(i, j)[c], whole.truth.at(x0 + i, y0 + j)[c]) << i << ", " << j;
      }
    }
  }
}

// Where nothing is hit: depth +inf, zero motion and alpha 0; truth alpha is the coverage.
TEST(SceneTruth, NoHitPixelsAndPartialCoverage) {
  Layer disc;
  disc.texture = objectPattern;
  disc.shape = DiscShape{6.0};
  disc.boundsMin = glm::dvec2(-6.0);
  disc.boundsMax = glm::dvec2(6.0);
  disc.originAtFrame0 = {16.0, 9.0};
  disc.velocity = {0.5, 0.0};
  disc.depth = 2.0f;
  const LayeredScene scene("disc_only", 32, 18, {disc});
  const SceneFrame frame = scene.render(0, RenderSettings{});
  EXPECT_TRUE(std::isinf(frame.depth.at(0, 0)[0]));
  EXPECT_EQ(frame.color.at(0, 0)[3], 0.0f);
  EXPECT_EQ(frame.motion.at(0, 0)[0], 0.0f);
  EXPECT_EQ(frame.depth.at(16, 9)[0], 2.0f);
  EXPECT_EQ(frame.motion.at(16, 9)[0], -0.5f);
  double coverage = 0.0;
  for (int j = 0; j < 18; ++j) {
    for (int i = 0; i < 32; ++i) coverage += frame.truth.at(i, j)[3];
  }
  EXPECT_NEAR(coverage, 3.14159265358979 * 36.0, 0.5);
}

}  // namespace
}  // namespace taa::scenes::test
