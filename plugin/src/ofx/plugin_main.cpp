// The bundle's entry points (OfxGetNumberOfPlugins, OfxGetPlugin) and the action dispatch of
// the TAA Resolve image effect. No exception leaves mainEntry: failures become kOfxStatFailed
// with the message posted to the host's message suite.
#include <cmath>
#include <cstring>
#include <exception>
#include <string>

#include "ofx/clip_preferences.h"
#include "ofx/color_check.h"
#include "ofx/describe.h"
#include "ofx/host_suites.h"
#include "ofx/instance.h"
#include "taa/version.h"

namespace taa::ofx {
namespace {

Instance* instanceOf(OfxImageEffectHandle effect) {
  OfxPropertySetHandle props = nullptr;
  void* data = nullptr;
  if (suites().effects->getPropertySet(effect, &props) != kOfxStatOK) return nullptr;
  suites().properties->propGetPointer(props, kOfxPropInstanceData, 0, &data);
  return static_cast<Instance*>(data);
}

// The instance's SequentialRender for its current settings (temporal_plan.h).
void updateSequentialRender(OfxImageEffectHandle effect) {
  OfxPropertySetHandle props = nullptr;
  if (suites().effects->getPropertySet(effect, &props) != kOfxStatOK) return;
  const PluginSettings settings = readSettings(effect, 0.0);
  suites().properties->propSetInt(props, kOfxImageEffectInstancePropSequentialRender, 0,
                                  sequentialRender(settings));
}

// A colorspace or bracket the chosen config lacks is reported on the
// effect as soon as the settings say so, not at the first render.
void checkColorSettings(OfxImageEffectHandle effect) {
  const std::string problem = colorSettingsProblem(readSettings(effect, 0.0));
  if (problem.empty()) {
    clearError(effect);
  } else {
    reportError(effect, ("TAA Resolve: " + problem).c_str());
  }
}

OfxStatus createInstance(OfxImageEffectHandle effect) {
  OfxPropertySetHandle props = nullptr;
  if (suites().effects->getPropertySet(effect, &props) != kOfxStatOK) return kOfxStatErrBadHandle;
  auto* instance = new Instance(effect);
  suites().properties->propSetPointer(props, kOfxPropInstanceData, 0, instance);
  updateSequentialRender(effect);
  checkColorSettings(effect);
  return kOfxStatOK;
}

OfxStatus destroyInstance(OfxImageEffectHandle effect) {
  Instance* instance = instanceOf(effect);
  delete instance;
  OfxPropertySetHandle props = nullptr;
  if (suites().effects->getPropertySet(effect, &props) == kOfxStatOK) {
    suites().properties->propSetPointer(props, kOfxPropInstanceData, 0, nullptr);
  }
  return kOfxStatOK;
}

OfxStatus instanceChanged(OfxImageEffectHandle effect, OfxPropertySetHandle inArgs) {
  if (!instanceOf(effect)) return kOfxStatErrBadHandle;
  char* type = nullptr;
  char* name = nullptr;
  suites().properties->propGetString(inArgs, kOfxPropType, 0, &type);
  suites().properties->propGetString(inArgs, kOfxPropName, 0, &name);
  if (!type || std::string(type) != kOfxTypeParameter || !name) return kOfxStatReplyDefault;
  updateSequentialRender(effect);
  if (isColorParameter(name)) checkColorSettings(effect);
  return kOfxStatOK;
}

OfxStatus purgeCaches(OfxImageEffectHandle effect) {
  Instance* instance = instanceOf(effect);
  if (!instance) return kOfxStatErrBadHandle;
  instance->purgeCaches();
  return kOfxStatOK;
}

OfxStatus endSequenceRender(OfxImageEffectHandle effect) {
  Instance* instance = instanceOf(effect);
  if (!instance) return kOfxStatErrBadHandle;
  instance->endSequence();
  return kOfxStatOK;
}

OfxStatus framesNeeded(OfxImageEffectHandle effect, OfxPropertySetHandle inArgs,
                       OfxPropertySetHandle outArgs) {
  Instance* instance = instanceOf(effect);
  if (!instance) return kOfxStatErrBadHandle;
  double time = 0.0;
  suites().properties->propGetDouble(inArgs, kOfxPropTime, 0, &time);
  const FrameRange frames = instance->plan(time).frames;
  const double values[2] = {double(frames.first), double(frames.last)};
  for (const char* clip : {kOfxImageEffectSimpleSourceClipName, kDepthClip, kMotionClip,
                           kPassClip, kPassFactorClip}) {
    const std::string name = std::string(kOfxImageClipPropFrameRangePrefix) + clip;
    suites().properties->propSetDoubleN(outArgs, name.c_str(), 2, values);
  }
  return kOfxStatOK;
}

OfxStatus render(OfxImageEffectHandle effect, OfxPropertySetHandle inArgs) {
  Instance* instance = instanceOf(effect);
  if (!instance) return kOfxStatErrBadHandle;
  const HostSuites& s = suites();
  double time = 0.0;
  double scale[2] = {1.0, 1.0};
  OfxRectI window{};
  s.properties->propGetDouble(inArgs, kOfxPropTime, 0, &time);
  s.properties->propGetDoubleN(inArgs, kOfxImageEffectPropRenderScale, 2, scale);
  s.properties->propGetIntN(inArgs, kOfxImageEffectPropRenderWindow, 4, &window.x1);
  instance->render(time, window, RenderScale{scale[0], scale[1]});
  clearError(effect);  // whatever a failed render left on the effect no longer holds
  return kOfxStatOK;
}

OfxStatus dispatch(const char* action, OfxImageEffectHandle effect, OfxPropertySetHandle inArgs,
                   OfxPropertySetHandle outArgs) {
  const std::string a = action;
  if (a == kOfxActionLoad) return fetchSuites() ? kOfxStatOK : kOfxStatErrMissingHostFeature;
  if (a == kOfxActionUnload) return kOfxStatOK;
  if (a == kOfxActionDescribe) return describe(effect);
  if (a == kOfxImageEffectActionDescribeInContext) return describeInContext(effect);
  if (a == kOfxActionCreateInstance) return createInstance(effect);
  if (a == kOfxActionDestroyInstance) return destroyInstance(effect);
  if (a == kOfxActionInstanceChanged) return instanceChanged(effect, inArgs);
  if (a == kOfxActionPurgeCaches) return purgeCaches(effect);
  if (a == kOfxImageEffectActionEndSequenceRender) return endSequenceRender(effect);
  if (a == kOfxImageEffectActionGetFramesNeeded) return framesNeeded(effect, inArgs, outArgs);
  if (a == kOfxImageEffectActionGetClipPreferences) return clipPreferences(effect, outArgs);
  if (a == kOfxImageEffectActionRender) return render(effect, inArgs);
  return kOfxStatReplyDefault;
}

OfxStatus mainEntry(const char* action, const void* handle, OfxPropertySetHandle inArgs,
                    OfxPropertySetHandle outArgs) {
  if (!action) return kOfxStatErrBadHandle;
  auto effect = static_cast<OfxImageEffectHandle>(const_cast<void*>(handle));
  try {
    return dispatch(action, effect, inArgs, outArgs);
  } catch (const std::exception& e) {
    reportError(effect, (std::string("TAA Resolve: ") + e.what()).c_str());
  } catch (...) {
    reportError(effect, "TAA Resolve: unknown error");
  }
  return kOfxStatFailed;
}

void setHost(OfxHost* host) { suites().host = host; }

OfxPlugin plugin = {kOfxImageEffectPluginApi,
                    1,
                    "org.taa.TAAResolve",
                    TAA_VERSION_MAJOR,
                    TAA_VERSION_MINOR,
                    setHost,
                    mainEntry};

}  // namespace
}  // namespace taa::ofx

extern "C" {

__attribute__((visibility("default"))) int OfxGetNumberOfPlugins(void) { return 1; }

__attribute__((visibility("default"))) OfxPlugin* OfxGetPlugin(int nth) {
  return nth == 0 ? &taa::ofx::plugin : nullptr;
}

}  // extern "C"
