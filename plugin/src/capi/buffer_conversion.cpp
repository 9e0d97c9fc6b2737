#include "capi/buffer_conversion.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "capi/host_enum.h"
#include "capi/status_error.h"
#include "io/aov_conversion.h"
#include "io/frame_reader.h"

namespace taa::capi {
namespace {

[[noreturn]] void invalid(const std::string& what) {
  throw StatusError(TAA_ERROR_INVALID_ARGUMENT, what);
}

// Resolved addressing of one buffer: where pixel (x, y) of the top-first raster lives.
struct Layout {
  char* data = nullptr;
  int width = 0, height = 0, channels = 0;
  bool half = false;
  std::ptrdiff_t rowStride = 0, pixelStride = 0;
  bool yUp = false;

  char* pixel(int x, int topRow) const {
    const int row = yUp ? height - 1 - topRow : topRow;
    return data + row * rowStride + x * pixelStride;
  }
  Imath::half readHalf(const char* pixel, int channel) const {
    std::uint16_t bits;
    std::memcpy(&bits, pixel + channel * 2, 2);
    Imath::half value;
    value.setBits(bits);
    return value;
  }
  float readFloat(const char* pixel, int channel) const {
    float value;
    std::memcpy(&value, pixel + channel * 4, 4);
    return value;
  }
  float read(const char* pixel, int channel) const {
    return half ? float(readHalf(pixel, channel)) : readFloat(pixel, channel);
  }
  // A sample of the buffer's own type T, as stored.
  template <typename T>
  T readStored(const char* pixel, int channel) const {
    if constexpr (std::is_same_v<T, Imath::half>) {
      return readHalf(pixel, channel);
    } else {
      return readFloat(pixel, channel);
    }
  }
  void write(char* pixel, int channel, float value) const {
    if (half) {
      // Beyond half's range the largest finite half, not Inf, as a half read-back from the GPU
      // clamps (glsl/finite_range.glsl); within it Imath rounds to nearest even.
      constexpr float kHalfMax = 65504.0f;
      write(pixel, channel, Imath::half(std::clamp(value, -kHalfMax, kHalfMax)));
    } else {
      std::memcpy(pixel + channel * 4, &value, 4);
    }
  }
  void write(char* pixel, int channel, Imath::half value) const {
    if (half) {
      const std::uint16_t bits = value.bits();
      std::memcpy(pixel + channel * 2, &bits, 2);
    } else {
      write(pixel, channel, float(value));
    }
  }
};

// Checks a buffer's fields; channel counts outside [minChannels, maxChannels] are an error.
Layout describe(const taa_buffer& buffer, const char* what, int minChannels, int maxChannels,
                int expectWidth = 0, int expectHeight = 0) {
  const std::string name = what;
  if (!buffer.data) invalid(name + " buffer has no data (NULL)");
  if (buffer.width <= 0 || buffer.height <= 0) {
    invalid(name + " buffer size must be positive, got " + std::to_string(buffer.width) + "x" +
            std::to_string(buffer.height));
  }
  // Before anything is allocated for it: files are held to the same limit (io/frame_reader.h).
  if (buffer.width > io::kMaxImageSide || buffer.height > io::kMaxImageSide) {
    invalid(name + " buffer is " + std::to_string(buffer.width) + "x" +
            std::to_string(buffer.height) + ": at most " + std::to_string(io::kMaxImageSide) +
            " pixels a side (the GL texture limit taa relies on)");
  }
  if (expectWidth > 0 && (buffer.width != expectWidth || buffer.height != expectHeight)) {
    invalid(name + " is " + std::to_string(buffer.width) + "x" + std::to_string(buffer.height) +
            " but color is " + std::to_string(expectWidth) + "x" + std::to_string(expectHeight));
  }
  if (buffer.channels < minChannels || buffer.channels > maxChannels) {
    const std::string expected = minChannels == maxChannels
                                     ? std::to_string(minChannels)
                                     : std::to_string(minChannels) + " or " +
                                           std::to_string(maxChannels);
    invalid(name + " buffer must have " + expected + " channels, has " +
            std::to_string(buffer.channels));
  }
  const int type = hostEnumValue(buffer.type);
  if (type != TAA_PIXEL_HALF && type != TAA_PIXEL_FLOAT) {
    invalid(name + " buffer has an unknown pixel type " + std::to_string(type));
  }
  Layout layout;
  layout.data = static_cast<char*>(buffer.data);
  layout.width = buffer.width;
  layout.height = buffer.height;
  layout.channels = buffer.channels;
  layout.half = type == TAA_PIXEL_HALF;
  layout.yUp = buffer.y_up != 0;
  const std::ptrdiff_t packedPixel = std::ptrdiff_t(buffer.channels) * (layout.half ? 2 : 4);
  layout.pixelStride = buffer.pixel_stride_bytes == 0 ? packedPixel : buffer.pixel_stride_bytes;
  if (layout.pixelStride < packedPixel) {
    invalid(name + " buffer pixel stride " + std::to_string(buffer.pixel_stride_bytes) +
            " bytes is less than its " + std::to_string(packedPixel) + " bytes of channels");
  }
  const std::ptrdiff_t packedRow = layout.pixelStride * buffer.width;
  layout.rowStride = buffer.row_stride_bytes == 0 ? packedRow : buffer.row_stride_bytes;
  if (std::abs(layout.rowStride) < packedRow) {
    invalid(name + " buffer row stride " + std::to_string(buffer.row_stride_bytes) +
            " bytes is less than a row of " + std::to_string(packedRow) + " bytes");
  }
  return layout;
}

Image readChannels(const Layout& layout) {
  Image image(layout.width, layout.height, layout.channels);
  float* out = image.pixels.data();
  for (int y = 0; y < layout.height; ++y) {
    for (int x = 0; x < layout.width; ++x) {
      const char* pixel = layout.pixel(x, y);
      for (int c = 0; c < layout.channels; ++c) *out++ = layout.read(pixel, c);
    }
  }
  return image;
}

bool isFinite(float value) { return std::isfinite(value); }
bool isFinite(Imath::half value) { return value.isFinite(); }

// RGBA of the buffer's own sample type T; NaN/Inf scrubbed to 0 and counted in `scrubbed`.
template <typename T>
ImageOf<T> readRgba(const Layout& layout, int& scrubbed) {
  ImageOf<T> rgba(layout.width, layout.height, 4);
  T* out = rgba.pixels.data();
  for (int y = 0; y < layout.height; ++y) {
    for (int x = 0; x < layout.width; ++x, out += 4) {
      const char* pixel = layout.pixel(x, y);
      out[3] = T(1.0f);  // a color without alpha is opaque, as io::readFrame reads it
      for (int c = 0; c < layout.channels; ++c) {
        const T value = layout.readStored<T>(pixel, c);
        if (isFinite(value)) {
          out[c] = value;
        } else {
          out[c] = T(0.0f);
          ++scrubbed;
        }
      }
    }
  }
  return rgba;
}

template <typename T>
void writeRgba(const ImageOf<T>& image, const Layout& layout) {
  for (int y = 0; y < layout.height; ++y) {
    for (int x = 0; x < layout.width; ++x) {
      const T* in = image.at(x, y);
      char* pixel = layout.pixel(x, y);
      for (int c = 0; c < layout.channels; ++c) layout.write(pixel, c, in[c]);
    }
  }
}

}  // namespace

TypedImage importColor(const taa_buffer& buffer, int* nonFinite) {
  const Layout layout = describe(buffer, "color", 3, 4);
  int scrubbed = 0;
  TypedImage rgba = layout.half ? TypedImage(readRgba<Imath::half>(layout, scrubbed))
                                : TypedImage(readRgba<float>(layout, scrubbed));
  if (nonFinite) *nonFinite = scrubbed;
  return rgba;
}

Image importDepth(const taa_buffer& buffer, const io::DepthConvention& convention,
                  int expectWidth, int expectHeight, const io::PixelRay* ray) {
  Image depth = readChannels(describe(buffer, "depth", 1, 1, expectWidth, expectHeight));
  if (convention.kind == io::DepthKind::Radial) {
    if (!ray) {
      invalid("radial depth needs the pixel rays: the frame's camera (world_to_camera and "
              "world_to_ndc, or the camera-sidecar parameter) or the depth-fov parameter");
    }
    io::radialToPlanar(depth, *ray, convention.noHitAbove);  // as io::readFrame does
    return depth;
  }
  io::convertDepth(depth, convention);  // the same code io::readFrame runs on files
  return depth;
}

Image importMotion(const taa_buffer& buffer, const io::MotionConvention& convention,
                   int expectWidth, int expectHeight) {
  Image motion = readChannels(describe(buffer, "motion", 2, 2, expectWidth, expectHeight));
  RasterWindow window;  // the buffer is the whole display window
  window.displayWidth = motion.width;
  window.displayHeight = motion.height;
  io::convertMotion(motion, convention, window);  // the same code io::readFrame runs on files
  return motion;
}

void exportColor(const TypedImage& image, const taa_buffer& buffer) {
  const Layout layout = describe(buffer, "output", 3, 4, image.width(), image.height());
  if (const HalfImage* halves = image.halves()) {
    writeRgba(*halves, layout);
  } else {
    writeRgba(*image.floats(), layout);
  }
}

namespace {

// The layout of a pass channel's buffer, checked: the channel must be one it has.
Layout passLayout(const PassChannel& pass, const std::string& what, int width, int height) {
  const std::string name = what + " \"" + pass.name + "\"";
  constexpr int kMaxChannels = 1 << 16;
  const Layout layout = describe(*pass.buffer, name.c_str(), 1, kMaxChannels, width, height);
  if (pass.channel < 0 || pass.channel >= layout.channels) {
    invalid(name + " asks for channel " + std::to_string(pass.channel) + " of a buffer of " +
            std::to_string(layout.channels) + " channels");
  }
  return layout;
}

}  // namespace

Image importPasses(const std::vector<PassChannel>& channels, int width, int height,
                   std::vector<OIIO::TypeDesc>& types) {
  Image image(width, height, int(channels.size()));
  types.clear();
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const Layout layout = passLayout(channels[c], "pass", width, height);
    types.push_back(layout.half ? OIIO::TypeHalf : OIIO::TypeFloat);
    float* out = &image.pixels[c];
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x, out += channels.size()) {
        *out = layout.read(layout.pixel(x, y), channels[c].channel);
      }
    }
  }
  return image;
}

void exportPasses(const Image& image, const std::vector<int>& sources,
                  const std::vector<PassChannel>& channels) {
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const Layout layout = passLayout(channels[c], "output pass", image.width, image.height);
    const std::size_t stride = std::size_t(image.channels);
    const float* in = &image.pixels[std::size_t(sources[c])];
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x, in += stride) {
        layout.write(layout.pixel(x, y), channels[c].channel, *in);
      }
    }
  }
}

}  // namespace taa::capi
