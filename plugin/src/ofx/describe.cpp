#include "ofx/describe.h"

#include <vector>

#include "ofx/host_suites.h"
#include "ofx/plugin_parameters.h"
#include "ofx/temporal_plan.h"

namespace taa::ofx {
namespace {

void setStrings(OfxPropertySetHandle props, const char* name,
                const std::vector<const char*>& values) {
  for (int i = 0; i < int(values.size()); ++i) {
    suites().properties->propSetString(props, name, i, values[i]);
  }
}

OfxStatus defineClip(OfxImageEffectHandle descriptor, const char* name,
                     const std::vector<const char*>& components, bool optional) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  const OfxStatus status = s.effects->clipDefine(descriptor, name, &props);
  if (status != kOfxStatOK) return status;
  setStrings(props, kOfxImageEffectPropSupportedComponents, components);
  s.properties->propSetInt(props, kOfxImageEffectPropTemporalClipAccess, 0, 1);
  s.properties->propSetInt(props, kOfxImageEffectPropSupportsTiles, 0, 0);
  s.properties->propSetInt(props, kOfxImageClipPropOptional, 0, optional ? 1 : 0);
  return kOfxStatOK;
}

}  // namespace

OfxStatus describe(OfxImageEffectHandle descriptor) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  if (s.effects->getPropertySet(descriptor, &props) != kOfxStatOK) return kOfxStatErrBadHandle;
  s.properties->propSetString(props, kOfxPropLabel, 0, "TAA Resolve");
  s.properties->propSetString(props, kOfxImageEffectPluginPropGrouping, 0, "taa");
  s.properties->propSetString(
      props, kOfxPropPluginDescription, 0,
      "Temporal anti-aliasing resolve of a jittered render with its depth and motion AOVs, "
      "exactly as taatool resolves the sequence. History mode: frame t is resolved from the "
      "clip's first frame (see History Frames). Window mode: from frames t-K..t+K, in any "
      "order. With the Pass clip connected (window mode), the output is that pass (a light, "
      "colour, data or Cryptomatte pass of the same render) resolved with the Source's "
      "weights, as taatool resolves every pass beside the beauty.");
  setStrings(props, kOfxImageEffectPropSupportedContexts,
             {kOfxImageEffectContextFilter, kOfxImageEffectContextGeneral});
  setStrings(props, kOfxImageEffectPropSupportedPixelDepths, {kOfxBitDepthHalf, kOfxBitDepthFloat});
  s.properties->propSetInt(props, kOfxImageEffectPropTemporalClipAccess, 0, 1);
  s.properties->propSetInt(props, kOfxImageEffectPropSupportsTiles, 0, 0);
  s.properties->propSetInt(props, kOfxImageEffectPropSupportsMultiResolution, 0, 1);
  s.properties->propSetInt(props, kOfxImageEffectPropSupportsMultipleClipDepths, 0, 1);
  // Depth and motion are in pixels of the colour's grid: the host conforms every clip to one
  // pixel aspect ratio.
  s.properties->propSetInt(props, kOfxImageEffectPropSupportsMultipleClipPARs, 0, 0);
  // The default parameters (window mode) render in any order; each instance updates this for
  // its own settings (temporal_plan.h: history from the clip's start needs the frames in order).
  s.properties->propSetInt(props, kOfxImageEffectInstancePropSequentialRender, 0,
                           sequentialRender(PluginSettings{}));
  s.properties->propSetInt(props, kOfxImageEffectPluginPropHostFrameThreading, 0, 0);
  // Each render takes a node (GL context) of its own from the instance's pool, so concurrent
  // renders are safe; beyond the pool's bound they wait (ofx/node_pool.h).
  s.properties->propSetString(props, kOfxImageEffectPluginRenderThreadSafety, 0,
                              kOfxImageEffectRenderFullySafe);
  return kOfxStatOK;
}

OfxStatus describeInContext(OfxImageEffectHandle descriptor) {
  struct ClipSpec {
    const char* name;
    std::vector<const char*> components;
    bool optional;
  };
  const std::vector<const char*> rgb = {kOfxImageComponentRGBA, kOfxImageComponentRGB};
  const std::vector<const char*> rgbOrAlpha = {kOfxImageComponentRGBA, kOfxImageComponentRGB,
                                               kOfxImageComponentAlpha};
  const ClipSpec clips[] = {{kOfxImageEffectSimpleSourceClipName, rgb, false},
                            {kDepthClip, rgbOrAlpha, true},
                            {kMotionClip, rgb, true},
                            {kPassClip, rgbOrAlpha, true},
                            {kPassFactorClip, rgbOrAlpha, true},
                            {kOfxImageEffectOutputClipName, {kOfxImageComponentRGBA}, false}};
  for (const ClipSpec& clip : clips) {
    const OfxStatus status = defineClip(descriptor, clip.name, clip.components, clip.optional);
    if (status != kOfxStatOK) return status;
  }
  OfxParamSetHandle parameters = nullptr;
  if (suites().effects->getParamSet(descriptor, &parameters) != kOfxStatOK) {
    return kOfxStatErrBadHandle;
  }
  defineParameters(parameters);
  return kOfxStatOK;
}

}  // namespace taa::ofx
