#include "ofx/aux_buffer.h"

#include <algorithm>
#include <cstring>

namespace taa::ofx {
namespace {

bool covers(const OfxRectI& outer, const OfxRectI& inner) {
  return outer.x1 <= inner.x1 && outer.y1 <= inner.y1 && outer.x2 >= inner.x2 &&
         outer.y2 >= inner.y2;
}

}  // namespace

AuxBuffer::AuxBuffer(const ClipImage& image, int firstChannel, int channels,
                     const OfxRectI& target, float fill, float channel1Scale) {
  const int width = target.x2 - target.x1, height = target.y2 - target.y1;
  if (covers(image.bounds(), target) && channel1Scale == 1.0f) {
    buffer_ = image.buffer(firstChannel, channels);
    buffer_.data = image.pixelAddress(target.x1, target.y1) + firstChannel * (image.isHalf() ? 2 : 4);
    buffer_.width = width;
    buffer_.height = height;
    return;
  }
  // y-up like the host's images: row 0 is target.y1.
  copy_.assign(std::size_t(width) * height * channels, fill);
  const OfxRectI& b = image.bounds();
  for (int y = std::max(target.y1, b.y1); y < std::min(target.y2, b.y2); ++y) {
    for (int x = std::max(target.x1, b.x1); x < std::min(target.x2, b.x2); ++x) {
      float* out = &copy_[(std::size_t(y - target.y1) * width + (x - target.x1)) * channels];
      for (int c = 0; c < channels; ++c) {
        out[c] = image.value(x, y, firstChannel + c) * (c == 1 ? channel1Scale : 1.0f);
      }
    }
  }
  std::memset(&buffer_, 0, sizeof buffer_);
  buffer_.data = copy_.data();
  buffer_.width = width;
  buffer_.height = height;
  buffer_.channels = channels;
  buffer_.type = TAA_PIXEL_FLOAT;
  buffer_.y_up = 1;
}

int depthChannel(const ClipImage& image, const std::string& unmapped) {
  if (image.components() == 1) return 0;
  if (image.components() == 4 && unmapped == kOfxImageComponentAlpha) return 3;
  return 0;
}

}  // namespace taa::ofx
