// Render threads share the instance's nodes under a bound (ofx/node_pool.h, issue 24: one node
// per thread held ~625 MB each at 1080p until PurgeCaches). Eight threads rendering at once
// get taatool's frames bit for bit, while at most the pool's two nodes fetch and hold images.
#include <thread>
#include <vector>

#include "ofx_host_fixture.h"

namespace taa::ofxtest {
namespace {

class OfxHostPoolTest : public OfxHostTest {
 protected:
  static Image expectedWindow(int frame) {
    return expectedWith(frame, "taatool-window", {"--mode", "window", "--window", "2"});
  }
  void setWindowMode(HostEffect& effect) {
    effect.params.at("mode").intValue = 1;
    effect.params.at("window").intValue = 2;
    EXPECT_EQ(host_.parameterChanged(effect, "mode"), kOfxStatOK);
    EXPECT_EQ(host_.parameterChanged(effect, "window"), kOfxStatOK);
  }
};

TEST_F(OfxHostPoolTest, EightThreadsShareTwoNodesAndGetTaatoolsFrames) {
  auto effect = instance();
  setWindowMode(*effect);
  constexpr int kThreads = 8;
  for (int f = kFirst; f <= kLast; ++f) expectedWindow(f);  // taatool's runs before the threads
  std::vector<std::vector<Image>> results(kThreads, std::vector<Image>(kLast + 1));
  host_.peakLiveImages();  // reset
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < kLast; ++i) {
        const int f = kFirst + (i + t) % kLast;  // each thread in its own order
        OutputImage output;
        if (host_.render(*effect, f, output) == kOfxStatOK) results[t][f] = output.toImage();
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) {
    for (int f = kFirst; f <= kLast; ++f) {
      EXPECT_EQ(maxDifference(results[t][f], expectedWindow(f)), 0.0f) << t << " frame " << f;
    }
  }
  // A render holds at most one frame's three images (Source, Depth, Motion) at a time, and
  // only while it has a node: two nodes, at most six. One node per thread held up to 24.
  const int peak = host_.peakLiveImages();
  EXPECT_GE(peak, 3);
  EXPECT_LE(peak, 6);
  EXPECT_EQ(host_.liveImages(), 0);
  EXPECT_EQ(host_.action(kOfxImageEffectActionEndSequenceRender, effect.get()), kOfxStatOK);
  // The node kept is one that holds frames: rendering again is exact and needs no new setup.
  EXPECT_EQ(maxDifference(render(*effect, 4), expectedWindow(4)), 0.0f);
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
