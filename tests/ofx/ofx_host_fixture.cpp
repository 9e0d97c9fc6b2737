#include "ofx_host_fixture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <unistd.h>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "taatool_runner.h"

namespace taa::ofxtest {

namespace fs = std::filesystem;

namespace {

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

std::string frameName(int frame) { return std::to_string(10000 + frame).substr(1); }

}  // namespace

void OfxHostTest::runTaatool(const fs::path& beauty, const fs::path& out,
                             const std::vector<std::string>& extra) {
  std::vector<std::string> args = {beauty.string(),
                                   "--depth",  (dir_ / "depth.####.exr").string(),
                                   "--motion", (dir_ / "motion.####.exr").string(),
                                   "-d",       "float"};
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"-o", (out / "out.####.exr").string(), "-q"});
  const fs::path scratch = out.string() + ".log";
  fs::create_directories(scratch);
  // $OCIO unset: the OCIO tests set it for the bundle and name their config to taatool.
  const test::ToolRun run = test::runProgram(test::taatoolPath(), args, scratch, {"OCIO"});
  if (run.exitCode != 0) {
    throw std::runtime_error("taatool failed (exit " + std::to_string(run.exitCode) + ") into " +
                             out.string() + ": " + run.err);
  }
}

std::string bundleBinary() {
  std::string root = TAA_OFX_BUNDLE_DIR;
  if (const char* path = std::getenv("OFX_PLUGIN_PATH"); path && *path) {
    root = std::string(path).substr(0, std::string(path).find(':'));
  }
  return root + "/TAAResolve.ofx.bundle/Contents/" TAA_OFX_ARCHITECTURE "/TAAResolve.ofx";
}

float maxDifference(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return INFINITY;
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    worst = std::max(worst, std::fabs(a.pixels[i] - b.pixels[i]));
  }
  return worst;
}

void OfxHostTest::SetUpTestSuite() {
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
  for (int f = kFirst; f <= kLast; ++f) {
    const std::string n = frameName(f);
    color_.frames[f] = readChannels((dir_ / ("beauty." + n + ".exr")).string(),
                                    {"R", "G", "B", "A"});
    depth_.frames[f] = readChannels((dir_ / ("depth." + n + ".exr")).string(), {"Z"});
    motion_.frames[f] = readChannels((dir_ / ("motion." + n + ".exr")).string(), {"X", "Y"});
  }
  halves_.clear();
  for (auto* clip : {&color_, &depth_, &motion_}) {
    ClipFrames half = *clip;
    half.half = true;
    halves_.push_back(half);
  }
}

void OfxHostTest::TearDownTestSuite() { fs::remove_all(dir_); }

Image OfxHostTest::expected(int frame, const std::string& folder) {
  static const std::map<std::string, std::vector<std::string>> arguments = {
      {"taatool", {}},
      {"taatool68", {"--frames", "6-8"}},
      {"taatool-half-scale", {"--jitter-scale", "0.5", "--motion-scale", "0.5"}}};
  return expectedWith(frame, folder, arguments.at(folder));
}

Image OfxHostTest::expectedWith(int frame, const std::string& folder,
                                std::vector<std::string> arguments) {
  // History mode, as the fixture's instances, unless the arguments choose.
  if (std::find(arguments.begin(), arguments.end(), "--mode") == arguments.end()) {
    arguments.insert(arguments.begin(), {"--mode", "history"});
  }
  if (!fs::exists(dir_ / folder)) {
    runTaatool(dir_ / "beauty.####.exr", dir_ / folder, arguments);
  }
  return readChannels((dir_ / folder / ("out." + frameName(frame) + ".exr")).string(),
                      {"R", "G", "B", "A"});
}

std::unique_ptr<HostEffect> OfxHostTest::instanceWithoutPreferences(bool half,
                                                                   double lastFrame,
                                                                   const ClipInputs& extra) {
  EXPECT_EQ(host_.load(bundleBinary()), "");
  EXPECT_EQ(host_.action(kOfxActionLoad, nullptr), kOfxStatOK);
  EXPECT_EQ(host_.action(kOfxActionDescribe, &descriptor_), kOfxStatOK);
  PropertySet context;
  context.set(kOfxImageEffectPropContext, {std::string(kOfxImageEffectContextGeneral)});
  contextDescriptor_.props = descriptor_.props;
  EXPECT_EQ(host_.action(kOfxImageEffectActionDescribeInContext, &contextDescriptor_, &context),
            kOfxStatOK);
  ClipInputs inputs = {{"Source", half ? &halves_[0] : &color_},
                       {"Depth", half ? &halves_[1] : &depth_},
                       {"Motion", half ? &halves_[2] : &motion_}};
  inputs.insert(extra.begin(), extra.end());
  auto effect = host_.makeInstance(contextDescriptor_, kOfxImageEffectContextGeneral, inputs,
                                   kBounds, kFirst, lastFrame);
  EXPECT_EQ(host_.action(kOfxActionCreateInstance, effect.get()), kOfxStatOK);
  effect->params.at("mode").intValue = 0;  // history (the default is window)
  EXPECT_EQ(host_.parameterChanged(*effect, "mode"), kOfxStatOK);
  return effect;
}

std::unique_ptr<HostEffect> OfxHostTest::instance(bool half, double lastFrame,
                                                  const ClipInputs& extra) {
  auto effect = instanceWithoutPreferences(half, lastFrame, extra);
  PropertySet preferences;
  EXPECT_EQ(host_.clipPreferences(*effect, preferences), kOfxStatOK);
  return effect;
}

void OfxHostTest::destroy(std::unique_ptr<HostEffect>& effect) {
  EXPECT_EQ(host_.action(kOfxActionDestroyInstance, effect.get()), kOfxStatOK);
  effect.reset();
}

Image OfxHostTest::render(HostEffect& effect, int frame, OfxStatus expectedStatus,
                          double renderScaleX, double renderScaleY) {
  OutputImage output;
  EXPECT_EQ(host_.render(effect, frame, output, renderScaleX, renderScaleY), expectedStatus)
      << "frame " << frame;
  return output.toImage();
}

}  // namespace taa::ofxtest
