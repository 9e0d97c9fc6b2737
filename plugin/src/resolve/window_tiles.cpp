#include "resolve/window_tiles.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace taa {
namespace {

// A far frame ends the tile's window when more than this share of the pixels it reached found
// its samples disagreeing (the gather's colour test: a shadow's edge sweeping through part of
// the tile), or when the mean of its differences strays from zero by more than this many
// standard errors plus this much luma (decisionLuma's scale: shading that shifted as a whole,
// by less than one pixel's test can tell). Chosen on the real-render yardstick
// (docs/TUNING.md, "The tile test").
constexpr double kDisagreeingShare = 0.05;
constexpr double kStandardErrors = 3.0;
constexpr double kTolerance = 0.002;
// A frame within `near` but the nearest ends the window only where more than this share of the
// pixels rejected it: a light that moves every frame (docs/TUNING.md, "The near frames").
constexpr double kNearDisagreeingShare = 0.2;
// A frame that reached fewer than this share of a tile's pixels says too little to end it.
constexpr double kTooFew = 0.25;

struct Moments {
  int count = 0, disagreeing = 0;
  double sum = 0.0, squares = 0.0;
};

}  // namespace

TileReach decideTileReach(const std::vector<std::uint8_t>& codes, int statsWidth,
                          int statsHeight, int perTile, const std::vector<int>& offsets,
                          int near) {
  TileReach reach;
  reach.columns = (statsWidth + perTile - 1) / perTile;
  reach.rows = (statsHeight + perTile - 1) / perTile;
  // The nearest frame each side always counts.
  const int always = std::min(near, 1);
  reach.frames.assign(std::size_t(2) * reach.columns * reach.rows, float(always));
  const std::size_t count = offsets.size();
  std::vector<Moments> moments(count);
  for (int row = 0; row < reach.rows; ++row) {
    for (int column = 0; column < reach.columns; ++column) {
      std::fill(moments.begin(), moments.end(), Moments{});
      int pixels = 0;
      for (int y = row * perTile; y < std::min(statsHeight, (row + 1) * perTile); ++y) {
        for (int x = column * perTile; x < std::min(statsWidth, (column + 1) * perTile); ++x) {
          const std::uint8_t* pixel = &codes[(std::size_t(y) * statsWidth + x) * count];
          ++pixels;
          for (std::size_t k = 0; k < count; ++k) {
            if (pixel[k] == kNoSamples) continue;
            const double difference = (double(pixel[k] & 127) - 64.0) / kDifferenceScale;
            Moments& m = moments[k];
            ++m.count;
            m.disagreeing += (pixel[k] & kDisagreeing) ? 1 : 0;
            m.sum += difference;
            m.squares += difference * difference;
          }
        }
      }
      // Sources come nearest first: each side walks outward and stops at its first frame
      // that disagrees.
      float* tileReach = &reach.frames[2 * (std::size_t(row) * reach.columns + column)];
      bool open[2] = {true, true};  // behind, ahead
      for (std::size_t k = 0; k < count; ++k) {
        const int offset = offsets[k];
        const int distance = std::abs(offset);
        if (distance <= always) continue;
        const int side = offset < 0 ? 0 : 1;
        const Moments& m = moments[k];
        bool agrees = m.count < kTooFew * pixels;
        if (!agrees && distance <= near) {
          agrees = m.disagreeing <= kNearDisagreeingShare * m.count;
        } else if (!agrees) {
          const double mean = m.sum / m.count;
          const double variance = std::max(m.squares / m.count - mean * mean, 0.0);
          const double standardError = std::sqrt(variance / m.count);
          agrees = m.disagreeing <= kDisagreeingShare * m.count &&
                   std::abs(mean) <= kStandardErrors * standardError + kTolerance;
        }
        open[side] = open[side] && agrees;
        if (open[side]) tileReach[side] = float(distance);
      }
    }
  }
  return reach;
}

}  // namespace taa
