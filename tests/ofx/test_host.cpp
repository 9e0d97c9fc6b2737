#include "test_host.h"

#include <Imath/half.h>
#include <dlfcn.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace taa::ofxtest {
namespace {

// The suites are plain C functions: they reach the host through this state.
std::mutex stateMutex;
std::vector<std::string> postedMessages;
std::map<const void*, std::string> persistentMessages;  // by effect handle
thread_local OutputImage* currentOutput = nullptr;

struct HostImage {
  PropertySet props;
  std::vector<char> data;
};
std::map<PropertySet*, std::unique_ptr<HostImage>> liveImages;  // by their props
std::size_t peakLiveImages = 0;  // the most held at once since the last reset

int componentCount(const std::string& components) {
  return components == kOfxImageComponentAlpha ? 1
         : components == kOfxImageComponentRGB ? 3
                                                : 4;
}

// What a stored frame of `channels` channels is connected as: 1 Alpha, 2 or 3 RGB, 4 RGBA.
const char* nativeComponents(int channels) {
  return channels == 1 ? kOfxImageComponentAlpha
         : channels == 4 ? kOfxImageComponentRGBA
                         : kOfxImageComponentRGB;
}

void describeImage(PropertySet& props, void* data, const OfxRectI& bounds, int rowBytes,
                   bool half, const std::string& components, double pixelAspectRatio) {
  props.set(kOfxImagePropData, {data});
  props.set(kOfxImagePropBounds, {bounds.x1, bounds.y1, bounds.x2, bounds.y2});
  props.set(kOfxImagePropRowBytes, {rowBytes});
  props.set(kOfxImageEffectPropPixelDepth,
            {std::string(half ? kOfxBitDepthHalf : kOfxBitDepthFloat)});
  props.set(kOfxImageEffectPropComponents, {components});
  props.set(kOfxImageEffectPropPreMultiplication, {std::string(kOfxImagePreMultiplied)});
  props.set(kOfxImagePropPixelAspectRatio, {pixelAspectRatio});
}

void storeValue(char* at, bool half, float value) {
  if (half) {
    const std::uint16_t bits = Imath::half(value).bits();
    std::memcpy(at, &bits, 2);
  } else {
    std::memcpy(at, &value, 4);
  }
}

float loadValue(const char* at, bool half) {
  if (half) {
    std::uint16_t bits;
    std::memcpy(&bits, at, 2);
    Imath::half h;
    h.setBits(bits);
    return float(h);
  }
  float value;
  std::memcpy(&value, at, 4);
  return value;
}

// A stored pixel as RGBA, the way a host widens components: Alpha -> (0, 0, 0, a), two
// channels -> (x, y, 0, 1), RGB -> (r, g, b, 1).
void widen(const float* in, int channels, float rgba[4]) {
  rgba[0] = rgba[1] = rgba[2] = 0.0f;
  rgba[3] = 1.0f;
  if (channels == 1) {
    rgba[3] = in[0];
    return;
  }
  for (int c = 0; c < channels; ++c) rgba[c] = in[c];
}

// An input frame as an OFX image: y-up rows, 16 bytes of padding per row, the clip's bounds
// (a frame smaller than them is centred in them with zeros around, one larger is cropped),
// served as the clip's mapped components.
HostImage* makeInputImage(const HostClip& clip, const Image& frame) {
  const bool half = clip.source->half;
  const std::string components =
      clip.components.empty() ? nativeComponents(frame.channels) : clip.components;
  const int count = componentCount(components);
  const int bytes = half ? 2 : 4;
  const int width = clip.bounds.x2 - clip.bounds.x1, height = clip.bounds.y2 - clip.bounds.y1;
  const int rowBytes = width * count * bytes + 16;
  const int dx = (width - frame.width) / 2, dy = (height - frame.height) / 2;
  auto* image = new HostImage;
  image->data.assign(std::size_t(rowBytes) * height, 0);
  for (int row = 0; row < height; ++row) {
    const int frameRow = row - dy;
    if (frameRow < 0 || frameRow >= frame.height) continue;
    char* out = image->data.data() + std::size_t(height - 1 - row) * rowBytes;
    for (int x = 0; x < width; ++x) {
      const int frameX = x - dx;
      if (frameX < 0 || frameX >= frame.width) continue;
      float rgba[4];
      widen(frame.at(frameX, frameRow), frame.channels, rgba);
      const float* served = count == 1 ? &rgba[3] : rgba;
      for (int c = 0; c < count; ++c) storeValue(out + (x * count + c) * bytes, half, served[c]);
    }
  }
  describeImage(image->props, image->data.data(), clip.bounds, rowBytes, half, components,
                clip.pixelAspectRatio);
  return image;
}

// --- OfxImageEffectSuiteV1
OfxStatus getPropertySet(OfxImageEffectHandle effect, OfxPropertySetHandle* props) {
  if (!effect) return kOfxStatErrBadHandle;
  *props = reinterpret_cast<HostEffect*>(effect)->props.handle();
  return kOfxStatOK;
}

OfxStatus getParamSet(OfxImageEffectHandle effect, OfxParamSetHandle* set) {
  if (!effect) return kOfxStatErrBadHandle;
  *set = reinterpret_cast<OfxParamSetHandle>(effect);
  return kOfxStatOK;
}

OfxStatus clipDefine(OfxImageEffectHandle effect, const char* name, OfxPropertySetHandle* props) {
  HostClip& clip = reinterpret_cast<HostEffect*>(effect)->clips[name];
  clip.name = name;
  *props = clip.props.handle();
  return kOfxStatOK;
}

OfxStatus clipGetHandle(OfxImageEffectHandle effect, const char* name, OfxImageClipHandle* clip,
                        OfxPropertySetHandle* props) {
  auto& clips = reinterpret_cast<HostEffect*>(effect)->clips;
  const auto it = clips.find(name);
  if (it == clips.end()) return kOfxStatErrBadIndex;
  *clip = reinterpret_cast<OfxImageClipHandle>(&it->second);
  if (props) *props = it->second.props.handle();
  return kOfxStatOK;
}

OfxStatus clipGetPropertySet(OfxImageClipHandle clip, OfxPropertySetHandle* props) {
  if (!clip) return kOfxStatErrBadHandle;
  *props = reinterpret_cast<HostClip*>(clip)->props.handle();
  return kOfxStatOK;
}

OfxStatus clipGetImage(OfxImageClipHandle handle, OfxTime time, const OfxRectD*,
                       OfxPropertySetHandle* imageProps) {
  const HostClip& clip = *reinterpret_cast<HostClip*>(handle);
  HostImage* image = nullptr;
  if (clip.name == kOfxImageEffectOutputClipName) {
    if (!currentOutput) return kOfxStatFailed;
    image = new HostImage;
    describeImage(image->props, currentOutput->data.data(), currentOutput->bounds,
                  currentOutput->rowBytes, currentOutput->half, kOfxImageComponentRGBA,
                  clip.pixelAspectRatio);
  } else {
    if (!clip.source) return kOfxStatFailed;
    const auto frame = clip.source->frames.find(int(time));
    if (frame == clip.source->frames.end()) return kOfxStatFailed;
    image = makeInputImage(clip, frame->second);
  }
  std::lock_guard<std::mutex> lock(stateMutex);
  ++const_cast<HostClip&>(clip).imagesServed;
  liveImages[&image->props].reset(image);
  peakLiveImages = std::max(peakLiveImages, liveImages.size());
  *imageProps = image->props.handle();
  return kOfxStatOK;
}

OfxStatus clipReleaseImage(OfxPropertySetHandle imageProps) {
  std::lock_guard<std::mutex> lock(stateMutex);
  return liveImages.erase(PropertySet::from(imageProps)) ? kOfxStatOK : kOfxStatErrBadHandle;
}

OfxStatus clipGetRegionOfDefinition(OfxImageClipHandle handle, OfxTime, OfxRectD* bounds) {
  const OfxRectI& b = reinterpret_cast<HostClip*>(handle)->bounds;
  *bounds = {double(b.x1), double(b.y1), double(b.x2), double(b.y2)};
  return kOfxStatOK;
}

int abortRender(OfxImageEffectHandle) { return 0; }

OfxStatus memoryAlloc(OfxImageEffectHandle, std::size_t, OfxImageMemoryHandle*) {
  return kOfxStatErrMemory;
}
OfxStatus memoryHandleOnly(OfxImageMemoryHandle) { return kOfxStatErrBadHandle; }
OfxStatus memoryLock(OfxImageMemoryHandle, void**) { return kOfxStatErrBadHandle; }

const OfxImageEffectSuiteV1 kImageEffectSuite = {
    getPropertySet,  getParamSet,          clipDefine,     clipGetHandle,
    clipGetPropertySet, clipGetImage,      clipReleaseImage, clipGetRegionOfDefinition,
    abortRender,     memoryAlloc,          memoryHandleOnly, memoryLock,
    memoryHandleOnly};

// --- OfxParameterSuiteV1
HostEffect* effectOf(OfxParamSetHandle set) { return reinterpret_cast<HostEffect*>(set); }

OfxStatus paramDefine(OfxParamSetHandle set, const char* type, const char* name,
                      OfxPropertySetHandle* props) {
  HostParam& param = effectOf(set)->params[name];
  param.type = type;
  param.props.set(kOfxPropName, {std::string(name)});
  if (props) *props = param.props.handle();
  return kOfxStatOK;
}

OfxStatus paramGetHandle(OfxParamSetHandle set, const char* name, OfxParamHandle* param,
                         OfxPropertySetHandle* props) {
  auto& params = effectOf(set)->params;
  const auto it = params.find(name);
  if (it == params.end()) return kOfxStatErrUnknown;
  *param = reinterpret_cast<OfxParamHandle>(&it->second);
  if (props) *props = it->second.props.handle();
  return kOfxStatOK;
}

OfxStatus paramSetGetPropertySet(OfxParamSetHandle set, OfxPropertySetHandle* props) {
  *props = effectOf(set)->paramSetProps.handle();
  return kOfxStatOK;
}

OfxStatus paramGetPropertySet(OfxParamHandle param, OfxPropertySetHandle* props) {
  *props = reinterpret_cast<HostParam*>(param)->props.handle();
  return kOfxStatOK;
}

OfxStatus readParam(const HostParam& param, va_list args) {
  if (param.type == kOfxParamTypeDouble) {
    *va_arg(args, double*) = param.doubleValue;
  } else if (param.type == kOfxParamTypeString) {
    *va_arg(args, const char**) = param.stringValue.c_str();
  } else {
    *va_arg(args, int*) = param.intValue;
  }
  return kOfxStatOK;
}

OfxStatus paramGetValue(OfxParamHandle handle, ...) {
  va_list args;
  va_start(args, handle);
  const OfxStatus status = readParam(*reinterpret_cast<HostParam*>(handle), args);
  va_end(args);
  return status;
}

OfxStatus paramGetValueAtTime(OfxParamHandle handle, OfxTime time, ...) {
  va_list args;
  va_start(args, time);
  const OfxStatus status = readParam(*reinterpret_cast<HostParam*>(handle), args);
  va_end(args);
  return status;
}

OfxStatus paramUnsupportedAtTime(OfxParamHandle, OfxTime, ...) { return kOfxStatErrUnsupported; }
OfxStatus paramUnsupportedIntegral(OfxParamHandle, OfxTime, OfxTime, ...) {
  return kOfxStatErrUnsupported;
}
OfxStatus paramUnsupported(OfxParamHandle, ...) { return kOfxStatErrUnsupported; }
OfxStatus paramNumKeys(OfxParamHandle, unsigned int* n) {
  *n = 0;
  return kOfxStatOK;
}
OfxStatus paramKeyTime(OfxParamHandle, unsigned int, OfxTime*) { return kOfxStatErrBadIndex; }
OfxStatus paramKeyIndex(OfxParamHandle, OfxTime, int, int* index) {
  *index = -1;
  return kOfxStatFailed;
}
OfxStatus paramDeleteKey(OfxParamHandle, OfxTime) { return kOfxStatErrBadIndex; }
OfxStatus paramDeleteAllKeys(OfxParamHandle) { return kOfxStatOK; }
OfxStatus paramCopy(OfxParamHandle, OfxParamHandle, OfxTime, const OfxRangeD*) {
  return kOfxStatErrUnsupported;
}
OfxStatus paramEditBegin(OfxParamSetHandle, const char*) { return kOfxStatOK; }
OfxStatus paramEditEnd(OfxParamSetHandle) { return kOfxStatOK; }

const OfxParameterSuiteV1 kParameterSuite = {
    paramDefine,          paramGetHandle,        paramSetGetPropertySet, paramGetPropertySet,
    paramGetValue,        paramGetValueAtTime,   paramUnsupportedAtTime, paramUnsupportedIntegral,
    paramUnsupported,     paramUnsupportedAtTime, paramNumKeys,          paramKeyTime,
    paramKeyIndex,        paramDeleteKey,        paramDeleteAllKeys,     paramCopy,
    paramEditBegin,       paramEditEnd};

// --- OfxMessageSuiteV2 (its first member is version 1's)
std::string formatMessage(const char* type, const char* format, va_list args) {
  char text[4096];
  std::vsnprintf(text, sizeof text, format, args);
  return std::string(type ? type : "") + ": " + text;
}

OfxStatus postMessage(void*, const char* type, const char*, const char* format, ...) {
  va_list args;
  va_start(args, format);
  const std::string text = formatMessage(type, format, args);
  va_end(args);
  std::lock_guard<std::mutex> lock(stateMutex);
  postedMessages.push_back(text);
  return kOfxStatOK;
}

OfxStatus setPersistentMessage(void* effect, const char* type, const char*, const char* format,
                               ...) {
  if (!effect) return kOfxStatErrBadHandle;
  va_list args;
  va_start(args, format);
  const std::string text = formatMessage(type, format, args);
  va_end(args);
  std::lock_guard<std::mutex> lock(stateMutex);
  persistentMessages[effect] = text;
  return kOfxStatOK;
}

OfxStatus clearPersistentMessage(void* effect) {
  if (!effect) return kOfxStatErrBadHandle;
  std::lock_guard<std::mutex> lock(stateMutex);
  persistentMessages.erase(effect);
  return kOfxStatOK;
}

const OfxMessageSuiteV2 kMessageSuite = {postMessage, setPersistentMessage,
                                         clearPersistentMessage};

const void* fetchSuite(OfxPropertySetHandle, const char* name, int version) {
  const std::string n = name ? name : "";
  if (n == kOfxMessageSuite && (version == 1 || version == 2)) return &kMessageSuite;
  if (version != 1) return nullptr;
  if (n == kOfxPropertySuite) return propertySuite();
  if (n == kOfxImageEffectSuite) return &kImageEffectSuite;
  if (n == kOfxParameterSuite) return &kParameterSuite;
  return nullptr;
}

}  // namespace

Image OutputImage::toImage() const {
  const int width = bounds.x2 - bounds.x1, height = bounds.y2 - bounds.y1;
  const int bytes = half ? 2 : 4;
  Image image(width, height, 4);
  for (int row = 0; row < height; ++row) {
    const char* in = data.data() + std::size_t(height - 1 - row) * rowBytes;
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < 4; ++c) image.at(x, row)[c] = loadValue(in + (x * 4 + c) * bytes, half);
    }
  }
  return image;
}

TestHost::TestHost() {
  hostProps_.set(kOfxPropName, {std::string("org.taa.testhost")});
  hostProps_.set(kOfxPropLabel, {std::string("taa test host")});
  host_.host = hostProps_.handle();
  host_.fetchSuite = fetchSuite;
  std::lock_guard<std::mutex> lock(stateMutex);
  postedMessages.clear();
  persistentMessages.clear();
}

TestHost::~TestHost() {
  if (plugin_) action(kOfxActionUnload, nullptr);
  if (library_) dlclose(library_);
}

std::string TestHost::load(const std::string& binaryPath) {
  library_ = dlopen(binaryPath.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library_) return dlerror();
  auto count = reinterpret_cast<int (*)()>(dlsym(library_, kOfxGetNumberOfPluginsSymbol));
  auto get = reinterpret_cast<OfxPlugin* (*)(int)>(dlsym(library_, kOfxGetPluginSymbol));
  if (!count || !get) return "the bundle's entry points are not exported";
  if (count() < 1) return "the bundle has no plugin";
  plugin_ = get(0);
  if (!plugin_) return "the bundle's first plugin is NULL";
  plugin_->setHost(&host_);
  return "";
}

OfxStatus TestHost::action(const char* name, HostEffect* effect, PropertySet* inArgs,
                           PropertySet* outArgs) {
  return plugin_->mainEntry(name, effect ? effect->handle() : nullptr,
                            inArgs ? inArgs->handle() : nullptr,
                            outArgs ? outArgs->handle() : nullptr);
}

std::unique_ptr<HostEffect> TestHost::makeInstance(
    HostEffect& descriptor, const char* context,
    const std::map<std::string, const ClipFrames*>& inputs, OfxRectI bounds, double firstFrame,
    double lastFrame) {
  auto instance = std::make_unique<HostEffect>();
  instance->props = descriptor.props;
  instance->props.set(kOfxImageEffectPropContext, {std::string(context)});
  instance->props.set(kOfxImageEffectPropFrameRange, {firstFrame, lastFrame});
  bool sourceHalf = false;
  for (const auto& [name, described] : descriptor.clips) {
    HostClip& clip = instance->clips[name];
    clip.name = name;
    clip.props = described.props;
    clip.bounds = bounds;
    const auto input = inputs.find(name);
    clip.source = input == inputs.end() ? nullptr : input->second;
    if (name == kOfxImageEffectSimpleSourceClipName && clip.source) sourceHalf = clip.source->half;
    const bool connected = clip.source || name == kOfxImageEffectOutputClipName;
    clip.props.set(kOfxImageClipPropConnected, {connected ? 1 : 0});
    std::string unmapped = connected ? kOfxImageComponentRGBA : kOfxImageComponentNone;
    if (clip.source && !clip.source->frames.empty()) {
      unmapped = nativeComponents(clip.source->frames.begin()->second.channels);
    }
    clip.props.set(kOfxImageClipPropUnmappedComponents, {unmapped});
    clip.props.set(kOfxImagePropPixelAspectRatio, {1.0});
    clip.props.set(kOfxImageEffectPropFrameRange, {firstFrame, lastFrame});
    clip.props.set(kOfxPropName, {name});
  }
  for (auto& [name, clip] : instance->clips) {
    const bool half = clip.source ? clip.source->half : sourceHalf;
    clip.props.set(kOfxImageEffectPropPixelDepth,
                   {std::string(half ? kOfxBitDepthHalf : kOfxBitDepthFloat)});
  }
  for (const auto& [name, described] : descriptor.params) {
    HostParam& param = instance->params[name];
    param = described;
    if (!param.props.has(kOfxParamPropDefault)) continue;
    if (param.type == kOfxParamTypeDouble) {
      param.doubleValue = param.props.getDouble(kOfxParamPropDefault);
    } else if (param.type == kOfxParamTypeString) {
      param.stringValue = param.props.getString(kOfxParamPropDefault);
    } else {
      param.intValue = param.props.getInt(kOfxParamPropDefault);
    }
  }
  return instance;
}

OfxStatus TestHost::clipPreferences(HostEffect& instance, PropertySet& outArgs, bool honour) {
  // The default for every input: the most chromatic components among the connected inputs.
  std::string defaults = kOfxImageComponentAlpha;
  for (const auto& [name, clip] : instance.clips) {
    if (!clip.source || clip.source->frames.empty()) continue;
    const std::string native = nativeComponents(clip.source->frames.begin()->second.channels);
    if (componentCount(native) > componentCount(defaults)) defaults = native;
  }
  outArgs = PropertySet{};
  for (const auto& [name, clip] : instance.clips) {
    const bool output = name == kOfxImageEffectOutputClipName;
    outArgs.set(kOfxImageClipPropComponentsPrefix + name,
                {output ? std::string(kOfxImageComponentRGBA) : defaults});
    outArgs.set(kOfxImageClipPropPARPrefix + name, {clip.pixelAspectRatio});
  }
  const OfxStatus status =
      action(kOfxImageEffectActionGetClipPreferences, &instance, nullptr, &outArgs);
  if (status != kOfxStatOK && status != kOfxStatReplyDefault) return status;
  for (auto& [name, clip] : instance.clips) {
    if (!clip.source) continue;
    clip.components = honour ? outArgs.getString(kOfxImageClipPropComponentsPrefix + name)
                             : defaults;
    clip.props.set(kOfxImageEffectPropComponents, {clip.components});
  }
  return status;
}

OfxStatus TestHost::parameterChanged(HostEffect& instance, const std::string& name) {
  PropertySet inArgs;
  inArgs.set(kOfxPropType, {std::string(kOfxTypeParameter)});
  inArgs.set(kOfxPropName, {name});
  inArgs.set(kOfxPropTime, {0.0});
  return action(kOfxActionInstanceChanged, &instance, &inArgs);
}

OfxStatus TestHost::render(HostEffect& instance, double time, OutputImage& output,
                           double renderScaleX, double renderScaleY) {
  if (renderScaleY < 0.0) renderScaleY = renderScaleX;
  const HostClip& out = instance.clips.at(kOfxImageEffectOutputClipName);
  output.bounds = out.bounds;
  output.half = out.props.getString(kOfxImageEffectPropPixelDepth) == kOfxBitDepthHalf;
  const int width = out.bounds.x2 - out.bounds.x1, height = out.bounds.y2 - out.bounds.y1;
  output.rowBytes = width * 4 * (output.half ? 2 : 4) + 32;
  output.data.assign(std::size_t(output.rowBytes) * height, 0);

  PropertySet inArgs;
  inArgs.set(kOfxPropTime, {time});
  inArgs.set(kOfxImageEffectPropFieldToRender, {std::string(kOfxImageFieldNone)});
  inArgs.set(kOfxImageEffectPropRenderWindow,
             {out.bounds.x1, out.bounds.y1, out.bounds.x2, out.bounds.y2});
  inArgs.set(kOfxImageEffectPropRenderScale, {renderScaleX, renderScaleY});
  currentOutput = &output;
  const OfxStatus status = action(kOfxImageEffectActionRender, &instance, &inArgs);
  currentOutput = nullptr;
  return status;
}

std::vector<std::string> TestHost::messages() const {
  std::lock_guard<std::mutex> lock(stateMutex);
  return postedMessages;
}

std::string TestHost::persistentMessage(const HostEffect& effect) const {
  std::lock_guard<std::mutex> lock(stateMutex);
  const auto it = persistentMessages.find(&effect);
  return it == persistentMessages.end() ? "" : it->second;
}

int TestHost::peakLiveImages(bool reset) const {
  std::lock_guard<std::mutex> lock(stateMutex);
  const int peak = int(taa::ofxtest::peakLiveImages);
  if (reset) taa::ofxtest::peakLiveImages = taa::ofxtest::liveImages.size();
  return peak;
}

int TestHost::liveImages() const {
  std::lock_guard<std::mutex> lock(stateMutex);
  return int(taa::ofxtest::liveImages.size());
}

}  // namespace taa::ofxtest
