#include "ofx/instance.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "ofx/aux_buffer.h"
#include "ofx/clip_image.h"
#include "ofx/describe.h"
#include "ofx/host_suites.h"
#include "ofx/pass_clip.h"
#include "util/frame_span.h"

namespace taa::ofx {
namespace {

OfxImageClipHandle clipHandle(OfxImageEffectHandle effect, const char* name) {
  OfxImageClipHandle clip = nullptr;
  if (suites().effects->clipGetHandle(effect, name, &clip, nullptr) != kOfxStatOK) {
    throw std::runtime_error(std::string("the host has no ") + name + " clip");
  }
  return clip;
}

std::string number(double value) {
  std::string text = std::to_string(value);
  text.erase(text.find_last_not_of('0') + 1);
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

// Depth and motion are in pixels of the colour's grid: a host that gives their clips another
// pixel aspect ratio than the Source's has resampled one of them (taa declares no support for
// several ratios, so hosts should conform them all).
void requireSamePixelAspect(const ClipImage& aux, const ClipImage& color) {
  if (aux.pixelAspectRatio() != color.pixelAspectRatio()) {
    throw std::runtime_error("the " + aux.where() + " has pixel aspect ratio " +
                             number(aux.pixelAspectRatio()) + ", the Source clip " +
                             number(color.pixelAspectRatio()) +
                             ": depth and motion must be on the colour's pixel grid");
  }
}

// The resolved Pass clip into `out` (RGBA): its channels in order; a one-channel (Alpha) pass
// in all four; an RGB pass with A = 1, as hosts map RGB to RGBA.
void readPass(const NodeSlot& history, taa_buffer& out) {
  const std::vector<std::string>& names = history.passNames;
  std::vector<taa_pass> passes;
  for (int c = 0; c < int(names.size()); ++c) {
    passes.push_back({names[std::size_t(c)].c_str(), &out, c});
  }
  if (taa_node_read_passes(history.node, passes.data(), int(passes.size())) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }
  float* values = static_cast<float*>(out.data);
  for (std::size_t p = 0; p < std::size_t(out.width) * out.height; ++p) {
    float* pixel = values + 4 * p;
    if (names.size() == 1) pixel[1] = pixel[2] = pixel[3] = pixel[0];
    if (names.size() == 3) pixel[3] = 1.0f;
  }
}

}  // namespace

Instance::Instance(OfxImageEffectHandle effect)
    : effect_(effect), pool_(renderNodesFromEnvironment()) {
  source_ = clipHandle(effect, kOfxImageEffectSimpleSourceClipName);
  depth_ = clipHandle(effect, kDepthClip);
  motion_ = clipHandle(effect, kMotionClip);
  output_ = clipHandle(effect, kOfxImageEffectOutputClipName);
  pass_ = clipHandle(effect, kPassClip);
  passFactor_ = clipHandle(effect, kPassFactorClip);
}

PluginSettings Instance::settingsAt(OfxTime time) const {
  PluginSettings settings = readSettings(effect_, time);
  settings.passConnected = isConnected(pass_);
  // Only a light pass has a factor: a colour left connected under another kind is not used.
  settings.passFactorConnected =
      settings.passConnected && settings.passKind == kPassLight && isConnected(passFactor_);
  return settings;
}

Instance::~Instance() = default;

FrameRange Instance::sourceRange(int frame) const {
  const OfxRangeD range = clipFrameRange(source_, frame);
  return {nearestFrame(range.min), nearestFrame(range.max)};
}

TemporalPlan Instance::plan(OfxTime time) const {
  const int frame = nearestFrame(time);
  return planFrame(frame, settingsAt(time), sourceRange(frame));
}

void Instance::purgeCaches() { pool_.purge(); }

void Instance::endSequence() { pool_.trim(1); }

OfxRectI Instance::pushFrame(NodeSlot& history, int frame, const PluginSettings& settings,
                             RenderScale scale) const {
  const ClipImage color(source_, frame, kOfxImageEffectSimpleSourceClipName);
  std::optional<ClipImage> depth, motion;
  if (isConnected(depth_)) depth.emplace(depth_, frame, kDepthClip);
  if (isConnected(motion_)) motion.emplace(motion_, frame, kMotionClip);
  if (depth) requireSamePixelAspect(*depth, color);
  if (motion) requireSamePixelAspect(*motion, color);
  if (motion && motion->components() < 2) {
    throw std::runtime_error("the " + motion->where() +
                             " has one channel: motion vectors need RGB or RGBA (x in R, y in G)");
  }
  const OfxRectI& bounds = color.bounds();
  const taa_buffer colorBuffer = color.buffer(0, std::min(color.components(), 4));
  std::optional<AuxBuffer> depthBuffer, motionBuffer;
  if (depth) {
    depthBuffer.emplace(*depth, depthChannel(*depth, unmappedComponents(depth_)), 1, bounds,
                        INFINITY);  // no hit where the host has no depth
  }
  if (motion) {
    // The node scales both components by the x render scale; y needs the y scale.
    motionBuffer.emplace(*motion, 0, 2, bounds, 0.0f, float(scale.y / scale.x));
  }
  taa_frame input;
  taa_frame_init(&input);
  input.frame = frame;
  input.color = &colorBuffer;
  input.depth = depthBuffer ? &depthBuffer->buffer() : nullptr;
  input.motion = motionBuffer ? &motionBuffer->buffer() : nullptr;
  input.has_jitter = 1;
  frameJitter(settings, frame, scale, input.jitter);
  if (!settings.passConnected) {
    if (taa_node_push_frame(history.node, &input) != TAA_OK) {
      throw std::runtime_error(taa_node_last_error(history.node));
    }
    return bounds;
  }
  const ClipImage pass(pass_, frame, kPassClip);
  requireSamePixelAspect(pass, color);
  std::optional<ClipImage> factor;
  if (settings.passFactorConnected) {
    factor.emplace(passFactor_, frame, kPassFactorClip);
    requireSamePixelAspect(*factor, color);
  }
  const PassBuffers passes(settings.passKind, pass, factor ? &*factor : nullptr, bounds);
  if (taa_node_push_frame_passes(history.node, &input, passes.passes().data(),
                                 int(passes.passes().size())) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }
  history.passNames = passChannels(settings.passKind, pass.components(), false).pass;
  return bounds;
}

void Instance::render(OfxTime time, const OfxRectI& window, RenderScale scale) {
  if (!(scale.x > 0.0 && scale.y > 0.0)) {
    throw std::runtime_error("render scale (" + number(scale.x) + ", " + number(scale.y) +
                             ") must be positive");
  }
  const int requested = nearestFrame(time);
  const PluginSettings settings = settingsAt(time);
  if (settings.passConnected && settings.mode != kModeWindow) {
    throw std::runtime_error(
        "the Pass clip is resolved with the window's weights: set Mode to Window, or "
        "disconnect the Pass clip");
  }
  const FrameRange range = sourceRange(requested);
  const TemporalPlan plan = planFrame(requested, settings, range);
  // The idle node that holds most of this render's work: in window mode the most frames of
  // its window, in history mode the frame before it (or the same one), with these settings.
  const auto score = [&](const NodeSlot& slot) {
    if (!slot.node || !slot.settings || *slot.settings != settings || !(slot.scale == scale)) {
      return 0;
    }
    if (settings.mode == kModeWindow) {
      if (!(slot.range == range)) return 0;
      int held = 1;
      for (int f : FrameSpan(plan.frames.first, plan.frames.last)) held += int(slot.ring.count(f));
      return held;
    }
    if (slot.startFrame != plan.frames.first || !slot.lastFrame) return 1;
    if (*slot.lastFrame == plan.frame) return 4;
    return isNextFrame(*slot.lastFrame, plan.frame) ? 3 : 1;
  };
  const std::shared_ptr<NodeSlot> slot =
      pool_.acquire(score, [this] { return suites().effects->abort(effect_) != 0; });
  NodeSlot& history = *slot;
  if (settings.mode == kModeWindow) {
    renderWindow(history, plan, range, settings, scale);
  } else {
    renderHistory(history, plan, settings, scale);
  }
  writeOutput(history, time, window);
}

void Instance::renderHistory(NodeSlot& history, const TemporalPlan& plan,
                             const PluginSettings& settings, RenderScale scale) const {
  if (!history.node && taa_node_create(nullptr, &history.node) != TAA_OK) {
    throw std::runtime_error(taa_last_error());
  }
  const bool sameSetup = history.settings && *history.settings == settings &&
                         history.scale == scale && history.startFrame == plan.frames.first;
  if (!sameSetup) {
    history.lastFrame.reset();
    history.ring.clear();     // another mode's frames, freed by the node with its new mode
    history.settings.reset();  // until applied
    applySettings(history.node, settings, scale);
    history.settings = settings;
    history.scale = scale;
  }
  const int frame = plan.frame;
  const bool holdsFrame = sameSetup && history.lastFrame == frame;
  const bool continues = sameSetup && history.lastFrame && isNextFrame(*history.lastFrame, frame);
  if (!holdsFrame) {
    int from = frame;
    if (!continues) {
      if (taa_node_reset_history(history.node) != TAA_OK) {
        throw std::runtime_error(taa_node_last_error(history.node));
      }
      from = plan.frames.first;
    }
    history.lastFrame.reset();  // until every frame below is in
    for (int f : FrameSpan(from, frame)) {
      if (suites().effects->abort(effect_)) throw std::runtime_error("render aborted by host");
      history.bounds = pushFrame(history, f, settings, scale);
    }
    history.startFrame = plan.frames.first;
    history.lastFrame = frame;
  }
}

void Instance::renderWindow(NodeSlot& history, const TemporalPlan& plan, FrameRange range,
                            const PluginSettings& settings, RenderScale scale) const {
  // The node knows every frame it was given (its windows are taatool's on those frames): a new
  // setup or clip range starts from a new node.
  const bool sameSetup = history.node && history.settings && *history.settings == settings &&
                         history.scale == scale && history.range == range;
  if (!sameSetup) {
    history.forget();
    if (taa_node_create(nullptr, &history.node) != TAA_OK) {
      throw std::runtime_error(taa_last_error());
    }
    applySettings(history.node, settings, scale);
    if (settings.passConnected) {
      // The kinds of the Pass clip's channels, by the names pass_clip gives them.
      const std::string rules = passRules(settings.passKind);
      if (taa_node_set_string(history.node, "aov", rules.c_str()) != TAA_OK) {
        throw std::runtime_error(taa_node_last_error(history.node));
      }
    }
    history.settings = settings;
    history.scale = scale;
    history.range = range;
  }
  // Frames the window does not need leave first, so the ring (2K+1) never has to evict.
  for (auto it = history.ring.begin(); it != history.ring.end();) {
    if (it->first >= plan.frames.first && it->first <= plan.frames.last) {
      ++it;
      continue;
    }
    if (taa_node_drop_frame(history.node, it->first) != TAA_OK) {
      throw std::runtime_error(taa_node_last_error(history.node));
    }
    it = history.ring.erase(it);
  }
  for (int f : FrameSpan(plan.frames.first, plan.frames.last)) {
    if (history.ring.count(f)) continue;
    if (suites().effects->abort(effect_)) throw std::runtime_error("render aborted by host");
    history.ring[f] = pushFrame(history, f, settings, scale);
  }
  if (taa_node_resolve_frame(history.node, plan.frame) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }
  history.bounds = history.ring.at(plan.frame);
}

void Instance::writeOutput(const NodeSlot& history, OfxTime time,
                           const OfxRectI& window) const {
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
  const bool pass = history.settings && history.settings->passConnected;
  if (!pass && taa_node_read_output(history.node, &out) != TAA_OK) {
    throw std::runtime_error(taa_node_last_error(history.node));
  }
  if (pass) readPass(history, out);

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
