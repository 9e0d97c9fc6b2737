// The 3D scenes' truth is converged: rendered again with another jittered sample pattern it
// moves by less than 1e-3 RMS (linear RGB), so metric differences are the resolve's, not noise.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "scenegen/scenes_3d.h"

namespace taa::scenes {
namespace {

struct Crop {
  const char* scene;
  int frame;
  int x0, y0;  // a 64 x 36 window of the 320 x 180 frame on the scene's hardest content
};

constexpr int kCropWidth = 64, kCropHeight = 36;

const Crop kCrops[] = {
    {"wires", 5, 120, 80},          {"wires", 9, 0, 20},
    {"checker_dolly", 5, 130, 52},  {"checker_dolly", 9, 10, 100},
    {"moving_object_3d", 5, 40, 66}, {"moving_object_3d", 9, 200, 60},
    {"rotate_yaw", 5, 150, 60},     {"hdr_highlights", 5, 80, 70},
    {"hdr_highlights", 9, 200, 20}, {"sky_pan", 5, 190, 60},
    {"cut", 8, 120, 80},            {"cut", kCutFrame, 128, 72},
};

// RMS over pixels and RGB of a - b.
double rmsDifference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (int j = 0; j < a.height; ++j) {
    for (int i = 0; i < a.width; ++i) {
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.at(i, j)[c]) - b.at(i, j)[c];
        sum += d * d;
      }
    }
  }
  return std::sqrt(sum / (3.0 * a.width * a.height));
}

TEST(SceneTruth3d, SecondSamplePatternAgreesWithin1e3Rms) {
  for (const Crop& crop : kCrops) {
    const auto scene = makeScene3d(crop.scene, 320, 180);
    ASSERT_TRUE(scene) << crop.scene;
    RenderSettings first, second;
    first.truthSeed = 1;
    second.truthSeed = 2;
    const auto start = std::chrono::steady_clock::now();
    const Image a = scene->truthRegion(crop.frame, first, crop.x0, crop.y0, kCropWidth,
                                       kCropHeight);
    const Image b = scene->truthRegion(crop.frame, second, crop.x0, crop.y0, kCropWidth,
                                       kCropHeight);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const double rms = rmsDifference(a, b);
    std::printf("%-18s frame %2d at (%3d, %3d): RMS %.2e (%.2f s)\n", crop.scene, crop.frame,
                crop.x0, crop.y0, rms, seconds.count());
    EXPECT_LT(rms, 1e-3) << crop.scene << " frame " << crop.frame;
  }
}

}  // namespace
}  // namespace taa::scenes
