// End-to-end: colour management with a studio's $OCIO (issue 24). The tonemap bracket is taa's
// maths and works whatever $OCIO names; the user's config serves the input and output
// colorspaces (ACEScg, roles), and the output header says which colorspace it holds.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

constexpr const char* kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";
const std::string kAcesConfig = TAA_SOURCE_DIR "/tests/color/aces_style.ocio";

// Sets $OCIO for the test's taatool runs (empty: unset), restoring the process's on exit.
class OcioVariable {
 public:
  explicit OcioVariable(const std::string& value) {
    if (const char* old = std::getenv("OCIO")) old_ = old;
    if (value.empty()) {
      unsetenv("OCIO");
    } else {
      setenv("OCIO", value.c_str(), 1);
    }
  }
  ~OcioVariable() {
    if (old_.empty()) {
      unsetenv("OCIO");
    } else {
      setenv("OCIO", old_.c_str(), 1);
    }
  }

 private:
  std::string old_;
};

struct Frame {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
};

Frame readFrame(const fs::path& path) {
  Frame frame;
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return frame;
  frame.spec = in->spec();
  frame.pixels.resize(frame.spec.image_pixels() * std::size_t(frame.spec.nchannels));
  EXPECT_TRUE(in->read_image(0, 0, 0, frame.spec.nchannels, OIIO::TypeFloat,
                             frame.pixels.data()));
  return frame;
}

// Frames [1, 3] of one flat colour `rgb` (float RGBA), depth 10, no motion: every resolve of
// them gives the colour back, so a colour conversion shows alone.
void writeFlatFrames(const fs::path& folder, const std::array<float, 3>& rgb) {
  fs::create_directories(folder);
  constexpr int kWidth = 16, kHeight = 12;
  for (int frame = 1; frame <= 3; ++frame) {
    char name[32];
    auto write = [&](const char* what, int channels, const std::vector<float>& pixels) {
      std::snprintf(name, sizeof name, "%s.%04d.exr", what, frame);
      const std::string path = (folder / name).string();
      OIIO::ImageSpec spec(kWidth, kHeight, channels, OIIO::TypeFloat);
      if (channels == 1) spec.channelnames = {"Z"};
      if (channels == 2) spec.channelnames = {"X", "Y"};
      auto out = OIIO::ImageOutput::create(path);
      ASSERT_TRUE(out && out->open(path, spec)) << path;
      ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
      ASSERT_TRUE(out->close());
    };
    std::vector<float> color;
    for (int i = 0; i < kWidth * kHeight; ++i) color.insert(color.end(), {rgb[0], rgb[1], rgb[2], 1});
    write("beauty", 4, color);
    write("depth", 1, std::vector<float>(kWidth * kHeight, 10.0f));
    write("motion", 2, std::vector<float>(2 * kWidth * kHeight, 0.0f));
  }
}

class ColourManagementTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder(); }

  ToolRun run(const fs::path& in, const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = test::separateFileArgs(in, dir_ / out / "r.####.exr");
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runTaatool(args, dir_);
  }

  fs::path dir_;
};

// Issue 24: with $OCIO set to any studio config, the default run failed ("unknown bracket
// taa_reinhard"). Now it runs, and gives the pixels the shipped config gives, bit for bit: the
// default spaces are the config's scene_linear in and out, with nothing to convert.
TEST_F(ColourManagementTest, DefaultRunWorksWithAStudioOcioAndGivesTheSamePixels) {
  test::writeSeparateFrames(dir_ / "in", 1, 3);
  Frame reference;
  {
    const OcioVariable unset("");
    const ToolRun shipped = run(dir_ / "in", "shipped", {"-d", "float"});
    ASSERT_EQ(shipped.exitCode, 0) << shipped.err;
    reference = readFrame(dir_ / "shipped" / "r.0002.exr");
    EXPECT_EQ(reference.spec.get_string_attribute("taa:colorspace"), "linear");
    EXPECT_EQ(reference.spec.get_string_attribute("taa:ocioConfig"), "taa's shipped config");
  }
  std::vector<std::pair<std::string, std::string>> studios = {{kAcesConfig, "ACEScg"}};
  if (fs::exists(kBlenderConfig)) {
    studios.push_back({kBlenderConfig, "Linear"});
  } else {
    ADD_FAILURE() << "Debian's Blender config is missing: " << kBlenderConfig;
  }
  int index = 0;
  for (const auto& [config, linear] : studios) {
    const OcioVariable studio(config);
    const std::string out = "studio" + std::to_string(index++);
    const ToolRun resolved = run(dir_ / "in", out, {"-d", "float"});
    ASSERT_EQ(resolved.exitCode, 0) << config << "\n" << resolved.err;
    const Frame frame = readFrame(dir_ / out / "r.0002.exr");
    EXPECT_EQ(frame.pixels, reference.pixels) << config;
    EXPECT_EQ(frame.spec.get_string_attribute("taa:colorspace"), linear) << config;
    EXPECT_EQ(frame.spec.get_string_attribute("taa:ocioConfig"), "$OCIO (" + config + ")");
  }
}

// ACEScg input with an ACES config: resolves, and the output keeps ACEScg and says so.
// ACES2065-1 input is bracketed in ACEScg (the config's scene_linear) and written where
// --colorspace-out says; the expected values come from the published matrices, not OCIO.
TEST_F(ColourManagementTest, AcesInputKeepsItsColorspaceOrGoesWhereAsked) {
  const std::array<float, 3> rgb = {0.5f, 2.0f, 8.0f};
  writeFlatFrames(dir_ / "flat", rgb);
  const OcioVariable aces(kAcesConfig);

  const ToolRun acescg = run(dir_ / "flat", "acescg", {"--colorspace-in", "ACEScg"});
  ASSERT_EQ(acescg.exitCode, 0) << acescg.err;
  Frame frame = readFrame(dir_ / "acescg" / "r.0002.exr");
  EXPECT_EQ(frame.spec.get_string_attribute("taa:colorspace"), "ACEScg");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(frame.pixels[std::size_t(c)], rgb[std::size_t(c)], 1e-3f * rgb[std::size_t(c)]);

  const ToolRun converted = run(dir_ / "flat", "rec709", {"--colorspace-in", "ACES2065-1",
                                                         "--colorspace-out", "lin_rec709"});
  ASSERT_EQ(converted.exitCode, 0) << converted.err;
  frame = readFrame(dir_ / "rec709" / "r.0002.exr");
  EXPECT_EQ(frame.spec.get_string_attribute("taa:colorspace"), "lin_rec709");
  EXPECT_EQ(frame.spec.get_string_attribute("taa:ocioConfig"), "$OCIO (" + kAcesConfig + ")");
  const float ap0To709[3][3] = {{2.5216861867f, -1.1341309062f, -0.3875552805f},
                                {-0.2764799076f, 1.3727190652f, -0.0962391576f},
                                {-0.0153780649f, -0.1529753224f, 1.1683533873f}};
  for (int r = 0; r < 3; ++r) {
    const float expected = ap0To709[r][0] * rgb[0] + ap0To709[r][1] * rgb[1] + ap0To709[r][2] * rgb[2];
    // Half output: 1e-3 relative is two half steps.
    EXPECT_NEAR(frame.pixels[std::size_t(r)], expected, 2e-3f * std::abs(expected)) << r;
  }

  // A name the config lacks: the message names the config and what it offers.
  test::expectToolError(run(dir_ / "flat", "bad", {"--colorspace-in", "acescg_typo"}),
                        {"acescg_typo", kAcesConfig, "ACEScg"});
}

}  // namespace
}  // namespace taa
