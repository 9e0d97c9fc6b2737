// The window's tile test: how far each side of a tile's window reaches.
#include "resolve/window_tiles.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace taa {
namespace {

// Sources as the gather orders them for a window of 3 each side: t-1, t+1, t-2, t+2, t-3, t+3.
const std::vector<int> kOffsets = {-1, 1, -2, 2, -3, 3};
constexpr int kPerTile = 8;

std::uint8_t code(double difference) {
  return std::uint8_t(64.0 + difference * kDifferenceScale);
}

// Two tiles side by side, 8x8 sampled pixels each; every source's difference is sampling noise
// (+-0.02, alternating, mean 0) unless, in tile `tile`, source `source` is shifted by `shift`,
// reached only `reachedPixels` pixels and was found disagreeing in `disagreeingPixels`.
std::vector<std::uint8_t> codes(int tile, int source, double shift, int reachedPixels = 64,
                                int disagreeingPixels = 0) {
  const int width = 2 * kPerTile, height = kPerTile, count = int(kOffsets.size());
  std::vector<std::uint8_t> out(std::size_t(width) * height * count);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double noise = (x + y) % 2 ? 0.02 : -0.02;
      for (int k = 0; k < count; ++k) {
        const bool here = x / kPerTile == tile && k == source;
        const int index = y * kPerTile + x % kPerTile;
        std::uint8_t& c = out[(std::size_t(y) * width + x) * count + std::size_t(k)];
        c = code(noise + (here ? shift : 0.0));
        if (here && index < disagreeingPixels) c |= kDisagreeing;
        if (here && index >= reachedPixels) c = kNoSamples;
      }
    }
  }
  return out;
}

TEST(WindowTiles, FramesThatAgreeExtendTheWindowToItsEnd) {
  const TileReach reach = decideTileReach(codes(0, 0, 0.0), 16, 8, kPerTile, kOffsets, 1);
  ASSERT_EQ(reach.columns, 2);
  ASSERT_EQ(reach.rows, 1);
  EXPECT_EQ(reach.frames, (std::vector<float>{3, 3, 3, 3}));
}

TEST(WindowTiles, ASideEndsBeforeItsFirstFrameWhoseShadingShifted) {
  // t-2 is brighter by 0.03 in the first tile: that tile reaches t-1 behind (the near frame
  // always counts) and the whole window ahead; the second tile is untouched.
  const TileReach reach = decideTileReach(codes(0, 2, 0.03), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(reach.frames, (std::vector<float>{1, 3, 3, 3}));
  // A shift ahead at t+3 ends that side at t+2.
  const TileReach ahead = decideTileReach(codes(1, 5, -0.03), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(ahead.frames, (std::vector<float>{3, 3, 3, 2}));
}

TEST(WindowTiles, TheNearestFramesCountWhateverTheyShow) {
  const TileReach reach = decideTileReach(codes(0, 1, 0.1), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(reach.frames, (std::vector<float>{3, 3, 3, 3}));
}

TEST(WindowTiles, FramesWithinNearButTheNearestEndTheWindowWhereAFifthRejectedThem) {
  // near 2: t-2 counts with 12 of 64 pixels rejecting it (19%) whatever its mean, and ends the
  // window behind at t-1 with 14 (22%; a light moving every frame); t-1 always counts.
  const TileReach some = decideTileReach(codes(0, 2, 0.1, 64, 12), 16, 8, kPerTile, kOffsets, 2);
  EXPECT_EQ(some.frames, (std::vector<float>{3, 3, 3, 3}));
  const TileReach more = decideTileReach(codes(0, 2, 0.0, 64, 14), 16, 8, kPerTile, kOffsets, 2);
  EXPECT_EQ(more.frames, (std::vector<float>{1, 3, 3, 3}));
  const TileReach nearest =
      decideTileReach(codes(0, 0, 0.0, 64, 64), 16, 8, kPerTile, kOffsets, 2);
  EXPECT_EQ(nearest.frames, (std::vector<float>{3, 3, 3, 3}));
}

TEST(WindowTiles, AFrameThatReachedFewPixelsDoesNotEndTheWindow) {
  // Shifted, but seen by 8 of the tile's 64 pixels (the rest off screen or hidden).
  const TileReach few = decideTileReach(codes(0, 2, 0.03, 8), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(few.frames, (std::vector<float>{3, 3, 3, 3}));
  const TileReach many = decideTileReach(codes(0, 2, 0.03, 40), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(many.frames, (std::vector<float>{1, 3, 3, 3}));
}

TEST(WindowTiles, ASideEndsWhereTheColourTestRejectedMoreThanOnePixelInTwenty) {
  // A shadow's edge sweeping through part of the tile: the pixels' own test finds it, the
  // tile's mean hardly moves. 3 of 64 pixels (4.7%) leave the window whole, 4 (6.3%) end it.
  const TileReach three = decideTileReach(codes(0, 4, 0.0, 64, 3), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(three.frames, (std::vector<float>{3, 3, 3, 3}));
  const TileReach four = decideTileReach(codes(0, 4, 0.0, 64, 4), 16, 8, kPerTile, kOffsets, 1);
  EXPECT_EQ(four.frames, (std::vector<float>{2, 3, 3, 3}));
}

}  // namespace
}  // namespace taa
