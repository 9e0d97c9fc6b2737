#include "ofx/temporal_plan.h"

#include <algorithm>

#include "util/frame_span.h"

namespace taa::ofx {

int sequentialRender(const PluginSettings& settings) {
  if (settings.mode == kModeWindow) return 0;
  return settings.historyFrames > 0 ? 2 : 1;
}

TemporalPlan planFrame(int frame, const PluginSettings& settings, FrameRange source) {
  if (source.last < source.first) source.last = source.first;
  TemporalPlan plan;
  plan.sequentialRender = sequentialRender(settings);
  plan.frame = std::clamp(frame, source.first, source.last);
  if (settings.mode == kModeWindow) {
    // taatool's window on the clip's frames: t-K..t+K, stopping at the clip's ends.
    plan.frames = {std::max(source.first, offsetFrame(plan.frame, -settings.windowRadius)),
                   std::min(source.last, offsetFrame(plan.frame, settings.windowRadius))};
    return plan;
  }
  // History: taatool's result for [start, t]; start is the clip's first frame, or t - N + 1.
  int first = source.first;
  if (settings.historyFrames > 0) {
    first = std::max(first, offsetFrame(plan.frame, 1LL - settings.historyFrames));
  }
  plan.frames = {first, plan.frame};
  return plan;
}

}  // namespace taa::ofx
