// The yardstick's metrics on tiny hand-made images whose answers are known.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "yardstick/metrics.h"
#include "yardstick/report.h"
#include "yardstick/sequence_score.h"

namespace taa::yardstick {
namespace {

// An RGB image whose pixel (x, y) is f(x, y) in every channel.
template <typename F>
Image makeImage(int w, int h, F f) {
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) image.at(x, y)[c] = float(f(x, y));
    }
  }
  return image;
}

TEST(YardstickMetrics, TonemapIsReinhard) {
  const Image linear =
      makeImage(3, 1, [](int x, int) { return x == 0 ? -1.0 : x == 1 ? 1.0 : 3.0; });
  const Image mapped = tonemap(linear);
  EXPECT_EQ(mapped.at(0, 0)[0], 0.0f);  // negatives clamp to 0
  EXPECT_FLOAT_EQ(mapped.at(1, 0)[0], 0.5f);
  EXPECT_FLOAT_EQ(mapped.at(2, 0)[0], 0.75f);
}

TEST(YardstickMetrics, IdenticalImagesHaveInfinitePsnrAndSsimOne) {
  const Image a =
      makeImage(16, 12, [](int x, int y) { return 0.1 + 0.05 * ((x * 7 + y * 3) % 11); });
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  EXPECT_GT(psnr(a, a), 0.0);
  EXPECT_NEAR(ssim(a, a), 1.0, 1e-6);
}

// A checkerboard of 0.25 / 0.75 shifted by one pixel is its complement: every pixel is off by
// 0.5, so MSE = 0.25 and PSNR = 10 log10(4) = 6.0206 dB.
TEST(YardstickMetrics, OnePixelShiftOfCheckerboard) {
  auto board = [](int shift) {
    return makeImage(32, 32, [shift](int x, int y) { return ((x + shift + y) & 1) ? 0.75 : 0.25; });
  };
  const Image a = board(0), b = board(1);
  EXPECT_NEAR(psnr(a, b), 6.0206, 1e-4);
  // SSIM at an interior pixel, worked by hand: with the 11-tap sigma-1.5 Gaussian, the
  // weights of even and odd offsets are equal to 1e-4, so both local means are 0.5, both
  // variances d^2 = 0.0625 and the covariance -d^2. Then
  // SSIM = (2*0.25 + C1)/(0.5 + C1) * (C2 - 2 d^2)/(C2 + 2 d^2) = (0.0009 - 0.125)/(0.1259).
  const double expected = (0.0009 - 0.125) / (0.0009 + 0.125);
  EXPECT_NEAR(expected, -0.98570, 1e-5);
  const Image map = ssimMap(a, b);
  EXPECT_NEAR(map.at(16, 16)[0], expected, 1e-3);
  EXPECT_NEAR(map.at(10, 20)[0], expected, 1e-3);
}

// A step edge shifted by one pixel: one column of 4 pixels differs by 0.5 of 16 pixels,
// MSE = 4 * 0.25 / 16 = 0.0625, PSNR = 10 log10(16) = 12.0412 dB.
TEST(YardstickMetrics, OnePixelShiftOfStepEdge) {
  const Image a = makeImage(4, 4, [](int x, int) { return x < 2 ? 0.0 : 0.5; });
  const Image b = makeImage(4, 4, [](int x, int) { return x < 1 ? 0.0 : 0.5; });
  EXPECT_NEAR(psnr(a, b), 12.0412, 1e-4);
  EXPECT_LT(ssim(a, b), 1.0);
}

// SSIM of two constant images is the luminance term alone: (2ab + C1) / (a^2 + b^2 + C1).
TEST(YardstickMetrics, SsimOfConstantsIsLuminanceTerm) {
  const Image a = makeImage(8, 8, [](int, int) { return 0.2; });
  const Image b = makeImage(8, 8, [](int, int) { return 0.6; });
  const double c1 = 1e-4;
  EXPECT_NEAR(ssim(a, b), (2 * 0.2 * 0.6 + c1) / (0.04 + 0.36 + c1), 1e-6);
}

TEST(YardstickMetrics, BilinearInterpolatesBetweenCentres) {
  const Image a = makeImage(2, 1, [](int x, int) { return x; });
  EXPECT_FLOAT_EQ(bilinear(a, 0.5, 0.5, 0), 0.0f);
  EXPECT_FLOAT_EQ(bilinear(a, 1.0, 0.5, 0), 0.5f);
  EXPECT_FLOAT_EQ(bilinear(a, 1.5, 0.5, 0), 1.0f);
  EXPECT_FLOAT_EQ(bilinear(a, 9.0, 0.5, 0), 1.0f);  // clamped
}

// Warping a pattern by its own exact motion leaves no change; disoccluded pixels and pixels
// whose previous position is off screen are left out.
TEST(YardstickMetrics, WarpedChangeFollowsFlow) {
  const auto pattern = [](int shift) {
    return makeImage(8, 4, [shift](int x, int y) { return 0.1 * ((x + shift) % 5) + 0.01 * y; });
  };
  const Image before = pattern(1), now = pattern(0);  // content moved one pixel right
  Image flow(8, 4, 2), disocclusion(8, 4, 1);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) flow.at(x, y)[0] = -1.0f;  // previous = current - 1 px
  }
  disocclusion.at(3, 2)[0] = 1.0f;
  const MeanAccumulator change = warpedChange(now, before, flow, disocclusion);
  EXPECT_EQ(change.count, 8 * 4 - 4 - 1);  // column 0 looks off screen; one disoccluded
  // Column 4 of `now` is 0.4 + .., its source column 3 of `before` is (3 + 1) % 5 = 4: same.
  EXPECT_NEAR(change.mean(), 0.0, 1e-7);
}

TEST(YardstickMetrics, DisocclusionAgeFollowsFlowAndExpires) {
  Image flow(4, 1, 2), disocclusion(4, 1, 1);
  for (int x = 0; x < 4; ++x) flow.at(x, 0)[0] = -1.0f;  // moving right one pixel per frame
  DisocclusionAge age;
  disocclusion.at(0, 0)[0] = 1.0f;
  age.advance(disocclusion, flow, true);
  disocclusion.at(0, 0)[0] = 0.0f;
  EXPECT_EQ(age.recent(4).at(0, 0)[0], 1.0f);
  age.advance(disocclusion, flow, false);
  EXPECT_EQ(age.recent(4).at(1, 0)[0], 1.0f);  // the revealed surface moved to x = 1
  EXPECT_EQ(age.recent(4).at(0, 0)[0], 0.0f);  // x = 0 looks off screen: never disoccluded
  age.advance(disocclusion, flow, false);
  age.advance(disocclusion, flow, false);
  EXPECT_EQ(age.recent(4).at(3, 0)[0], 1.0f);  // age 3: still recent
  EXPECT_EQ(age.recent(3).at(3, 0)[0], 0.0f);
}

// The truth's own change is taken out: a sequence equal to the truth has no temporal error
// however much the truth changes; a constant offset has none either (it does not change);
// an offset that alternates sign from frame to frame is counted twice its size.
TEST(YardstickMetrics, TemporalErrorMeasuresChangeBeyondTheTruths) {
  const auto truth = [](int frame) {
    return makeImage(8, 4, [frame](int x, int y) { return 0.05 * ((x + 3 * frame) % 7) + 0.02 * y; });
  };
  Image flow(8, 4, 2), disocclusion(8, 4, 1);
  disocclusion.at(2, 1)[0] = 1.0f;
  const Image truthBefore = truth(0), truthNow = truth(1);
  const MeanAccumulator same = temporalError(truthNow, truthBefore, truthNow, truthBefore, flow,
                                             disocclusion);
  EXPECT_EQ(same.count, 8 * 4 - 1);
  EXPECT_DOUBLE_EQ(same.mean(), 0.0);
  auto offset = [](Image image, float by) {
    for (float& v : image.pixels) v += by;
    return image;
  };
  EXPECT_NEAR(temporalError(offset(truthNow, 0.1f), offset(truthBefore, 0.1f), truthNow,
                            truthBefore, flow, disocclusion).mean(), 0.0, 1e-6);
  EXPECT_NEAR(temporalError(offset(truthNow, 0.1f), offset(truthBefore, -0.1f), truthNow,
                            truthBefore, flow, disocclusion).mean(), 0.2, 1e-6);
}

// The ladder (spp -> PSNR) is read in log2(spp): half way between the 2 and 4 spp rungs is
// 2 * sqrt(2) spp; below the raw input it is "<1" (0), above the last rung +inf.
TEST(YardstickReport, EquivalentSppInterpolatesInLog2) {
  const std::vector<std::pair<int, double>> ladder = {{1, 20.0}, {2, 23.0}, {4, 26.0}};
  EXPECT_DOUBLE_EQ(equivalentSpp(20.0, ladder), 1.0);
  EXPECT_NEAR(equivalentSpp(24.5, ladder), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(equivalentSpp(26.0, ladder), 4.0);
  EXPECT_EQ(equivalentSpp(19.0, ladder), 0.0);
  EXPECT_TRUE(std::isinf(equivalentSpp(27.0, ladder)));
  EXPECT_TRUE(std::isnan(equivalentSpp(25.0, {})));
}

// Sequence ratios: output == truth has flicker 1; output == raw input has ghosting 1.
TEST(YardstickScores, RatiosAreOneForTheirReferences) {
  std::vector<ReferenceFrame> frames;
  for (int f = 1; f <= 6; ++f) {
    ReferenceFrame frame;
    frame.frame = f;
    frame.truth = makeImage(12, 8, [f](int x, int y) { return 0.05 * ((x + y + f) % 7); });
    frame.raw = makeImage(12, 8, [f](int x, int y) { return 0.07 * ((x * y + f) % 5); });
    frame.flow = Image(12, 8, 2);
    frame.disocclusion = Image(12, 8, 1);
    for (int y = 0; y < 8; ++y) frame.disocclusion.at((f * 2) % 12, y)[0] = 1.0f;
    frames.push_back(std::move(frame));
  }
  const Reference reference = prepareReference(frames, ScoreOptions{2, 4});
  EXPECT_EQ(reference.measuredFrames, 4);
  std::vector<Image> truth, raw;
  for (const ReferenceFrame& frame : reference.frames) {
    truth.push_back(frame.truth);
    raw.push_back(frame.raw);
  }
  const Scores ofTruth = score(reference, truth);
  EXPECT_TRUE(std::isinf(ofTruth.psnr));
  EXPECT_NEAR(ofTruth.ssim, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(ofTruth.flicker, 1.0);
  EXPECT_DOUBLE_EQ(ofTruth.temporal, 0.0);
  EXPECT_DOUBLE_EQ(ofTruth.ghosting, 0.0);
  const Scores ofRaw = score(reference, raw);
  EXPECT_DOUBLE_EQ(ofRaw.ghosting, 1.0);
  EXPECT_GT(ofRaw.flicker, 1.0);
  EXPECT_GT(ofRaw.temporal, 0.0);
}

// A new shot restarts the warm-up.
TEST(YardstickScores, WarmupRestartsAtACut) {
  std::vector<ReferenceFrame> frames;
  for (int f = 1; f <= 10; ++f) {
    ReferenceFrame frame;
    frame.frame = f;
    frame.shot = f < 6 ? 0 : 1;
    frame.truth = frame.raw = makeImage(4, 4, [](int, int) { return 0.5; });
    frame.flow = Image(4, 4, 2);
    frame.disocclusion = Image(4, 4, 1);
    frames.push_back(std::move(frame));
  }
  const Reference reference = prepareReference(frames, ScoreOptions{3, 4});
  const std::vector<bool> expected = {false, false, false, true, true,
                                      false, false, false, true, true};
  EXPECT_EQ(reference.measured, expected);
}

}  // namespace
}  // namespace taa::yardstick
