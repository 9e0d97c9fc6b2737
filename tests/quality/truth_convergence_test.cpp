// The 3D scenes' truth is converged: a whole frame rendered again with another jittered sample
// pattern moves by less than 1e-3 RMS (linear RGB), so metric differences are the resolve's,
// not noise. One frame per scene, on its hardest content.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "scenegen/scenes_3d.h"

namespace taa::scenes {
namespace {

struct Shot {
  const char* scene;
  int frame;
};

const Shot kShots[] = {
    {"wires", 9},          {"checker_dolly", 9}, {"moving_object_3d", 9}, {"rotate_yaw", 5},
    {"hdr_highlights", 9}, {"sky_pan", 5},       {"cut", kCutFrame},
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
  for (const Shot& shot : kShots) {
    const auto scene = makeScene3d(shot.scene, 320, 180);
    ASSERT_TRUE(scene) << shot.scene;
    RenderSettings first, second;
    first.truthSeed = 1;
    second.truthSeed = 2;
    const auto start = std::chrono::steady_clock::now();
    const Image a = scene->truthRegion(shot.frame, first, 0, 0, 320, 180);
    const Image b = scene->truthRegion(shot.frame, second, 0, 0, 320, 180);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const double rms = rmsDifference(a, b);
    std::printf("%-18s frame %2d: RMS %.2e (%.2f s)\n", shot.scene, shot.frame, rms,
                seconds.count());
    EXPECT_LT(rms, 1e-3) << shot.scene << " frame " << shot.frame;
  }
}

}  // namespace
}  // namespace taa::scenes
