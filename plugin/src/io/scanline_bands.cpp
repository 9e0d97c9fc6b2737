#include "io/scanline_bands.h"

#include <string>

namespace taa::io {

int rowsPerBand(const OIIO::ImageSpec& spec) {
  constexpr int kRows = 32;
  if (spec.tile_height > 0) {
    return (kRows + spec.tile_height - 1) / spec.tile_height * spec.tile_height;
  }
  const std::string compression = spec.get_string_attribute("compression");
  return compression.rfind("dwab", 0) == 0 ? 256 : kRows;
}

}  // namespace taa::io
