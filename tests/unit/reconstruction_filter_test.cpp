#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "resolve/reconstruction_filter.h"

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

}  // namespace
}  // namespace taa
