// A plain float image in taa's raster convention: row 0 is the top row, channels interleaved.
#pragma once

#include <cstddef>
#include <vector>

namespace taa {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;  // width * height * channels, rows top first

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c) {}

  bool empty() const { return pixels.empty(); }
  float* at(int x, int y) { return &pixels[(std::size_t(y) * width + x) * channels]; }
  const float* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * channels]; }
};

}  // namespace taa
