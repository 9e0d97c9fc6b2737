#include "ofx/instance.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "ofx/clip_image.h"
#include "ofx/describe.h"
#include "ofx/host_suites.h"

namespace taa::ofx {
namespace {

OfxImageClipHandle clipHandle(OfxImageEffectHandle effect, const char* name) {
  OfxImageClipHandle clip = nullptr;
  if (suites().effects->clipGetHandle(effect, name, &clip, nullptr) != kOfxStatOK) {
    throw std::runtime_error(std::string("the host has no ") + name + " clip");
  }
  return clip;
}

bool sameRect(const OfxRectI& a, const OfxRectI& b) {
  return a.x1 == b.x1 && a.y1 == b.y1 && a.x2 == b.x2 && a.y2 == b.y2;
}

std::string rectText(const OfxRectI& r) {
  return "(" + std::to_string(r.x1) + ", " + std::to_string(r.y1) + ")-(" + std::to_string(r.x2) +
         ", " + std::to_string(r.y2) + ")";
}

}  // namespace

Instance::Instance(OfxImageEffectHandle effect) : effect_(effect) {
  source_ = clipHandle(effect, kOfxImageEffectSimpleSourceClipName);
  depth_ = clipHandle(effect, kDepthClip);
  motion_ = clipHandle(effect, kMotionClip);
  output_ = clipHandle(effect, kOfxImageEffectOutputClipName);
}

Instance::~Instance() {
  for (auto& entry : histories_) taa_node_destroy(entry.second->node);
}

int Instance::firstFrame(int frame, const PluginSettings& settings) const {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  double range[2] = {double(frame), double(frame)};
  if (s.effects->clipGetPropertySet(source_, &props) == kOfxStatOK) {
    s.properties->propGetDoubleN(props, kOfxImageEffectPropFrameRange, 2, range);
  }
  int first = int(std::lround(range[0]));
  if (settings.historyFrames > 0) first = std::max(first, frame - settings.historyFrames + 1);
  return std::min(first, frame);
}

OfxRangeD Instance::framesNeeded(OfxTime time) const {
  const int frame = int(std::lround(time));
  const PluginSettings settings = readSettings(effect_, time);
  return {double(firstFrame(frame, settings)), double(frame)};
}

Instance::ThreadHistory& Instance::historyOfThisThread() {
  std::lock_guard<std::mutex> lock(historiesMutex_);
  auto& slot = histories_[std::this_thread::get_id()];
  if (!slot) {
    taa_node* node = nullptr;
    if (taa_node_create(nullptr, &node) != TAA_OK) throw std::runtime_error(taa_last_error());
    slot = std::make_unique<ThreadHistory>();
    slot->node = node;
  }
  return *slot;
}

void Instance::pushFrame(ThreadHistory& history, int frame) const {
  const ClipImage color(source_, frame, kOfxImageEffectSimpleSourceClipName);
  std::optional<ClipImage> depth, motion;
  if (isConnected(depth_)) depth.emplace(depth_, frame, kDepthClip);
  if (isConnected(motion_)) motion.emplace(motion_, frame, kMotionClip);
  for (const ClipImage* aux : {depth ? &*depth : nullptr, motion ? &*motion : nullptr}) {
    if (aux && !sameRect(aux->bounds(), color.bounds())) {
      throw std::runtime_error("frame " + std::to_string(frame) +
                               ": depth/motion bounds " + rectText(aux->bounds()) +
                               " differ from the source's " + rectText(color.bounds()));
    }
  }
  if (motion && motion->components() < 2) {
    throw std::runtime_error("the Motion clip needs RGB or RGBA (vectors in R, G)");
  }
  const taa_buffer colorBuffer = color.buffer(0, std::min(color.components(), 4));
  taa_buffer depthBuffer{}, motionBuffer{};
  taa_frame input;
  taa_frame_init(&input);
  input.frame = frame;
  input.color = &colorBuffer;
  if (depth) {
    // Alpha images carry depth in their one channel, colour images in R.
    depthBuffer = depth->buffer(0, 1);
    input.depth = &depthBuffer;
  }
  if (motion) {
    motionBuffer = motion->buffer(0, 2);
    input.motion = &motionBuffer;
  }
  if (taa_node_push_frame(history.node, &input) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }
  history.bounds = color.bounds();
}

void Instance::render(OfxTime time, const OfxRectI& window, double renderScaleX) {
  const int frame = int(std::lround(time));
  const PluginSettings settings = readSettings(effect_, time);
  const int start = firstFrame(frame, settings);
  ThreadHistory& history = historyOfThisThread();

  const bool sameSetup = history.settings && *history.settings == settings &&
                         history.renderScale == renderScaleX && history.startFrame == start;
  if (!sameSetup) {
    applySettings(history.node, settings, renderScaleX);
    history.settings = settings;
    history.renderScale = renderScaleX;
    history.lastFrame.reset();
  }
  const bool holdsFrame = sameSetup && history.lastFrame == frame;
  const bool continues = sameSetup && history.lastFrame && *history.lastFrame + 1 == frame;
  if (!holdsFrame) {
    int from = frame;
    if (!continues) {
      if (taa_node_reset_history(history.node) != TAA_OK) {
        throw std::runtime_error(taa_node_last_error(history.node));
      }
      from = start;
    }
    history.lastFrame.reset();  // until every frame below is in
    for (int f = from; f <= frame; ++f) {
      if (suites().effects->abort(effect_)) throw std::runtime_error("render aborted by host");
      pushFrame(history, f);
    }
    history.startFrame = start;
    history.lastFrame = frame;
  }
  writeOutput(history, time, window);
}

void Instance::writeOutput(ThreadHistory& history, OfxTime time, const OfxRectI& window) const {
  // The resolved frame over the source bounds, y-up like the host's images.
  const OfxRectI& src = history.bounds;
  const int width = src.x2 - src.x1, height = src.y2 - src.y1;
  std::vector<float> resolved(std::size_t(width) * height * 4);
  taa_buffer out;
  std::memset(&out, 0, sizeof out);
  out.data = resolved.data();
  out.width = width;
  out.height = height;
  out.channels = 4;
  out.type = TAA_PIXEL_FLOAT;
  out.y_up = 1;
  if (taa_node_read_output(history.node, &out) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }

  const ClipImage target(output_, time, kOfxImageEffectOutputClipName);
  const OfxRectI& dst = target.bounds();
  const int channels = std::min(target.components(), 4);
  const int x1 = std::max(window.x1, dst.x1), x2 = std::min(window.x2, dst.x2);
  const int y1 = std::max(window.y1, dst.y1), y2 = std::min(window.y2, dst.y2);
  for (int y = y1; y < y2; ++y) {
    for (int x = x1; x < x2; ++x) {
      const bool inside = x >= src.x1 && x < src.x2 && y >= src.y1 && y < src.y2;
      const float* value =
          inside ? &resolved[(std::size_t(y - src.y1) * width + (x - src.x1)) * 4] : nullptr;
      char* pixel = target.pixelAddress(x, y);
      for (int c = 0; c < channels; ++c) {
        const float v = value ? value[c] : 0.0f;
        if (target.isHalf()) {
          const std::uint16_t bits = Imath::half(v).bits();
          std::memcpy(pixel + c * 2, &bits, 2);
        } else {
          std::memcpy(pixel + c * 4, &v, 4);
        }
      }
    }
  }
}

}  // namespace taa::ofx
