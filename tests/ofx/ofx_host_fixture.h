// The fixture of the OpenFX host tests: a generated sequence (moving_object, 64x40, frames
// 1-8), the bundle loaded in a TestHost, an instance made the way a host makes one (describe,
// describe in context, create, clip preferences), and taatool's results on the same files to
// compare renders with.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "test_host.h"

namespace taa::ofxtest {

constexpr int kFirst = 1, kLast = 8;
const OfxRectI kBounds = {10, 20, 10 + 64, 20 + 40};  // offset bounds exercise the mapping

// The bundle binary under OFX_PLUGIN_PATH's first folder, or the build tree's bundle folder.
std::string bundleBinary();

// The largest absolute difference of two images (infinity when their sizes differ).
float maxDifference(const Image& a, const Image& b);

class OfxHostTest : public ::testing::Test {
 public:
  // The fixture's input frames as stored (rows top first).
  static const Image& colorFrame(int frame) { return color_.frames.at(frame); }
  static const Image& depthFrame(int frame) { return depth_.frames.at(frame); }
  static const Image& motionFrame(int frame) { return motion_.frames.at(frame); }

 protected:
  static void SetUpTestSuite();
  static void TearDownTestSuite();

  // taatool's output for `frame` in history mode with the extra arguments `folder` stands for
  // (made on first use, with $OCIO unset): "taatool" (no others), "taatool68" (--frames 6-8),
  // "taatool-half-scale" (--jitter-scale 0.5 --motion-scale 0.5).
  static Image expected(int frame, const std::string& folder = "taatool");
  // taatool's output with `arguments` added (and --mode history unless they say --mode), into
  // `folder` (made on first use).
  static Image expectedWith(int frame, const std::string& folder,
                            std::vector<std::string> arguments);
  // taatool on `beauty` (a frame pattern) with the fixture's depth and motion files, -d float
  // and `extra`, into out/out.####.exr; $OCIO unset. Throws with taatool's stderr if it fails.
  static void runTaatool(const std::filesystem::path& beauty, const std::filesystem::path& out,
                         const std::vector<std::string>& extra);


  // Loads the bundle, describes it in the general context, creates an instance, sets it to
  // history mode (the tests here were written for its temporal plan; OfxHostWindowTest sets
  // window mode, ParametersHaveTheLibrarysDefaults checks the default) and runs the clip
  // preferences action as a host does before rendering.
  // `extra` connects more clips (Pass, PassFactor) by name.
  using ClipInputs = std::map<std::string, const ClipFrames*>;
  std::unique_ptr<HostEffect> instance(bool half = false, double lastFrame = kLast,
                                       const ClipInputs& extra = {});
  // The same, without the clip preferences action (the caller runs it).
  std::unique_ptr<HostEffect> instanceWithoutPreferences(bool half = false,
                                                        double lastFrame = kLast,
                                                        const ClipInputs& extra = {});
  void destroy(std::unique_ptr<HostEffect>& effect);

  Image render(HostEffect& effect, int frame, OfxStatus expectedStatus = kOfxStatOK,
               double renderScaleX = 1.0, double renderScaleY = -1.0 /* = x */);

  static inline std::filesystem::path dir_;
  static inline ClipFrames color_, depth_, motion_;
  static inline std::vector<ClipFrames> halves_;
  TestHost host_;
  HostEffect descriptor_, contextDescriptor_;
};

}  // namespace taa::ofxtest
