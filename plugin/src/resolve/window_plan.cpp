#include "resolve/window_plan.h"

#include <algorithm>
#include <climits>

#include "util/frame_span.h"

namespace taa {

WindowPlan planWindows(const std::vector<int>& outputs, const std::vector<int>& available,
                       const std::set<int>& resets, int radius) {
  std::set<int> exists(available.begin(), available.end());
  exists.insert(outputs.begin(), outputs.end());
  // INT_MIN has no frame before it; INT_MAX none after it (util/frame_span.h).
  auto startsShot = [&](int frame) {
    return frame == INT_MIN || !exists.count(frame - 1) || resets.count(frame);
  };
  auto continuesShot = [&](int frame) {  // whether the frame after `frame` is in its shot
    return frame != INT_MAX && exists.count(frame + 1) && !resets.count(frame + 1);
  };

  WindowPlan plan;
  std::set<int> reads;
  for (int frame : outputs) {
    FrameWindow window{frame, frame};
    const int lowest = offsetFrame(frame, -radius), highest = offsetFrame(frame, radius);
    while (window.first > lowest && !startsShot(window.first)) --window.first;
    while (window.last < highest && continuesShot(window.last)) ++window.last;
    plan.windows[frame] = window;
    for (int f : FrameSpan(window.first, window.last)) reads.insert(f);
  }
  plan.reads.assign(reads.begin(), reads.end());
  for (int frame : plan.reads) {
    if (startsShot(frame)) plan.shotStarts.insert(frame);
  }
  return plan;
}

}  // namespace taa
