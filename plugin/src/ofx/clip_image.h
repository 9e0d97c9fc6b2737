// One image fetched from a clip, released on destruction, and described as taa_buffers. OFX
// images are y-up: row 0 of the data is the bottom row (bounds.y1), rows rowBytes apart.
#pragma once

#include <string>

#include "ofx/ofx_abi.h"
#include "taa/taa.h"

namespace taa::ofx {

class ClipImage {
 public:
  // Fetches the clip's image at `time`; throws std::runtime_error naming `clipName` when the
  // host has none, or its pixel depth is not half or float.
  ClipImage(OfxImageClipHandle clip, OfxTime time, const std::string& clipName);
  ~ClipImage();
  ClipImage(const ClipImage&) = delete;
  ClipImage& operator=(const ClipImage&) = delete;

  const OfxRectI& bounds() const { return bounds_; }
  int components() const { return components_; }  // 1 (Alpha), 3 (RGB) or 4 (RGBA)
  bool isHalf() const { return half_; }
  double pixelAspectRatio() const { return pixelAspectRatio_; }
  const std::string& where() const { return where_; }  // "<clip> clip at frame <t>"
  char* pixelAddress(int x, int y) const;  // (x, y) in the image's pixel coordinates

  // `channels` channels starting at `firstChannel` of every pixel, as a y-up buffer.
  taa_buffer buffer(int firstChannel, int channels) const;

  // Channel c of pixel (x, y) as a float.
  float value(int x, int y, int c) const;

 private:
  OfxPropertySetHandle image_ = nullptr;
  char* data_ = nullptr;
  OfxRectI bounds_{};
  int rowBytes_ = 0;
  int components_ = 0;
  bool half_ = false;
  double pixelAspectRatio_ = 1.0;
  std::string where_;
};

// Whether an optional clip is connected to anything.
bool isConnected(OfxImageClipHandle clip);

// The components of what is connected to the clip before the host maps them
// (kOfxImageClipPropUnmappedComponents); "" when the host does not say.
std::string unmappedComponents(OfxImageClipHandle clip);

// A clip's frame range (kOfxImageEffectPropFrameRange), or [fallback, fallback] when the host
// does not say.
OfxRangeD clipFrameRange(OfxImageClipHandle clip, double fallback);

}  // namespace taa::ofx
