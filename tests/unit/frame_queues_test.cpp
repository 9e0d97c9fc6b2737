// The write-behind queue reports each write in order, as soon as the next frame is pushed after
// it finished (issue 25: PROGRESS lines trailed the renames by up to two frames).
#include "resolve/frame_queues.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace taa {
namespace {

TEST(WriteBehind, AFinishedWriteIsReportedWhenTheNextFrameIsPushed) {
  std::vector<int> reported;
  std::atomic<int> written{0};
  WriteBehind writes(2, [&](int index) { reported.push_back(index); });
  writes.push(([&] { ++written; }), 0);
  while (written < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::atomic<bool> release{false};
  writes.push(([&] {
                while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
              }),
              1);
  EXPECT_EQ(reported, (std::vector<int>{0}));  // not held until the queue fills
  release = true;
  writes.finish();
  EXPECT_EQ(reported, (std::vector<int>{0, 1}));
}

TEST(WriteBehind, ReportsInOrderWhateverOrderWritesFinishIn) {
  std::vector<int> reported;
  std::atomic<bool> releaseFirst{false};
  WriteBehind writes(3, [&](int index) { reported.push_back(index); });
  writes.push(([&] {
                while (!releaseFirst) std::this_thread::sleep_for(std::chrono::milliseconds(1));
              }),
              0);
  writes.push([] {}, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  writes.push([] {}, 2);
  EXPECT_TRUE(reported.empty());  // 1 and 2 wait for 0
  releaseFirst = true;
  writes.finish();
  EXPECT_EQ(reported, (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace taa
