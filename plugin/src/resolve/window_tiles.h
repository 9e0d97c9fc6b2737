// The window's tile test (--window-near, issue 23): the nearest frame each side always counts,
// the others within `near` unless a fifth of the tile's pixels rejected them (a light moving
// every frame); each side of a tile's window reaches on, frame by frame, while the farther
// frame's samples agree with t's own over the tile: few of its pixels' colour tests rejected
// them, and the mean of their differences (one per sampled pixel) is within its standard error
// of zero (plus a small tolerance). Where the shading holds still (a static shot, a dolly) a
// tile gets the long window; where it changes (a shadow sweeping, a light turning) the near
// one. Pooled over a tile, a shift too small for one pixel's noisy test shows (the per-pixel
// colour test and --window-adaptive decide per pixel).
#pragma once

#include <cstdint>
#include <vector>

namespace taa {

// The gather's tile-test output (glsl/window_gather.frag, TILE_STATS), per sampled pixel and
// source: 0 where the source gave no samples, else 64 + 256 x (the luma of its samples' mean
// minus t's own), clamped to 1..127, plus 128 where the colour test found them disagreeing.
inline constexpr int kNoSamples = 0;
inline constexpr int kDisagreeing = 128;
inline constexpr double kDifferenceScale = 256.0;

struct TileReach {
  int columns = 0, rows = 0;
  std::vector<float> frames;  // per tile, row-major: reach behind, reach ahead (in frames)
};

// `codes`: statsWidth x statsHeight sampled pixels of `offsets.size()` codes each, `perTile`
// pixels each way to a tile; `offsets`: each source's distance from t in frames (negative
// behind), nearest first as the gather orders them.
TileReach decideTileReach(const std::vector<std::uint8_t>& codes, int statsWidth,
                          int statsHeight, int perTile, const std::vector<int>& offsets,
                          int near);

}  // namespace taa
