// The bounded node pool of the OpenFX plugin (ofx/node_pool.h), without a host or GL: at most
// maxNodes slots exist and are in use at once, however many threads ask; a render gets the
// idle slot that holds most of its work; EndSequenceRender's trim and PurgeCaches free them.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "ofx/node_pool.h"

namespace taa::ofx {
namespace {

TEST(NodePool, AtMostMaxNodesAreInUseWhateverTheThreads) {
  NodePool pool(2);
  std::atomic<int> inUse{0}, most{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 20; ++i) {
        auto slot = pool.acquire([](const NodeSlot&) { return 0; }, nullptr);
        const int now = ++inUse;
        for (int seen = most; now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        --inUse;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(most, 2);
  EXPECT_EQ(pool.size(), 2u);
  EXPECT_EQ(pool.peakSize(), 2u);
  pool.trim(1);  // the end of a sequence render
  EXPECT_EQ(pool.size(), 1u);
  pool.purge();
  EXPECT_EQ(pool.size(), 0u);
}

TEST(NodePool, TheIdleSlotHoldingMostOfTheWorkIsTaken) {
  NodePool pool(3);
  std::vector<std::shared_ptr<NodeSlot>> held;
  for (int i = 0; i < 3; ++i) {
    held.push_back(pool.acquire([](const NodeSlot&) { return 0; }, nullptr));
    held.back()->startFrame = 10 * i;  // a mark to find each by
  }
  held.clear();  // all three idle now
  auto slot = pool.acquire([](const NodeSlot& s) { return s.startFrame == 10 ? 5 : 1; }, nullptr);
  EXPECT_EQ(slot->startFrame, 10);
  EXPECT_EQ(pool.size(), 3u);
}

TEST(NodePool, AWaitingRenderStopsWhenTheHostAborts) {
  NodePool pool(1);
  auto slot = pool.acquire([](const NodeSlot&) { return 0; }, nullptr);
  try {
    pool.acquire([](const NodeSlot&) { return 0; }, [] { return true; });
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("render aborted by host while waiting"),
              std::string::npos)
        << e.what();
  }
}

TEST(NodePool, TheBoundComesFromTheEnvironment) {
  unsetenv("TAA_OFX_RENDER_NODES");
  EXPECT_EQ(renderNodesFromEnvironment(), 2u);
  setenv("TAA_OFX_RENDER_NODES", "5", 1);
  EXPECT_EQ(renderNodesFromEnvironment(), 5u);
  setenv("TAA_OFX_RENDER_NODES", "0", 1);  // out of range: the default
  EXPECT_EQ(renderNodesFromEnvironment(), 2u);
  unsetenv("TAA_OFX_RENDER_NODES");
}

}  // namespace
}  // namespace taa::ofx
