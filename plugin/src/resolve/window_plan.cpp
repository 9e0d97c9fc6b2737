#include "resolve/window_plan.h"

#include <algorithm>

namespace taa {

WindowPlan planWindows(const std::vector<int>& outputs, const std::vector<int>& available,
                       const std::set<int>& resets, int radius) {
  std::set<int> exists(available.begin(), available.end());
  exists.insert(outputs.begin(), outputs.end());
  auto startsShot = [&](int frame) { return !exists.count(frame - 1) || resets.count(frame); };

  WindowPlan plan;
  std::set<int> reads;
  for (int frame : outputs) {
    FrameWindow window{frame, frame};
    while (window.first > frame - radius && !startsShot(window.first)) --window.first;
    while (window.last < frame + radius && exists.count(window.last + 1) &&
           !resets.count(window.last + 1)) {
      ++window.last;
    }
    plan.windows[frame] = window;
    for (int f = window.first; f <= window.last; ++f) reads.insert(f);
  }
  plan.reads.assign(reads.begin(), reads.end());
  for (int frame : plan.reads) {
    if (startsShot(frame)) plan.shotStarts.insert(frame);
  }
  return plan;
}

}  // namespace taa
