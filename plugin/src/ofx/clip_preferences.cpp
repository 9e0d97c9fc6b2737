#include "ofx/clip_preferences.h"

#include <string>

#include "ofx/clip_image.h"
#include "ofx/describe.h"
#include "ofx/host_suites.h"

namespace taa::ofx {
namespace {

void setComponents(OfxPropertySetHandle outArgs, const char* clip, const char* components) {
  const std::string name = std::string(kOfxImageClipPropComponentsPrefix) + clip;
  suites().properties->propSetString(outArgs, name.c_str(), 0, components);
}

// Keeps an optional input clip's components as connected, when they are ones it accepts.
void keepConnectedComponents(OfxImageEffectHandle effect, OfxPropertySetHandle outArgs,
                             const char* clipName, bool acceptsAlpha) {
  OfxImageClipHandle clip = nullptr;
  if (suites().effects->clipGetHandle(effect, clipName, &clip, nullptr) != kOfxStatOK) return;
  if (!isConnected(clip)) return;
  const std::string connected = unmappedComponents(clip);
  if (connected == kOfxImageComponentRGBA) {
    setComponents(outArgs, clipName, kOfxImageComponentRGBA);
  } else if (connected == kOfxImageComponentRGB) {
    setComponents(outArgs, clipName, kOfxImageComponentRGB);
  } else if (connected == kOfxImageComponentAlpha && acceptsAlpha) {
    setComponents(outArgs, clipName, kOfxImageComponentAlpha);
  }
}

}  // namespace

OfxStatus clipPreferences(OfxImageEffectHandle effect, OfxPropertySetHandle outArgs) {
  const HostSuites& s = suites();
  s.properties->propSetString(outArgs, kOfxImageEffectPropPreMultiplication, 0,
                              kOfxImagePreMultiplied);
  s.properties->propSetInt(outArgs, kOfxImageEffectFrameVarying, 0, 1);
  setComponents(outArgs, kOfxImageEffectOutputClipName, kOfxImageComponentRGBA);
  keepConnectedComponents(effect, outArgs, kDepthClip, true);
  keepConnectedComponents(effect, outArgs, kMotionClip, false);
  keepConnectedComponents(effect, outArgs, kPassClip, true);
  keepConnectedComponents(effect, outArgs, kPassFactorClip, true);
  return kOfxStatOK;
}

}  // namespace taa::ofx
