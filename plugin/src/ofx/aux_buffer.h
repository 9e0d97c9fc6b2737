// Depth or motion as the node needs them: one or two channels over the source image's bounds.
// The host's images may be larger (overscan AOVs), smaller or offset (multi-resolution hosts):
// where an image covers the source bounds the buffer is a view of the host's memory at the
// source's pixels (exactly what taatool reads from files cropped to the colour's window),
// otherwise a copy with the pixels it lacks filled (depth: no hit; motion: none).
#pragma once

#include <vector>

#include "ofx/clip_image.h"
#include "taa/taa.h"

namespace taa::ofx {

class AuxBuffer {
 public:
  // `channels` channels of `image` from `firstChannel`, over `target` (the source's bounds).
  // `fill` goes where the image has no pixels; channel 1 is multiplied by `channel1Scale`
  // (motion y when the render scale differs in x and y), which forces a copy unless it is 1.
  AuxBuffer(const ClipImage& image, int firstChannel, int channels, const OfxRectI& target,
            float fill, float channel1Scale = 1.0f);

  const taa_buffer& buffer() const { return buffer_; }
  bool isCopy() const { return !copy_.empty(); }

 private:
  std::vector<float> copy_;
  taa_buffer buffer_{};
};

// Which channel of the host's depth image holds depth: the only one of an Alpha image; A of an
// RGBA image the host made from an Alpha clip (`unmapped` says what is connected, a host maps
// Alpha to RGBA with the value in A); R otherwise.
int depthChannel(const ClipImage& image, const std::string& unmapped);

}  // namespace taa::ofx
