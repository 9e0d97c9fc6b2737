#include "ofx/temporal_plan.h"

#include <algorithm>

namespace taa::ofx {

int sequentialRender(const PluginSettings& settings) {
  return settings.historyFrames > 0 ? 2 : 1;
}

TemporalPlan planFrame(int frame, const PluginSettings& settings, FrameRange source) {
  if (source.last < source.first) source.last = source.first;
  TemporalPlan plan;
  plan.sequentialRender = sequentialRender(settings);
  // History: taatool's result for [start, t]; start is the clip's first frame, or t - N + 1.
  const int last = std::clamp(frame, source.first, source.last);
  int first = source.first;
  if (settings.historyFrames > 0) first = std::max(first, last - settings.historyFrames + 1);
  plan.frames = {first, last};
  return plan;
}

}  // namespace taa::ofx
