#include "yardstick/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

constexpr int kLabelHeight = 14;
constexpr int kGap = 2;
constexpr const char* kFont = "DejaVuSans";

// Tonemapped x / (1 + x) back to linear, clamped to [0, 1], then the sRGB transfer curve.
float displayValue(float tonemapped) {
  const float t = std::clamp(tonemapped, 0.0f, 0.999999f);
  const float linear = std::min(1.0f, t / (1.0f - t));
  return linear <= 0.0031308f ? 12.92f * linear
                              : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

double windowSum(const std::vector<double>& integral, int stride, int x, int y, int w, int h) {
  auto at = [&](int xx, int yy) { return integral[std::size_t(yy) * stride + xx]; };
  return at(x + w, y + h) - at(x, y + h) - at(x + w, y) + at(x, y);
}

}  // namespace

Crop worstWindow(const Image& a, const Image& b, int width, int height) {
  width = std::min(width, a.width);
  height = std::min(height, a.height);
  const int stride = a.width + 1;
  std::vector<double> integral(std::size_t(stride) * (a.height + 1), 0.0);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      double error = 0.0;
      for (int c = 0; c < 3; ++c) error += std::fabs(double(a.at(x, y)[c]) - b.at(x, y)[c]);
      integral[std::size_t(y + 1) * stride + x + 1] = error +
                                                      integral[std::size_t(y) * stride + x + 1] +
                                                      integral[std::size_t(y + 1) * stride + x] -
                                                      integral[std::size_t(y) * stride + x];
    }
  }
  Crop best{0, 0, width, height};
  double bestSum = -1.0;
  // Steps of 4 px: the window's place need not be exact, only telling.
  for (int y = 0; y + height <= a.height; y += 4) {
    for (int x = 0; x + width <= a.width; x += 4) {
      const double sum = windowSum(integral, stride, x, y, width, height);
      if (sum > bestSum) {
        bestSum = sum;
        best = {x, y, width, height};
      }
    }
  }
  return best;
}

Image errorHeatMap(const Image& a, const Image& truth, float fullScale) {
  OIIO::ImageBuf error(OIIO::ImageSpec(a.width, a.height, 1, OIIO::TypeDesc::FLOAT));
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      float sum = 0.0f;
      for (int c = 0; c < 3; ++c) sum += std::fabs(a.at(x, y)[c] - truth.at(x, y)[c]);
      const float value = std::min(1.0f, sum / 3.0f / fullScale);
      error.setpixel(x, y, &value);
    }
  }
  const OIIO::ImageBuf colours = OIIO::ImageBufAlgo::color_map(error, 0, "inferno");
  Image map(a.width, a.height, 3);
  colours.get_pixels(OIIO::ROI(0, a.width, 0, a.height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT,
                     map.pixels.data());
  // The tiles are tonemapped; store the map's display colours in that form (x / (1 + x) of
  // the linear value whose sRGB encoding they are).
  for (float& v : map.pixels) {
    const float linear = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    v = linear / (1.0f + linear);
  }
  return map;
}

std::string writeContactSheet(const std::string& path, const std::vector<SheetTile>& tiles,
                              const Crop& crop, int columns) {
  if (tiles.empty() || columns < 1) throw Error("contact sheet: no tiles", {path});
  const int rows = (int(tiles.size()) + columns - 1) / columns;
  const int cellW = crop.width + kGap, cellH = crop.height + kLabelHeight + kGap;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(columns * cellW, rows * cellH, 3, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::fill(sheet, {0.12f, 0.12f, 0.12f});
  std::string warning;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Image& image = tiles[k].image;
    const int left = int(k % columns) * cellW, top = int(k / columns) * cellH;
    for (int y = 0; y < crop.height; ++y) {
      for (int x = 0; x < crop.width; ++x) {
        const float* p = image.at(std::min(crop.x + x, image.width - 1),
                                  std::min(crop.y + y, image.height - 1));
        const float rgb[3] = {displayValue(p[0]), displayValue(p[1]), displayValue(p[2])};
        sheet.setpixel(left + x, top + kLabelHeight + y, rgb);
      }
    }
    const float white[3] = {1.0f, 1.0f, 1.0f};
    if (warning.empty() &&
        !OIIO::ImageBufAlgo::render_text(sheet, left + 2, top + kLabelHeight - 3,
                                         tiles[k].label, 11, kFont, white)) {
      warning = "contact sheet without labels (font " + std::string(kFont) +
                " not found: install fonts-dejavu-core): " + path;
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (!sheet.write(path)) throw Error("cannot write contact sheet: " + sheet.geterror(), {path});
  return warning;
}

}  // namespace taa::yardstick
