// The OpenFX bundle loaded the way a host loads it (test_host): descriptor properties, then
// renders of a generated sequence compared against taatool's output on the same frames.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <unistd.h>

#include "scenegen/exr_output.h"
#include "taa/options.h"
#include "scenegen/scene_library.h"
#include "test_host.h"

namespace taa::ofxtest {
namespace {

namespace fs = std::filesystem;

constexpr int kFirst = 1, kLast = 8;
const OfxRectI kBounds = {10, 20, 10 + 64, 20 + 40};  // offset bounds exercise the mapping

// The bundle binary under OFX_PLUGIN_PATH's first folder, or the build tree's bundle folder.
std::string bundleBinary() {
  std::string root = TAA_OFX_BUNDLE_DIR;
  if (const char* path = std::getenv("OFX_PLUGIN_PATH"); path && *path) {
    root = std::string(path).substr(0, std::string(path).find(':'));
  }
  return root + "/TAAResolve.ofx.bundle/Contents/Linux-x86-64/TAAResolve.ofx";
}

Image readChannels(const std::string& path, const std::vector<std::string>& names) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> all(std::size_t(spec.width) * spec.height * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data());
  Image image(spec.width, spec.height, int(names.size()));
  for (int c = 0; c < int(names.size()); ++c) {
    const int source = spec.channelindex(names[c]);
    if (source < 0) throw std::runtime_error("no channel " + names[c] + " in " + path);
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
      image.pixels[p * names.size() + c] = all[p * spec.nchannels + source];
    }
  }
  return image;
}

float maxDifference(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return INFINITY;
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    worst = std::max(worst, std::fabs(a.pixels[i] - b.pixels[i]));
  }
  return worst;
}

int runTaatool(const std::string& args) {
  return std::system((std::string("'") + TAA_TAATOOL_PATH + "' " + args + " -q").c_str());
}

class OfxHostTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // CTest runs each test of the suite as its own process, possibly in parallel.
    dir_ = fs::path(TAA_TEST_TMPDIR) / ("sequence_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    auto scene = scenes::makeScene("moving_object", 64, 40);
    scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 1;
    for (int f = kFirst; f <= kLast; ++f) {
      scenes::writeFrame(scene->render(f, settings), "moving_object",
                         scenes::OutputLayout::Separate, dir_.string());
    }
    const std::string in = "'" + (dir_ / "beauty.####.exr").string() + "' --depth '" +
                           (dir_ / "depth.####.exr").string() + "' --motion '" +
                           (dir_ / "motion.####.exr").string() + "' -d float";
    ASSERT_EQ(runTaatool(in + " -o '" + (dir_ / "taatool/out.####.exr").string() + "'"), 0);
    ASSERT_EQ(runTaatool(in + " --frames 6-8 -o '" + (dir_ / "taatool68/out.####.exr").string() +
                         "'"), 0);
    ASSERT_EQ(runTaatool(in + " --jitter-scale 0.5 --motion-scale 0.5 -o '" +
                         (dir_ / "taatool-half-scale/out.####.exr").string() + "'"), 0);
    for (int f = kFirst; f <= kLast; ++f) {
      const std::string n = std::to_string(10000 + f).substr(1);
      color_.frames[f] = readChannels((dir_ / ("beauty." + n + ".exr")).string(),
                                      {"R", "G", "B", "A"});
      depth_.frames[f] = readChannels((dir_ / ("depth." + n + ".exr")).string(), {"Z"});
      motion_.frames[f] = readChannels((dir_ / ("motion." + n + ".exr")).string(), {"X", "Y"});
    }
    for (auto* clip : {&color_, &depth_, &motion_}) {
      ClipFrames half = *clip;
      half.half = true;
      halves_.push_back(half);
    }
  }

  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static Image expected(int frame, const std::string& folder = "taatool") {
    const std::string n = std::to_string(10000 + frame).substr(1);
    return readChannels((dir_ / folder / ("out." + n + ".exr")).string(), {"R", "G", "B", "A"});
  }

  // Loads the bundle, describes it in the general context and creates an instance.
  std::unique_ptr<HostEffect> instance(bool half = false, double lastFrame = kLast) {
    EXPECT_EQ(host_.load(bundleBinary()), "");
    EXPECT_EQ(host_.action(kOfxActionLoad, nullptr), kOfxStatOK);
    EXPECT_EQ(host_.action(kOfxActionDescribe, &descriptor_), kOfxStatOK);
    PropertySet context;
    context.set(kOfxImageEffectPropContext, {std::string(kOfxImageEffectContextGeneral)});
    contextDescriptor_.props = descriptor_.props;
    EXPECT_EQ(host_.action(kOfxImageEffectActionDescribeInContext, &contextDescriptor_, &context),
              kOfxStatOK);
    const std::map<std::string, const ClipFrames*> inputs = {
        {"Source", half ? &halves_[0] : &color_},
        {"Depth", half ? &halves_[1] : &depth_},
        {"Motion", half ? &halves_[2] : &motion_}};
    auto effect = host_.makeInstance(contextDescriptor_, kOfxImageEffectContextGeneral, inputs,
                                     kBounds, kFirst, lastFrame);
    EXPECT_EQ(host_.action(kOfxActionCreateInstance, effect.get()), kOfxStatOK);
    return effect;
  }

  void destroy(std::unique_ptr<HostEffect>& effect) {
    EXPECT_EQ(host_.action(kOfxActionDestroyInstance, effect.get()), kOfxStatOK);
    effect.reset();
  }

  Image render(HostEffect& effect, int frame, OfxStatus expectedStatus = kOfxStatOK,
               double renderScale = 1.0) {
    OutputImage output;
    EXPECT_EQ(host_.render(effect, frame, output, renderScale), expectedStatus)
        << "frame " << frame;
    return output.toImage();
  }

  static inline fs::path dir_;
  static inline ClipFrames color_, depth_, motion_;
  static inline std::vector<ClipFrames> halves_;
  TestHost host_;
  HostEffect descriptor_, contextDescriptor_;
};

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
                           "motionY", "motionTo", "motionScale", "historyFrames"}) {
    EXPECT_TRUE(params.count(name)) << name;
  }

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
    const std::string name = std::string("OfxImageClipPropFrameRange_") + clip;
    ASSERT_EQ(out.dimension(name), 2) << name;
    EXPECT_EQ(out.getDouble(name, 0), 1.0);
    EXPECT_EQ(out.getDouble(name, 1), 5.0);
  }
  effect->params.at("historyFrames").intValue = 3;
  in.set(kOfxPropTime, {8.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  EXPECT_EQ(out.getDouble("OfxImageClipPropFrameRange_Source", 0), 6.0);
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

TEST_F(OfxHostTest, MissingInputFailsWithAMessage) {
  auto effect = instance(false, 10.0);  // the clip claims frames up to 10; images end at 8
  render(*effect, 9, kOfxStatFailed);
  const auto messages = host_.messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.back().find("no image for the Source clip at frame 9"), std::string::npos)
      << messages.back();
  EXPECT_EQ(host_.liveImages(), 0);
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
