// The OpenFX bundle loaded the way a host loads it (test_host): descriptor properties, then
// renders of a generated sequence compared against taatool's output on the same frames.
#include <cmath>
#include <thread>

#include "ofx_host_fixture.h"
#include "taa/options.h"

namespace taa::ofxtest {
namespace {

TEST_F(OfxHostTest, DescriptorDeclaresTemporalAccessDepthsAndContexts) {
  auto effect = instance();
  const PropertySet& p = descriptor_.props;
  EXPECT_EQ(p.getInt(kOfxImageEffectPropTemporalClipAccess), 1);
  const auto depths = p.strings(kOfxImageEffectPropSupportedPixelDepths);
  EXPECT_EQ(depths, (std::vector<std::string>{kOfxBitDepthHalf, kOfxBitDepthFloat}));
  const auto contexts = p.strings(kOfxImageEffectPropSupportedContexts);
  EXPECT_EQ(contexts, (std::vector<std::string>{kOfxImageEffectContextFilter,
                                                 kOfxImageEffectContextGeneral}));
  EXPECT_EQ(p.getInt(kOfxImageEffectPropSupportsTiles), 0);
  EXPECT_EQ(p.getString(kOfxImageEffectPluginRenderThreadSafety), kOfxImageEffectRenderFullySafe);

  const auto& clips = contextDescriptor_.clips;
  for (const char* name : {"Source", "Depth", "Motion", "Output"}) {
    ASSERT_TRUE(clips.count(name)) << name;
  }
  EXPECT_EQ(clips.at("Source").props.getInt(kOfxImageEffectPropTemporalClipAccess), 1);
  EXPECT_EQ(clips.at("Source").props.getInt(kOfxImageClipPropOptional), 0);
  EXPECT_EQ(clips.at("Depth").props.getInt(kOfxImageClipPropOptional), 1);
  EXPECT_EQ(clips.at("Motion").props.getInt(kOfxImageClipPropOptional), 1);
  EXPECT_EQ(clips.at("Output").props.strings(kOfxImageEffectPropSupportedComponents),
            std::vector<std::string>{kOfxImageComponentRGBA});
  const auto& params = contextDescriptor_.params;
  ASSERT_TRUE(params.count("blend"));
  // Defaults are the library's (taatool's), not numbers of the plugin's own.
  EXPECT_DOUBLE_EQ(params.at("blend").props.getDouble(kOfxParamPropDefault),
                   double(ResolveOptions{}.blend));
  for (const char* name : {"rectify", "dilateMotion", "jitter", "jitterOffset", "jitterPeriod",
                           "motionY", "motionTo", "motionScale", "historyFrames",
                           "ocioConfigSource", "ocioConfigFile", "colorspaceIn", "bracket",
                           "colorspaceOut"}) {
    EXPECT_TRUE(params.count(name)) << name;
  }
  EXPECT_EQ(params.at("bracket").props.getString(kOfxParamPropDefault),
            ColorOptions{}.bracket);
  EXPECT_EQ(params.at("ocioConfigFile").props.getString(kOfxParamPropStringMode),
            kOfxParamStringIsFilePath);

  PropertySet filter, filterDescriptor;
  filter.set(kOfxImageEffectPropContext, {std::string(kOfxImageEffectContextFilter)});
  HostEffect filterContext;
  EXPECT_EQ(host_.action(kOfxImageEffectActionDescribeInContext, &filterContext, &filter),
            kOfxStatOK);
  EXPECT_TRUE(filterContext.clips.count("Source") && filterContext.clips.count("Output"));
  destroy(effect);
}

TEST_F(OfxHostTest, FramesNeededReachBackToTheClipStart) {
  auto effect = instance();
  PropertySet in, out;
  in.set(kOfxPropTime, {5.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  for (const char* clip : {"Source", "Depth", "Motion"}) {
    const std::string name = std::string(kOfxImageClipPropFrameRangePrefix) + clip;
    ASSERT_EQ(out.dimension(name), 2) << name;
    EXPECT_EQ(out.getDouble(name, 0), 1.0);
    EXPECT_EQ(out.getDouble(name, 1), 5.0);
  }
  effect->params.at("historyFrames").intValue = 3;
  in.set(kOfxPropTime, {8.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  EXPECT_EQ(out.getDouble(std::string(kOfxImageClipPropFrameRangePrefix) + "Source", 0), 6.0);
  destroy(effect);
}

TEST_F(OfxHostTest, SequentialRenderMatchesTaatool) {
  auto effect = instance();
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  // Frame 8 is not frame 8 alone: the comparison can fail.
  EXPECT_GT(maxDifference(expected(kLast), expected(kLast, "taatool68")), 1e-3f);
  EXPECT_EQ(host_.liveImages(), 0);
  EXPECT_TRUE(host_.messages().empty());
  destroy(effect);
}

// A render at scale 0.5 means images half the size of the render their motion vectors and
// jitter were made for: the plugin scales both, as taatool's --motion-scale and --jitter-scale
// do. (This host hands over the same images at either scale; only the parameters differ.)
TEST_F(OfxHostTest, RenderScaleScalesMotionAndJitterLikeTaatool) {
  auto effect = instance();
  for (int f = kFirst; f <= kLast; ++f) {
    const Image halfScale = render(*effect, f, kOfxStatOK, 0.5);
    EXPECT_LE(maxDifference(halfScale, expected(f, "taatool-half-scale")), 1e-5f) << "frame " << f;
  }
  // The scaled result differs from the full-scale one: the comparison can fail.
  EXPECT_GT(maxDifference(expected(kLast), expected(kLast, "taatool-half-scale")), 1e-3f);
  destroy(effect);
}

TEST_F(OfxHostTest, RandomAccessResolvesFromTheClipStart) {
  auto effect = instance();
  for (int f : {6, 3, 8, 8, 2}) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  destroy(effect);
}

TEST_F(OfxHostTest, HistoryFramesLimitsHistoryLikeTaatoolFrameRange) {
  auto effect = instance();
  effect->params.at("historyFrames").intValue = 3;
  EXPECT_LE(maxDifference(render(*effect, 8), expected(8, "taatool68")), 1e-5f);
  destroy(effect);
}

TEST_F(OfxHostTest, RenderThreadsKeepTheirOwnHistory) {
  auto effect = instance();
  std::vector<Image> forward(kLast + 1), backward(kLast + 1);
  std::thread a([&] {
    for (int f = kFirst; f <= kLast; ++f) forward[f] = render(*effect, f);
  });
  std::thread b([&] {
    for (int f = kLast; f >= kFirst; f -= 3) backward[f] = render(*effect, f);
  });
  a.join();
  b.join();
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_LE(maxDifference(forward[f], expected(f)), 1e-5f) << "frame " << f;
    if (!backward[f].empty()) {
      EXPECT_LE(maxDifference(backward[f], expected(f)), 1e-5f) << "frame " << f;
    }
  }
  destroy(effect);
}

TEST_F(OfxHostTest, HalfImagesStayCloseToTheFloatResult) {
  auto effect = instance(true);
  Image last;
  for (int f = kFirst; f <= kLast; ++f) last = render(*effect, f);
  const Image reference = expected(kLast);
  double sum = 0.0;
  for (std::size_t i = 0; i < last.pixels.size(); ++i) {
    sum += std::fabs(last.pixels[i] - reference.pixels[i]);
  }
  EXPECT_LT(sum / double(last.pixels.size()), 2e-3);
  destroy(effect);
}

// A failed render leaves a persistent message on the effect (hosts show it on the node) that
// names the clip and the frame; the next good render clears it.
TEST_F(OfxHostTest, MissingInputFailsWithAPersistentMessage) {
  auto effect = instance(false, 10.0);  // the clip claims frames up to 10; images end at 8
  render(*effect, 9, kOfxStatFailed);
  const std::string message = host_.persistentMessage(*effect);
  EXPECT_NE(message.find("OfxMessageError: "), std::string::npos) << message;
  EXPECT_NE(message.find("no image for the Source clip at frame 9"), std::string::npos)
      << message;
  EXPECT_EQ(host_.liveImages(), 0);
  render(*effect, 3);
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
