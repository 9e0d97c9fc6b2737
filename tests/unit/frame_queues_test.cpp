// The write-behind queue reports each write in order, as soon as the next frame is pushed after
// it finished (issue 25: PROGRESS lines trailed the renames by up to two frames).
#include "resolve/frame_queues.h"

#include "resolve/sequence_job.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
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

// The window run reads its first frame at depth 0 and sets the depth once it knows whether the
// frames carry passes: the reads after that go ahead on other threads, up to the new depth.
TEST(ReadAhead, ADepthSetLaterAppliesToTheReadsStartedAfterIt) {
  std::mutex mutex;
  std::vector<std::thread::id> readers(8);
  std::vector<int> waited(8, -1);  // whether each read was told its caller waits for it
  std::atomic<int> started{0};
  ReadAhead reads({0, 1, 2, 3, 4, 5, 6, 7}, 0, [&](int frame, bool callerWaits) {
    ++started;
    std::lock_guard<std::mutex> lock(mutex);
    readers[std::size_t(frame)] = std::this_thread::get_id();
    waited[std::size_t(frame)] = callerWaits;
    io::FrameData data;
    data.frame = frame;
    return data;
  });
  EXPECT_EQ(reads.next().frame, 0);
  EXPECT_EQ(readers[0], std::this_thread::get_id());  // depth 0: on the calling thread
  EXPECT_EQ(started, 1);
  reads.setDepth(2);
  EXPECT_EQ(reads.next().frame, 1);  // started at depth 0 (deferred): runs here, now
  EXPECT_EQ(readers[1], std::this_thread::get_id());
  EXPECT_EQ(reads.next().frame, 2);
  EXPECT_NE(readers[2], std::this_thread::get_id());  // at depth 2: on a worker thread
  // Only the reads the caller waits for may take every core (io/part_channels' threads).
  EXPECT_EQ(waited[0], 1);
  EXPECT_EQ(waited[1], 1);
  EXPECT_EQ(waited[2], 0);
  // Frames 3 to 5 go ahead (the frame after the one taken, and two more), not frame 6.
  while (started < 6) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(started, 6);
}

TEST(IoDepth, PassesInTheWindowResolveReadAndWriteOneStepAfterAnotherUnlessAsked) {
  SequenceJob job;
  job.resolve.mode = ResolveMode::Window;
  EXPECT_EQ(job.ioThreads, kAutoIoThreads);
  EXPECT_EQ(ioDepthOf(job, false), 2);
  EXPECT_EQ(ioDepthOf(job, true), 0);
  job.ioThreads = 3;
  EXPECT_EQ(ioDepthOf(job, true), 3);
  job.ioThreads = kAutoIoThreads;
  job.resolve.mode = ResolveMode::History;
  EXPECT_EQ(ioDepthOf(job, true), 2);
}

}  // namespace
}  // namespace taa
