// Which frames a window job reads and which frames each output's window spans
// (resolve/window_plan): windows stop at the shot's ends, gaps and reset frames, and depend on
// the frames that exist, not on the frames asked for.
#include <gtest/gtest.h>

#include <limits>
#include <numeric>
#include <random>

#include "resolve/window_plan.h"

namespace taa {
namespace {

std::vector<int> range(int first, int last) {
  std::vector<int> frames(std::size_t(last - first + 1));
  std::iota(frames.begin(), frames.end(), first);
  return frames;
}

void expectWindow(const WindowPlan& plan, int frame, int first, int last) {
  ASSERT_TRUE(plan.windows.count(frame)) << frame;
  EXPECT_EQ(plan.windows.at(frame).first, first) << "frame " << frame;
  EXPECT_EQ(plan.windows.at(frame).last, last) << "frame " << frame;
}

TEST(WindowPlan, WindowsStopAtTheShotsEnds) {
  const WindowPlan plan = planWindows({1, 5, 10}, range(1, 10), {}, 2);
  expectWindow(plan, 1, 1, 3);
  expectWindow(plan, 5, 3, 7);
  expectWindow(plan, 10, 8, 10);
  EXPECT_EQ(plan.reads, range(1, 10));
  EXPECT_EQ(plan.shotStarts, (std::set<int>{1}));
}

TEST(WindowPlan, GapsAndResetFramesSplitShots) {
  std::vector<int> available = range(1, 4);  // 5 is missing
  for (int f : range(6, 12)) available.push_back(f);
  const WindowPlan plan = planWindows({4, 6, 9, 10}, available, {10}, 3);
  expectWindow(plan, 4, 1, 4);    // stops before the gap
  expectWindow(plan, 6, 6, 9);    // starts after it, stops before the reset frame 10
  expectWindow(plan, 9, 6, 9);
  expectWindow(plan, 10, 10, 12);  // the reset frame starts a shot
  EXPECT_EQ(plan.shotStarts, (std::set<int>{1, 6, 10}));
  EXPECT_EQ(plan.reads, (std::vector<int>{1, 2, 3, 4, 6, 7, 8, 9, 10, 11, 12}));
}

// What a farm relies on: a frame's window is the same whether it is resolved alone, in a
// chunk, or in a run over the whole shot.
TEST(WindowPlan, AFramesWindowDoesNotDependOnTheOtherFramesAskedFor) {
  const std::vector<int> shot = range(1001, 1040);
  const WindowPlan whole = planWindows(shot, shot, {1020}, 4);
  for (const std::vector<int>& chunk :
       {range(1001, 1010), range(1017, 1023), std::vector<int>{1040}, std::vector<int>{1019}}) {
    const WindowPlan part = planWindows(chunk, shot, {1020}, 4);
    for (int frame : chunk) {
      expectWindow(part, frame, whole.windows.at(frame).first, whole.windows.at(frame).last);
    }
  }
}

TEST(WindowPlan, ZeroRadiusReadsTheOutputsAlone) {
  const WindowPlan plan = planWindows({3, 7}, range(1, 10), {}, 0);
  expectWindow(plan, 3, 3, 3);
  expectWindow(plan, 7, 7, 7);
  EXPECT_EQ(plan.reads, (std::vector<int>{3, 7}));
}

// Issue 25, defect 2: a frame numbered INT_MAX made the plan's loop over its window wrap around
// and read without end. Frames at both ends of the int range, and random ones anywhere in it,
// get the window of the frames that exist, and nothing beyond them.
TEST(WindowPlan, FramesAtTheEndsOfTheIntRangeHaveBoundedWindows) {
  const int top = std::numeric_limits<int>::max(), bottom = std::numeric_limits<int>::min();
  const WindowPlan high = planWindows({top - 1, top}, {top - 1, top}, {}, 4);
  expectWindow(high, top, top - 1, top);
  expectWindow(high, top - 1, top - 1, top);
  EXPECT_EQ(high.reads, (std::vector<int>{top - 1, top}));
  const WindowPlan low = planWindows({bottom}, {bottom, bottom + 1, bottom + 2}, {}, 1);
  expectWindow(low, bottom, bottom, bottom + 1);
  EXPECT_EQ(low.shotStarts, (std::set<int>{bottom}));
  const WindowPlan huge = planWindows({top}, {top}, {}, top);  // any radius
  expectWindow(huge, top, top, top);

  std::mt19937 random(25);
  for (int round = 0; round < 200; ++round) {
    const int radius = int(random() % 9);
    std::vector<int> frames;
    const int start = round % 3 == 0 ? top - int(random() % 6)
                    : round % 3 == 1 ? bottom + int(random() % 6)
                                     : int(random());
    for (long long f = start; f <= std::min<long long>(top, (long long)start + 5); ++f) {
      frames.push_back(int(f));
    }
    const WindowPlan plan = planWindows({frames.back()}, frames, {}, radius);
    const FrameWindow window = plan.windows.at(frames.back());
    EXPECT_GE(window.first, frames.front());
    EXPECT_EQ(window.last, frames.back());
    EXPECT_LE(plan.reads.size(), frames.size());
  }
}

}  // namespace
}  // namespace taa
