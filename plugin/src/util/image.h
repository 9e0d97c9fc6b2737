// Images in taa's raster convention: row 0 is the top row, channels interleaved.
// Image (float) serves depth, motion, masks and the host buffers; TypedImage keeps colour in the
// type the file stored it in, so half colour goes from the file to the GPU and back to the file
// without being widened and narrowed on the way (reading half as float alone costs about 30%
// more CPU; docs/PERFORMANCE.md).
#pragma once

#include <Imath/half.h>

#include <cstddef>
#include <utility>
#include <variant>
#include <vector>

#include "util/frame_buffer_pool.h"

namespace taa {

// The types an image's samples can have. Half is IEEE binary16 (Imath::half, OIIO's TypeHalf).
enum class SampleType { Half, Float };

template <typename T>
struct ImageOf {
  int width = 0;
  int height = 0;
  int channels = 0;
  FrameVector<T> pixels;  // width * height * channels, rows top first

  ImageOf() = default;
  ImageOf(int w, int h, int c) : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c) {}

  bool empty() const { return pixels.empty(); }
  T* at(int x, int y) { return &pixels[(std::size_t(y) * width + x) * channels]; }
  const T* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * channels]; }
};

using Image = ImageOf<float>;
using HalfImage = ImageOf<Imath::half>;

// An image that is either half or float, decided at run time (by the file it came from, or the
// type an output is written as).
class TypedImage {
 public:
  TypedImage() = default;
  TypedImage(Image image) : image_(std::move(image)) {}
  TypedImage(HalfImage image) : image_(std::move(image)) {}
  TypedImage(int width, int height, int channels, SampleType type);

  SampleType type() const { return image_.index() == 0 ? SampleType::Float : SampleType::Half; }
  int width() const;
  int height() const;
  int channels() const;
  bool empty() const;
  const void* data() const;
  void* data();

  // The image when it has that type, else nullptr.
  const Image* floats() const { return std::get_if<Image>(&image_); }
  Image* floats() { return std::get_if<Image>(&image_); }
  const HalfImage* halves() const { return std::get_if<HalfImage>(&image_); }
  HalfImage* halves() { return std::get_if<HalfImage>(&image_); }

  // A float copy (half widens exactly).
  Image toFloat() const;

 private:
  std::variant<Image, HalfImage> image_;
};

// A non-owning view of a float, half or typed image, for functions that take either.
// Converts implicitly from a pointer to any of them; nullptr (or an empty image) is "none".
struct ImageView {
  const void* data = nullptr;
  SampleType type = SampleType::Float;
  int width = 0, height = 0, channels = 0;

  ImageView() = default;
  ImageView(std::nullptr_t) {}
  ImageView(const Image* image) { if (image) *this = view(*image, SampleType::Float); }
  ImageView(const HalfImage* image) { if (image) *this = view(*image, SampleType::Half); }
  ImageView(const TypedImage* image) {
    if (image && !image->empty()) {
      *this = {image->data(), image->type(), image->width(), image->height(), image->channels()};
    }
  }
  ImageView(const void* d, SampleType t, int w, int h, int c)
      : data(d), type(t), width(w), height(h), channels(c) {}

  explicit operator bool() const { return data != nullptr; }

 private:
  template <typename T>
  static ImageView view(const ImageOf<T>& image, SampleType t) {
    if (image.empty()) return {};
    return {image.pixels.data(), t, image.width, image.height, image.channels};
  }
};

}  // namespace taa
