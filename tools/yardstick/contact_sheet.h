// Contact sheets: one frame of a scene as every row of the table saw it, side by side, with an
// error heat map, as a PNG linked from docs/QUALITY.md. People judge TAA by eye first.
#pragma once

#include <string>
#include <vector>

#include "util/image.h"

namespace taa::yardstick {

struct SheetTile {
  std::string label;
  Image image;  // tonemapped x / (1 + x) RGB (metrics.h: tonemap), the whole frame
};

// A rectangle of the frame shown in every tile.
struct Crop {
  int x = 0, y = 0, width = 0, height = 0;
};

// The width x height window (clamped to the image) where the mean RGB |a - b| is largest:
// where aliasing is worst, so the sheet shows what the resolve has to fix.
Crop worstWindow(const Image& a, const Image& b, int width, int height);

// |a - truth| (RGB mean) as an "inferno" heat map, `fullScale` mapping to the top colour;
// tonemapped like the tiles (so a tile of SheetTile's kind).
Image errorHeatMap(const Image& a, const Image& truth, float fullScale);

// Writes the tiles, each cropped to `crop`, into a grid `columns` wide with a label strip
// above each (DejaVu Sans via OpenImageIO's text rendering; without the font the labels are
// left out and a warning returned). Tiles are shown as sRGB of the linear values (clamped to
// 1), pixel for pixel. Throws taa::Error when the PNG cannot be written. Returns "" or a
// warning.
std::string writeContactSheet(const std::string& path, const std::vector<SheetTile>& tiles,
                              const Crop& crop, int columns);

}  // namespace taa::yardstick
