#include "util/image.h"

#include <OpenImageIO/imageio.h>

namespace taa {
TypedImage::TypedImage(int width, int height, int channels, SampleType type) {
  if (type == SampleType::Half) {
    image_ = HalfImage(width, height, channels);
  } else {
    image_ = Image(width, height, channels);
  }
}

int TypedImage::width() const {
  return std::visit([](const auto& image) { return image.width; }, image_);
}
int TypedImage::height() const {
  return std::visit([](const auto& image) { return image.height; }, image_);
}
int TypedImage::channels() const {
  return std::visit([](const auto& image) { return image.channels; }, image_);
}
bool TypedImage::empty() const {
  return std::visit([](const auto& image) { return image.empty(); }, image_);
}
const void* TypedImage::data() const {
  return std::visit([](const auto& image) -> const void* { return image.pixels.data(); }, image_);
}
void* TypedImage::data() {
  return std::visit([](auto& image) -> void* { return image.pixels.data(); }, image_);
}

Image TypedImage::toFloat() const {
  if (const Image* image = floats()) return *image;
  const HalfImage& half = *halves();
  Image image(half.width, half.height, half.channels);
  // OIIO's converter: libImath's half tables are not a dependency of taa_core.
  OIIO::convert_pixel_values(OIIO::TypeHalf, half.pixels.data(), OIIO::TypeFloat,
                             image.pixels.data(), int(half.pixels.size()));
  return image;
}

}  // namespace taa
