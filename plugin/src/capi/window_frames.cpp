#include "capi/window_frames.h"

#include <cstdlib>
#include <utility>
#include <vector>

#include "capi/status_error.h"
#include "resolve/option_registry.h"
#include "resolve/window_plan.h"
#include "taa/error.h"
#include "util/frame_span.h"

namespace taa::capi {
namespace {

std::string textOf(const ResolveOptions& options) {
  std::string text;
  for (const OptionInfo& option : resolveOptionList()) {
    text += option.name + "=" + resolveOptionValue(options, option.name) + ";";
  }
  return text;
}

// "1-3, 6" for {1, 2, 3, 6}; "no frames" for none.
std::string describeFrames(const std::set<int>& frames) {
  std::string text;
  for (auto it = frames.begin(); it != frames.end();) {
    const int first = *it;
    int last = first;
    for (++it; it != frames.end() && *it == last + 1; ++it) last = *it;
    text += (text.empty() ? "" : ", ") + std::to_string(first);
    if (last != first) text += "-" + std::to_string(last);
  }
  return text.empty() ? "no frames" : "frames " + text;
}

std::string sizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

WindowFrames::WindowFrames(gl::Context& context, const ResolveOptions& options,
                           double ringBudget)
    : context_(context),
      options_(options),
      optionsText_(textOf(options)),
      ringBudget_(ringBudget),
      radius_(options.window.radius),
      resolver_(std::make_unique<WindowResolver>(context, options)) {}

WindowFrames::~WindowFrames() = default;

int WindowFrames::radiusFor(const ResolveOptions& options, int width, int height) const {
  const bool withPasses = passPlan_ && !passPlan_->names.empty();
  const double frameBytes =
      ringBytesPerPixel(withPasses ? &*passPlan_ : nullptr) * double(width) * double(height);
  const int k = windowRadiusWithinBudget(options.window.radius, options.window.nearRadius,
                                         frameBytes, withPasses, ringBudget_);
  return windowRadiusTheGlHolds(context_, k, width, height);
}

std::unique_ptr<WindowResolver> WindowFrames::makeResolver(const ResolveOptions& options,
                                                           int radius) const {
  ResolveOptions within = options;
  within.window.radius = radius;
  auto resolver = std::make_unique<WindowResolver>(context_, within);
  if (passPlan_) resolver->setPasses(passPlan_->halfGroups, int(passPlan_->cryptomatte.size()));
  return resolver;
}

void WindowFrames::setOptions(const ResolveOptions& options) {
  std::string text = textOf(options);
  if (text == optionsText_) return;
  const int radius = size_ ? radiusFor(options, size_->first, size_->second)
                           : options.window.radius;
  auto resolver = makeResolver(options, radius);
  for (int frame : std::set<int>(ring_)) {
    remove(frame, "removed when a resolve parameter changed (the ring starts empty)");
  }
  resolver_ = std::move(resolver);
  radius_ = radius;
  options_ = options;
  optionsText_ = std::move(text);
}

void WindowFrames::fitRing(int width, int height, const std::string& pushed) {
  const int radius = radiusFor(options_, width, height);
  if (radius == radius_) return;
  auto resolver = makeResolver(options_, radius);
  for (int held : std::set<int>(ring_)) {
    remove(held, "removed when " + pushed + ": its passes' memory makes the window K " +
                     std::to_string(radius) + ", not " + std::to_string(radius_));
  }
  resolver_ = std::move(resolver);
  radius_ = radius;
}

void WindowFrames::remove(int frame, const std::string& why) {
  resolver_->dropFrame(frame);
  ring_.erase(frame);
  matrices_.erase(frame);
  keptPasses_.erase(frame);
  removed_[frame] = why;
}

int WindowFrames::farthestFrom(int frame) const {
  // ring_ is ascending: on a tie the earlier frame, found first, is kept as the answer.
  const auto distance = [frame](int held) { return std::llabs((long long)held - frame); };
  int farthest = *ring_.begin();
  for (int held : ring_) {
    if (distance(held) > distance(farthest)) farthest = held;
  }
  return farthest;
}

void WindowFrames::usePasses(std::optional<PassPlan> plan, const std::string& pushed) {
  const auto sameChannels = [](const PassPlan& a, const PassPlan& b) {
    return a.names == b.names && a.formats == b.formats && a.kinds == b.kinds;
  };
  if (plan.has_value() == passPlan_.has_value() &&
      (!plan || sameChannels(*plan, *passPlan_))) {
    return;
  }
  for (int held : std::set<int>(ring_)) {
    remove(held, "removed when " + pushed + " with other passes (every frame in the ring "
                 "carries the same pass channels)");
  }
  resolver_->setPasses(plan ? plan->halfGroups : std::vector<bool>(),
                       plan ? int(plan->cryptomatte.size()) : 0);
  passPlan_ = std::move(plan);
}

void WindowFrames::push(int frame, const ResolveInput& input, bool startsShot,
                        const FrameMatrices& matrices, const FramePasses* passes) {
  // Planned before anything changes: a refused push leaves the ring as it was.
  std::optional<PassPlan> plan;
  if (passes) {
    try {
      plan = planPasses(passes->names, passes->types, passes->rules);
    } catch (const Error& e) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        "frame " + std::to_string(frame) + "'s passes: " + e.what());
    }
  }
  const int width = input.color.width, height = input.color.height;
  const bool othersHeld = ring_.size() > (ring_.count(frame) ? 1u : 0u);
  const bool newSize = size_ && *size_ != std::make_pair(width, height);
  if (othersHeld && newSize && !startsShot) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                      "frame " + std::to_string(frame) + " is " + sizeText(width, height) +
                          " but the frames in the ring are " +
                          sizeText(size_->first, size_->second) +
                          ": a frame of another size must start a shot "
                          "(taa_node_reset_history before pushing it)");
  }
  if (ring_.count(frame)) remove(frame, "");  // replaced below
  const std::string pushed = "frame " + std::to_string(frame) + " was pushed";
  usePasses(std::move(plan), pushed);
  fitRing(width, height, pushed);
  if (newSize) {
    for (int held : std::set<int>(ring_)) {
      remove(held, "removed when " + pushed + " with another size, starting a shot");
    }
  } else if (int(ring_.size()) >= resolver_->capacity()) {
    remove(farthestFrom(frame), "evicted when " + pushed + " into the full ring of " +
                                    std::to_string(resolver_->capacity()) + " frames");
  }
  PackedPasses packed;
  ResolveInput withPasses = input;
  if (passPlan_) {
    packed = packPasses(passes->values, *passPlan_);
    for (const TypedImage& group : packed.groups) withPasses.passGroups.emplace_back(&group);
    for (const Image& set : packed.cryptomatte) withPasses.cryptomatte.emplace_back(&set);
  }
  try {
    resolver_->addFrame(frame, withPasses);
  } catch (const Error& e) {
    resolver_->dropFrame(frame);  // whatever part of it was stored
    removed_[frame] = "its push failed";
    throw StatusError(TAA_ERROR_INTERNAL, "frame " + std::to_string(frame) + ": " + e.what());
  }
  ring_.insert(frame);
  matrices_[frame] = matrices;
  if (passPlan_) keptPasses_[frame] = std::move(packed.kept);
  size_ = std::make_pair(width, height);
  known_.insert(frame);
  removed_.erase(frame);
  if (startsShot) shotStarts_.insert(frame);
}

void WindowFrames::drop(int frame) {
  if (ring_.count(frame)) remove(frame, "dropped (taa_node_drop_frame)");
}

std::string WindowFrames::missingMessage(int missing, int frame, int first, int last) const {
  std::string what = "frame " + std::to_string(missing);
  if (missing != frame) {
    what += " of frame " + std::to_string(frame) + "'s window (frames " + std::to_string(first) +
            "-" + std::to_string(last) + ")";
  }
  const auto why = removed_.find(missing);
  return what + " is not in the ring: it was " +
         (why == removed_.end() ? std::string("never pushed") : why->second) +
         "; push it again (the ring holds " + describeFrames(ring_) + ")";
}

TypedImage WindowFrames::resolve(int frame, SampleType outputType) {
  if (!known_.count(frame)) {
    throw StatusError(TAA_ERROR_MISSING_FRAME,
                      "frame " + std::to_string(frame) + " has not been pushed (the ring holds " +
                          describeFrames(ring_) + ")");
  }
  // taatool's rule on the frames pushed so far: consecutive frames within K, in one shot.
  const WindowPlan plan =
      planWindows({frame}, std::vector<int>(known_.begin(), known_.end()), shotStarts_,
                  radius_);
  const FrameWindow window = plan.windows.at(frame);
  // The frame itself first: its absence says more than a neighbour's.
  if (!ring_.count(frame)) {
    throw StatusError(TAA_ERROR_MISSING_FRAME,
                      missingMessage(frame, frame, window.first, window.last));
  }
  for (int f : FrameSpan(window.first, window.last)) {
    if (!ring_.count(f)) {
      throw StatusError(TAA_ERROR_MISSING_FRAME,
                        missingMessage(f, frame, window.first, window.last));
    }
  }
  try {
    TypedImage output = resolver_->resolve(frame, window.first, window.last, outputType);
    resolvedPasses_ = Image();
    if (passPlan_ && !passPlan_->empty()) {
      resolvedPasses_ = finishPasses(resolver_->takePassSums(), keptPasses_.at(frame), *passPlan_);
    }
    return output;
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_INTERNAL, "frame " + std::to_string(frame) + ": " + e.what());
  }
}

const FrameMatrices& WindowFrames::matrices(int frame) const { return matrices_.at(frame); }

}  // namespace taa::capi
