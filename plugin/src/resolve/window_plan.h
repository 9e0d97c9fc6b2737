// Which frames the window resolve reads for a job and which frames each output frame's window
// spans. Shots are runs of consecutive frames that exist, split at reset frames; a window
// never crosses a shot's ends. The plan depends on the frames that exist, not on the frames
// asked for, so resolving a sub-range reads what a whole-shot run reads around it and gives
// the same frames.
#pragma once

#include <map>
#include <set>
#include <vector>

namespace taa {

struct FrameWindow {
  int first = 0, last = 0;  // inclusive
};

struct WindowPlan {
  std::vector<int> reads;               // every frame some window uses, ascending
  std::map<int, FrameWindow> windows;   // output frame -> its window
  std::set<int> shotStarts;             // frames whose shot has no earlier frame
};

// `outputs`: frames to resolve; `available`: frames that exist (outputs count as existing);
// `resets`: frames that start a shot; `radius`: K.
WindowPlan planWindows(const std::vector<int>& outputs, const std::vector<int>& available,
                       const std::set<int>& resets, int radius);

}  // namespace taa
