// The bundle in window mode (Mode = Window, Window (K)): every frame is taatool
// --mode window's frame bit for bit, whatever order the host renders in; the frames needed are
// t-K..t+K inside the clip; SequentialRender says any order; each render thread keeps its ring
// between renders, so the next frame costs one fetched and pushed frame.
#include <algorithm>
#include <thread>
#include <vector>

#include "ofx_host_fixture.h"
#include "taa/options.h"

namespace taa::ofxtest {
namespace {

constexpr int kRadius = 2;
const std::vector<std::string> kWindowArguments = {"--mode", "window", "--window", "2"};

class OfxHostWindowTest : public OfxHostTest {
 protected:
  // taatool --mode window --window 2 (plus `extra`) on the clip's files.
  static Image expectedWindow(int frame, const std::string& folder = "taatool-window",
                              const std::vector<std::string>& extra = {}) {
    std::vector<std::string> arguments = kWindowArguments;
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return expectedWith(frame, folder, arguments);
  }

  void setWindowMode(HostEffect& effect, int radius = kRadius) {
    effect.params.at("mode").intValue = 1;
    effect.params.at("window").intValue = radius;
    EXPECT_EQ(host_.parameterChanged(effect, "mode"), kOfxStatOK);
    EXPECT_EQ(host_.parameterChanged(effect, "window"), kOfxStatOK);
  }

  // Renders `frames` in that order, each compared with taatool's frame bit for bit.
  void renderAndCompare(HostEffect& effect, const std::vector<int>& frames, const char* order) {
    for (int f : frames) {
      EXPECT_EQ(maxDifference(render(effect, f), expectedWindow(f)), 0.0f)
          << order << ", frame " << f;
    }
  }
};

TEST_F(OfxHostWindowTest, ParametersHaveTheLibrarysDefaults) {
  auto effect = instance();
  const auto& params = contextDescriptor_.params;
  const WindowOptions defaults;
  ASSERT_TRUE(params.count("mode") && params.count("window"));
  EXPECT_EQ(params.at("mode").props.strings(kOfxParamPropChoiceOption),
            (std::vector<std::string>{"History", "Window"}));
  EXPECT_EQ(params.at("mode").props.getInt(kOfxParamPropDefault),
            ResolveOptions{}.mode == ResolveMode::Window ? 1 : 0);
  EXPECT_EQ(params.at("window").props.getInt(kOfxParamPropDefault), defaults.radius);
  EXPECT_EQ(params.at("window").props.getInt(kOfxParamPropMax), 24);  // issue 23: >= 23
  EXPECT_DOUBLE_EQ(params.at("windowSigma").props.getDouble(kOfxParamPropDefault),
                   double(defaults.sigma));
  EXPECT_DOUBLE_EQ(params.at("windowFalloff").props.getDouble(kOfxParamPropDefault),
                   double(defaults.falloff));
  ASSERT_TRUE(params.count("windowTaper"));
  EXPECT_EQ(params.at("windowTaper").props.getInt(kOfxParamPropDefault), defaults.taper ? 1 : 0);
  ASSERT_TRUE(params.count("windowStrata"));
  EXPECT_EQ(params.at("windowStrata").props.getInt(kOfxParamPropDefault),
            defaults.strata ? 1 : 0);
  ASSERT_TRUE(params.count("windowTwoClusters"));
  EXPECT_EQ(params.at("windowTwoClusters").props.getInt(kOfxParamPropDefault),
            defaults.twoClusters ? 1 : 0);
  EXPECT_DOUBLE_EQ(params.at("windowColourTolerance").props.getDouble(kOfxParamPropDefault),
                   double(defaults.colourTolerance));
  EXPECT_DOUBLE_EQ(params.at("windowStaticTolerance").props.getDouble(kOfxParamPropDefault),
                   double(defaults.staticTolerance));
  EXPECT_DOUBLE_EQ(
      params.at("windowReconstructionWeight").props.getDouble(kOfxParamPropDefault),
      double(defaults.reconstructionWeight));
  destroy(effect);
}

// History needs every frame before t (1), window mode none (0); the descriptor declares the
// default mode's value.
TEST_F(OfxHostWindowTest, SequentialRenderFollowsTheMode) {
  auto effect = instance();  // history mode (the fixture's)
  EXPECT_EQ(descriptor_.props.getInt(kOfxImageEffectInstancePropSequentialRender), 0);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 1);
  setWindowMode(*effect);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 0);
  effect->params.at("historyFrames").intValue = 3;  // a history setting changes nothing here
  EXPECT_EQ(host_.parameterChanged(*effect, "historyFrames"), kOfxStatOK);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 0);
  effect->params.at("mode").intValue = 0;
  EXPECT_EQ(host_.parameterChanged(*effect, "mode"), kOfxStatOK);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 2);
  destroy(effect);
}

TEST_F(OfxHostWindowTest, FramesNeededAreTheWindowInsideTheClip) {
  auto effect = instance();
  setWindowMode(*effect);
  const std::vector<std::pair<double, std::pair<double, double>>> cases = {
      {1.0, {1.0, 3.0}}, {2.0, {1.0, 4.0}}, {5.0, {3.0, 7.0}},  {7.0, {5.0, 8.0}},
      {8.0, {6.0, 8.0}}, {10.0, {6.0, 8.0}}, {-3.0, {1.0, 3.0}}};
  for (const auto& [time, range] : cases) {
    PropertySet in, out;
    in.set(kOfxPropTime, {time});
    ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
              kOfxStatOK);
    for (const char* clip : {"Source", "Depth", "Motion"}) {
      const std::string name = std::string(kOfxImageClipPropFrameRangePrefix) + clip;
      ASSERT_EQ(out.dimension(name), 2) << name;
      EXPECT_EQ(out.getDouble(name, 0), range.first) << name << " at " << time;
      EXPECT_EQ(out.getDouble(name, 1), range.second) << name << " at " << time;
    }
  }
  destroy(effect);
}

TEST_F(OfxHostWindowTest, AnyRenderOrderGivesTaatoolsFrames) {
  auto effect = instance();
  setWindowMode(*effect);
  // The comparison can fail: the window's frame is not the history's.
  EXPECT_GT(maxDifference(expectedWindow(5), expected(5)), 1e-3f);
  std::vector<int> frames;
  for (int f = kFirst; f <= kLast; ++f) frames.push_back(f);
  renderAndCompare(*effect, frames, "in order");
  std::reverse(frames.begin(), frames.end());
  renderAndCompare(*effect, frames, "reversed");
  renderAndCompare(*effect, {5, 2, 8, 1, 7, 3, 6, 4, 4}, "shuffled");
  // Outside the clip: its end frames, held.
  EXPECT_EQ(maxDifference(render(*effect, 10), expectedWindow(kLast)), 0.0f);
  EXPECT_EQ(maxDifference(render(*effect, -3), expectedWindow(kFirst)), 0.0f);
  EXPECT_EQ(host_.liveImages(), 0);
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  destroy(effect);
}

// The ring stays between renders on a thread: a frame next to the last one fetches (and
// pushes) the one frame its window lacks; the same frame again fetches nothing. A new setting
// or purge caches starts from an empty ring.
TEST_F(OfxHostWindowTest, TheNextFrameFetchesOneFrame) {
  auto effect = instance();
  setWindowMode(*effect);
  const HostClip& source = effect->clips.at("Source");
  auto fetched = [&](int frame) {
    const int before = source.imagesServed;
    EXPECT_EQ(maxDifference(render(*effect, frame), expectedWindow(frame)), 0.0f) << frame;
    return source.imagesServed - before;
  };
  EXPECT_EQ(fetched(3), 5);  // 1-5
  EXPECT_EQ(fetched(4), 1);  // 6
  EXPECT_EQ(fetched(5), 1);  // 7
  EXPECT_EQ(fetched(5), 0);
  EXPECT_EQ(fetched(4), 1);  // 2 again
  EXPECT_EQ(fetched(8), 2);  // 6 held, 2-5 dropped: 7 and 8
  EXPECT_EQ(host_.action(kOfxActionPurgeCaches, effect.get()), kOfxStatOK);
  EXPECT_EQ(fetched(7), 4);  // 5-8
  // Window Sigma reaches the resolve (the two frames differ) and starts an empty ring.
  EXPECT_GT(maxDifference(expectedWindow(7),
                          expectedWindow(7, "taatool-window-sigma", {"--window-sigma", "0.5"})),
            1e-3f);
  effect->params.at("windowSigma").doubleValue = 0.5;
  EXPECT_EQ(host_.parameterChanged(*effect, "windowSigma"), kOfxStatOK);
  const int before = source.imagesServed;
  EXPECT_EQ(maxDifference(render(*effect, 7),
                          expectedWindow(7, "taatool-window-sigma", {"--window-sigma", "0.5"})),
            0.0f);
  EXPECT_EQ(source.imagesServed - before, 4);
  destroy(effect);
}

// A render at scale 0.5 scales motion and jitter as taatool's --motion-scale and --jitter-scale.
TEST_F(OfxHostWindowTest, RenderScaleScalesMotionAndJitterLikeTaatool) {
  auto effect = instance();
  setWindowMode(*effect);
  const auto halfScale = [](int f) {
    return expectedWindow(f, "taatool-window-half-scale",
                          {"--jitter-scale", "0.5", "--motion-scale", "0.5"});
  };
  for (int f : {4, 5, 1}) {
    EXPECT_EQ(maxDifference(render(*effect, f, kOfxStatOK, 0.5), halfScale(f)), 0.0f)
        << "frame " << f;
  }
  // The scaled result differs from the full-scale one: the comparison can fail.
  EXPECT_GT(maxDifference(expectedWindow(4), halfScale(4)), 1e-3f);
  destroy(effect);
}

TEST_F(OfxHostWindowTest, RenderThreadsKeepTheirOwnRing) {
  auto effect = instance();
  setWindowMode(*effect);
  std::vector<Image> forward(kLast + 1), backward(kLast + 1);
  std::thread a([&] {
    for (int f = kFirst; f <= kLast; ++f) forward[f] = render(*effect, f);
  });
  std::thread b([&] {
    for (int f = kLast; f >= kFirst; --f) backward[f] = render(*effect, f);
  });
  a.join();
  b.join();
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_EQ(maxDifference(forward[f], expectedWindow(f)), 0.0f) << "frame " << f;
    EXPECT_EQ(maxDifference(backward[f], expectedWindow(f)), 0.0f) << "frame " << f;
  }
  destroy(effect);
}

// Switching modes on an instance that has rendered: each mode's frames are still taatool's.
TEST_F(OfxHostWindowTest, SwitchingModesKeepsBothExact) {
  auto effect = instance();
  for (int f = kFirst; f <= 3; ++f) render(*effect, f);
  setWindowMode(*effect);
  EXPECT_EQ(maxDifference(render(*effect, 4), expectedWindow(4)), 0.0f);
  effect->params.at("mode").intValue = 0;
  EXPECT_EQ(host_.parameterChanged(*effect, "mode"), kOfxStatOK);
  EXPECT_LE(maxDifference(render(*effect, 4), expected(4)), 1e-5f);
  EXPECT_LE(maxDifference(render(*effect, 5), expected(5)), 1e-5f);
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
