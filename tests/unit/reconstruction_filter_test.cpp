#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "resolve/jitter.h"
#include "resolve/reconstruction_filter.h"
#include "taa/error.h"

namespace taa {
namespace {

float sum(const std::array<float, 9>& weights) {
  return std::accumulate(weights.begin(), weights.end(), 0.0f);
}

TEST(ReconstructionFilter, CentreTakesThePixelsOwnSampleWhateverTheJitter) {
  const std::array<float, 9> w = reconstructionWeights(Reconstruction::Centre, {0.4f, -0.3f});
  for (int i = 0; i < 9; ++i) EXPECT_EQ(w[std::size_t(i)], i == 4 ? 1.0f : 0.0f) << i;
}

TEST(ReconstructionFilter, WeightsSumToOne) {
  for (Reconstruction filter : {Reconstruction::BlackmanHarris, Reconstruction::Lanczos2}) {
    for (const glm::vec2 jitter :
         {glm::vec2(0.0f), glm::vec2(0.49f, -0.5f), glm::vec2(-0.2f, 0.3f)}) {
      EXPECT_NEAR(sum(reconstructionWeights(filter, jitter)), 1.0f, 1e-6f);
    }
  }
}

TEST(ReconstructionFilter, LanczosInterpolatesUnjitteredSamples) {
  // Lanczos-2 is zero at every non-zero integer: samples at pixel centres are taken as they are.
  const std::array<float, 9> w = reconstructionWeights(Reconstruction::Lanczos2, {0.0f, 0.0f});
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(w[std::size_t(i)], i == 4 ? 1.0f : 0.0f, 1e-6f) << i;
}

TEST(ReconstructionFilter, BlackmanHarrisIsSoftAndPositive) {
  const std::array<float, 9> w =
      reconstructionWeights(Reconstruction::BlackmanHarris, {0.0f, 0.0f});
  for (float weight : w) EXPECT_GT(weight, 0.0f);
  EXPECT_NEAR(w[3] / w[4], std::exp(-2.29f), 1e-6f);  // a direct neighbour, one pixel away
  EXPECT_FLOAT_EQ(w[0], w[8]);                         // symmetric
}

TEST(ReconstructionFilter, NeighbourCloserToTheCentreWeighsMore) {
  // Samples moved right by 0.4: the left neighbour's sample is 0.6 px away, the right one's 1.4.
  for (Reconstruction filter : {Reconstruction::BlackmanHarris, Reconstruction::Lanczos2}) {
    const std::array<float, 9> w = reconstructionWeights(filter, {0.4f, 0.0f});
    EXPECT_GT(w[3], w[5]);
    EXPECT_GT(w[4], w[3]);
    EXPECT_FLOAT_EQ(w[1], w[7]);  // rows above and below alike
    EXPECT_FLOAT_EQ(w[0], w[6]);
  }
}

TEST(ReconstructionFilter, Lanczos2HasNegativeLobes) {
  // 1.5 px away lies in the negative lobe (between 1 and 2).
  EXPECT_LT(lanczos2Weight({1.5f, 0.0f}), 0.0f);
  EXPECT_FLOAT_EQ(lanczos2Weight({2.0f, 0.0f}), 0.0f);
  EXPECT_FLOAT_EQ(lanczos2Weight({0.0f, 0.0f}), 1.0f);
}

// Issue 17: a NaN jitter made every weight NaN and the whole frame +Inf. Jitter is checked where
// it enters (resolve/jitter.h); here the weights fall back to the centre sample regardless.
TEST(ReconstructionFilter, NonFiniteJitterGivesTheCentreSampleAlone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (Reconstruction filter : {Reconstruction::BlackmanHarris, Reconstruction::Lanczos2}) {
    for (glm::vec2 jitter : {glm::vec2(nan, 0.0f), glm::vec2(0.0f, inf), glm::vec2(-inf, nan)}) {
      const std::array<float, 9> w = reconstructionWeights(filter, jitter);
      for (int i = 0; i < 9; ++i) EXPECT_EQ(w[std::size_t(i)], i == 4 ? 1.0f : 0.0f);
    }
  }
}

TEST(Jitter, CheckedJitterRefusesNonFiniteOffsetsNamingTheSource) {
  EXPECT_EQ(checkedJitter({0.25f, -0.5f}, "x"), glm::vec2(0.25f, -0.5f));
  try {
    checkedJitter({std::numeric_limits<float>::quiet_NaN(), 0.5f}, "the header attribute j",
                  {"beauty.0007.exr", 7, ""});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "jitter (nan, 0.5) from the header attribute j is not a finite "
                           "number of pixels : beauty.0007.exr (frame 7)");
  }
  // Issue 25: 1e38 was taken. A jitter is at most a pixel from the centre.
  EXPECT_EQ(checkedJitter({-1.0f, 1.0f}, "x"), glm::vec2(-1.0f, 1.0f));
  for (glm::vec2 far : {glm::vec2(1e38f, 0.0f), glm::vec2(0.0f, -1.5f)}) {
    try {
      checkedJitter(far, "the camera sidecar");
      FAIL() << "no error for " << far.x << ", " << far.y;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("from the camera sidecar is more than 1 pixel from "
                                           "the pixel centre"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace taa
