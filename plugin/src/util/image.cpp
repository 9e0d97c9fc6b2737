#include "util/image.h"

#include <algorithm>

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
  // Imath's exact widening (the OpenFX bundle links no OpenImageIO: this was its one call).
  std::transform(half.pixels.begin(), half.pixels.end(), image.pixels.begin(),
                 [](Imath::half h) { return float(h); });
  return image;
}

}  // namespace taa
