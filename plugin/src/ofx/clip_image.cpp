#include "ofx/clip_image.h"

#include <Imath/half.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "ofx/host_suites.h"

namespace taa::ofx {

namespace {

std::string frameText(OfxTime time) {
  const double rounded = std::round(time);
  return rounded == time ? std::to_string(std::lround(time)) : std::to_string(time);
}

}  // namespace

ClipImage::ClipImage(OfxImageClipHandle clip, OfxTime time, const std::string& clipName) {
  const HostSuites& s = suites();
  where_ = clipName + " clip at frame " + frameText(time);
  const std::string& where = where_;
  if (s.effects->clipGetImage(clip, time, nullptr, &image_) != kOfxStatOK || !image_) {
    image_ = nullptr;
    throw std::runtime_error("the host gave no image for the " + where);
  }
  void* data = nullptr;
  char* depth = nullptr;
  char* components = nullptr;
  s.properties->propGetPointer(image_, kOfxImagePropData, 0, &data);
  s.properties->propGetIntN(image_, kOfxImagePropBounds, 4, &bounds_.x1);
  s.properties->propGetInt(image_, kOfxImagePropRowBytes, 0, &rowBytes_);
  s.properties->propGetString(image_, kOfxImageEffectPropPixelDepth, 0, &depth);
  s.properties->propGetString(image_, kOfxImageEffectPropComponents, 0, &components);
  if (s.properties->propGetDouble(image_, kOfxImagePropPixelAspectRatio, 0,
                                  &pixelAspectRatio_) != kOfxStatOK) {
    pixelAspectRatio_ = 1.0;  // hosts that never leave square pixels may not say
  }
  data_ = static_cast<char*>(data);
  const std::string depthName = depth ? depth : "";
  const std::string componentName = components ? components : "";
  if (depthName == kOfxBitDepthHalf) {
    half_ = true;
  } else if (depthName != kOfxBitDepthFloat) {
    suites().effects->clipReleaseImage(image_);
    throw std::runtime_error("unsupported pixel depth \"" + depthName + "\" on the " + where +
                             " (half or float only)");
  }
  components_ = componentName == kOfxImageComponentRGBA  ? 4
                : componentName == kOfxImageComponentRGB ? 3
                : componentName == kOfxImageComponentAlpha ? 1
                                                           : 0;
  if (!data_ || components_ == 0 || bounds_.x2 <= bounds_.x1 || bounds_.y2 <= bounds_.y1) {
    suites().effects->clipReleaseImage(image_);
    throw std::runtime_error("malformed image (components \"" + componentName +
                             "\", no data or empty bounds) on the " + where);
  }
}

ClipImage::~ClipImage() {
  if (image_) suites().effects->clipReleaseImage(image_);
}

char* ClipImage::pixelAddress(int x, int y) const {
  const int bytes = components_ * (half_ ? 2 : 4);
  return data_ + std::ptrdiff_t(y - bounds_.y1) * rowBytes_ + std::ptrdiff_t(x - bounds_.x1) * bytes;
}

taa_buffer ClipImage::buffer(int firstChannel, int channels) const {
  taa_buffer b;
  std::memset(&b, 0, sizeof b);
  const int channelBytes = half_ ? 2 : 4;
  b.data = data_ + firstChannel * channelBytes;
  b.width = bounds_.x2 - bounds_.x1;
  b.height = bounds_.y2 - bounds_.y1;
  b.channels = channels;
  b.type = half_ ? TAA_PIXEL_HALF : TAA_PIXEL_FLOAT;
  b.row_stride_bytes = rowBytes_;
  b.pixel_stride_bytes = components_ * channelBytes;
  b.y_up = 1;
  return b;
}

float ClipImage::value(int x, int y, int c) const {
  const char* at = pixelAddress(x, y) + c * (half_ ? 2 : 4);
  if (half_) {
    std::uint16_t bits;
    std::memcpy(&bits, at, 2);
    Imath::half h;
    h.setBits(bits);
    return float(h);
  }
  float v;
  std::memcpy(&v, at, 4);
  return v;
}

bool isConnected(OfxImageClipHandle clip) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  if (!clip || s.effects->clipGetPropertySet(clip, &props) != kOfxStatOK) return false;
  int connected = 0;
  s.properties->propGetInt(props, kOfxImageClipPropConnected, 0, &connected);
  return connected != 0;
}

std::string unmappedComponents(OfxImageClipHandle clip) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  char* components = nullptr;
  if (!clip || s.effects->clipGetPropertySet(clip, &props) != kOfxStatOK) return "";
  if (s.properties->propGetString(props, kOfxImageClipPropUnmappedComponents, 0, &components) !=
      kOfxStatOK) {
    return "";
  }
  return components ? components : "";
}

OfxRangeD clipFrameRange(OfxImageClipHandle clip, double fallback) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  double range[2] = {fallback, fallback};
  if (clip && s.effects->clipGetPropertySet(clip, &props) == kOfxStatOK &&
      s.properties->propGetDoubleN(props, kOfxImageEffectPropFrameRange, 2, range) != kOfxStatOK) {
    range[0] = range[1] = fallback;
  }
  return {range[0], range[1]};
}

}  // namespace taa::ofx
