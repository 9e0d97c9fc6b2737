// Building the bracket from shipped and user configs, and its errors (CPU side, no GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "color/ocio_bracket.h"
#include "taa/error.h"

namespace taa::color {
namespace {

namespace fs = std::filesystem;

// A small user config: linear reference, a gamma working space, a clamped (non-invertible) one.
// One file per test: CTest runs the tests of this file in parallel processes.
std::string writeUserConfig() {
  const fs::path dir = fs::path(TAA_TEST_TMPDIR) /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  const fs::path path = dir / "config.ocio";
  std::ofstream(path) << R"(ocio_profile_version: 2
roles:
  default: lin
  scene_linear: lin
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  d:
    - !<View> {name: v, colorspace: lin}
colorspaces:
  - !<ColorSpace> {name: lin}
  - !<ColorSpace>
    name: gamma_half
    from_scene_reference: !<ExponentTransform> {value: 0.5, style: pass_thru}
  - !<ColorSpace>
    name: clamped
    from_scene_reference: !<RangeTransform> {min_in_value: 0, max_in_value: 1, min_out_value: 0, max_out_value: 1}
named_transforms:
  - !<NamedTransform>
    name: halve
    transform: !<MatrixTransform> {matrix: [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1]}
)";
  return path.string();
}

std::string errorOf(const ColorOptions& options) {
  try {
    OcioBracket bracket(options);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The ACES-style config written from the published matrices, and Debian's Blender config.
std::string acesConfig() { return TAA_SOURCE_DIR "/tests/color/aces_style.ocio"; }
constexpr const char* kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";

class OcioBracketTest : public ::testing::Test {
 protected:
  void TearDown() override { unsetenv("OCIO"); }
};

TEST_F(OcioBracketTest, ShippedConfigOffersTheDocumentedBrackets) {
  unsetenv("OCIO");
  const LoadedConfig shipped = loadConfig("");
  EXPECT_EQ(shipped.description, "taa's shipped config");
  const auto names = listBrackets(shipped.config);
  for (const char* name : {"none", "taa_log2", "taa_reinhard"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  EXPECT_EQ(std::find(names.begin(), names.end(), "raw"), names.end());  // data space
}

TEST_F(OcioBracketTest, ReinhardWorkingSpaceIsXOverXPlusFour) {
  ColorOptions options;
  options.bracket = "taa_reinhard";
  const OcioBracket bracket(options);
  for (float x : {0.0f, 1.0f, 4.0f, 100.0f}) {
    float pixel[3] = {x, x, x};
    bracket.toWorkingCpu()->applyRGB(pixel);
    EXPECT_NEAR(pixel[0], x / (x + 4.0f), 1e-6f) << x;
  }
}

TEST_F(OcioBracketTest, UserConfigByPathAndByOcioVariable) {
  const std::string path = writeUserConfig();
  ColorOptions options;
  options.ocioConfig = path;
  options.bracket = "gamma_half";
  const OcioBracket byPath(options);
  float pixel[3] = {4.0f, 9.0f, 16.0f};
  byPath.toWorkingCpu()->applyRGB(pixel);
  EXPECT_NEAR(pixel[1], 3.0f, 1e-5f);

  setenv("OCIO", path.c_str(), 1);
  EXPECT_NE(loadConfig("$OCIO").description.find("$OCIO"), std::string::npos);
  options.ocioConfig = "$OCIO";
  options.bracket = "halve";  // a named transform
  const OcioBracket byVariable(options);
  float named[3] = {4.0f, 9.0f, 16.0f};
  byVariable.toWorkingCpu()->applyRGB(named);
  EXPECT_NEAR(named[2], 8.0f, 1e-6f);
  byVariable.fromWorkingCpu()->applyRGB(named);
  EXPECT_NEAR(named[2], 16.0f, 1e-5f);
}

// One rule in every face: the config named, else $OCIO's when set, else taa's shipped one.
TEST_F(OcioBracketTest, ConfigIsTheOneNamedElseOcioElseShipped) {
  const std::string path = writeUserConfig();
  unsetenv("OCIO");
  EXPECT_EQ(loadConfig("").description, "taa's shipped config");
  setenv("OCIO", path.c_str(), 1);
  EXPECT_EQ(loadConfig("").description, "$OCIO (" + path + ")");
  EXPECT_EQ(loadConfig(path).description, path);
  unsetenv("OCIO");
  ColorOptions options;
  options.ocioConfig = "$OCIO";
  const std::string message = errorOf(options);
  EXPECT_NE(message.find("$OCIO is not set"), std::string::npos) << message;
}

// Studio configs have none of taa's names: the bracket is taa's maths on the config's
// scene_linear values whatever the config (issue 24: "unknown bracket taa_reinhard" with $OCIO
// set to Blender's config).
TEST_F(OcioBracketTest, TaaBracketsWorkInAnyConfig) {
  std::vector<std::string> configs = {writeUserConfig(), acesConfig()};
  if (fs::exists(kBlenderConfig)) configs.push_back(kBlenderConfig);
  for (const std::string& config : configs) {
    for (const bool viaEnvironment : {false, true}) {
      ColorOptions options;  // the defaults: scene_linear in and out, taa_reinhard
      if (viaEnvironment) {
        setenv("OCIO", config.c_str(), 1);
      } else {
        options.ocioConfig = config;
      }
      const std::string message = errorOf(options);
      ASSERT_EQ(message, "") << config;
      const OcioBracket bracket(options);
      float pixel[3] = {4.0f, 1.0f, 0.0f};
      bracket.toWorkingCpu()->applyRGB(pixel);
      EXPECT_NEAR(pixel[0], 0.5f, 1e-6f) << config;
      EXPECT_NEAR(pixel[1], 0.2f, 1e-6f) << config;
      bracket.fromWorkingCpu()->applyRGB(pixel);
      EXPECT_NEAR(pixel[0], 4.0f, 1e-4f) << config;
      unsetenv("OCIO");
    }
    const auto names = listBrackets(loadConfig(config).config);
    for (const char* name : {"none", "taa_reinhard", "taa_log2"}) {
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << config << name;
    }
  }
}

// The default bracket built in a user config is the very shader the shipped config gave
// before the rule (getProcessor("linear", "taa_reinhard")): outputs stay bit-identical.
TEST_F(OcioBracketTest, DefaultBracketIsTheShippedConfigsShaderInEveryConfig) {
  const OCIO::ConstConfigRcPtr shipped = loadConfig("").config;
  auto text = [](const OCIO::ConstProcessorRcPtr& processor) {
    OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
    desc->setFunctionName(kToWorkingFunction);
    desc->setResourcePrefix((std::string(kToWorkingFunction) + "_").c_str());
    processor->getDefaultGPUProcessor()->extractGpuShaderInfo(desc);
    return std::string(desc->getShaderText());
  };
  const std::string before = text(shipped->getProcessor("linear", "taa_reinhard"));
  EXPECT_EQ(OcioBracket(ColorOptions{}).toWorking()->getShaderText(), before);
  ColorOptions aces;
  aces.ocioConfig = acesConfig();
  aces.colorspaceIn = "ACEScg";  // its scene_linear: nothing to convert
  EXPECT_EQ(OcioBracket(aces).toWorking()->getShaderText(), before);
}

// ACES2065-1 input: converted to ACEScg (the config's scene_linear) for the bracket, and the
// output to the colorspace asked for; the matrices are the published ones, applied here.
TEST_F(OcioBracketTest, AcesInputIsBracketedInSceneLinearAndOutputWhereAsked) {
  ColorOptions options;
  options.ocioConfig = acesConfig();
  options.colorspaceIn = "ACES2065-1";
  options.colorspaceOut = "lin_rec709";
  const OcioBracket bracket(options);
  const float ap0[3] = {0.5f, 2.0f, 8.0f};
  float pixel[3] = {ap0[0], ap0[1], ap0[2]};
  bracket.toWorkingCpu()->applyRGB(pixel);
  const float ap0ToAp1[3][3] = {{1.4514393161f, -0.2365107469f, -0.2149285693f},
                                {-0.0765537734f, 1.1762296998f, -0.0996759264f},
                                {0.0083161484f, -0.0060324498f, 0.9977163014f}};
  const float ap0To709[3][3] = {{2.5216861867f, -1.1341309062f, -0.3875552805f},
                                {-0.2764799076f, 1.3727190652f, -0.0962391576f},
                                {-0.0153780649f, -0.1529753224f, 1.1683533873f}};
  for (int r = 0; r < 3; ++r) {
    const float ap1 = ap0ToAp1[r][0] * ap0[0] + ap0ToAp1[r][1] * ap0[1] + ap0ToAp1[r][2] * ap0[2];
    EXPECT_NEAR(pixel[r], ap1 >= 0 ? ap1 / (ap1 + 4.0f) : ap1 / 4.0f, 1e-5f) << r;
  }
  bracket.fromWorkingCpu()->applyRGB(pixel);
  for (int r = 0; r < 3; ++r) {
    const float rec709 =
        ap0To709[r][0] * ap0[0] + ap0To709[r][1] * ap0[1] + ap0To709[r][2] * ap0[2];
    EXPECT_NEAR(pixel[r], rec709, 1e-4f * std::max(1.0f, std::abs(rec709))) << r;
  }
  EXPECT_EQ(outputColorspace(options).colorspace, "lin_rec709");
  options.colorspaceOut.clear();  // the output keeps the input's colorspace
  EXPECT_EQ(outputColorspace(options).colorspace, "ACES2065-1");
  options.colorspaceIn = "scene_linear";
  EXPECT_EQ(outputColorspace(options).colorspace, "ACEScg");
  EXPECT_EQ(outputColorspace(options).config, acesConfig());
  EXPECT_EQ(outputColorspace(ColorOptions{}).colorspace, "linear");
}

// OCIO does not require a scene_linear role: the defaults still resolve (the input taken as
// linear); a named colorspace needs the role, and the message says so.
TEST_F(OcioBracketTest, ConfigWithoutSceneLinearRole) {
  const fs::path path = fs::path(TAA_TEST_TMPDIR) / "no_scene_linear.ocio";
  fs::create_directories(path.parent_path());
  std::ofstream(path) << R"(ocio_profile_version: 2
roles:
  default: lin
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  d:
    - !<View> {name: v, colorspace: lin}
colorspaces:
  - !<ColorSpace> {name: lin}
  - !<ColorSpace>
    name: gamma_half
    from_scene_reference: !<ExponentTransform> {value: 0.5, style: pass_thru}
)";
  ColorOptions options;
  options.ocioConfig = path.string();
  EXPECT_EQ(errorOf(options), "");
  options.bracket = "none";
  EXPECT_EQ(errorOf(options), "");
  options.bracket = "taa_reinhard";
  options.colorspaceIn = "gamma_half";
  const std::string message = errorOf(options);
  EXPECT_NE(message.find("no scene_linear role"), std::string::npos) << message;
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
}

TEST_F(OcioBracketTest, ErrorsNameTheConfigAndTheName) {
  const std::string path = writeUserConfig();
  ColorOptions options;
  options.ocioConfig = path;
  options.bracket = "no_such_space";
  std::string message = errorOf(options);
  EXPECT_NE(message.find("no_such_space"), std::string::npos) << message;
  EXPECT_NE(message.find(path), std::string::npos) << message;
  // ... and what the config offers instead.
  EXPECT_NE(message.find("which offers the brackets none, "), std::string::npos) << message;
  EXPECT_NE(message.find("gamma_half"), std::string::npos) << message;

  options.bracket = "clamped";
  message = errorOf(options);
  EXPECT_NE(message.find("not invertible"), std::string::npos) << message;
  EXPECT_NE(message.find("clamped"), std::string::npos) << message;

  options.bracket = "gamma_half";
  options.colorspaceIn = "acescg";
  message = errorOf(options);
  EXPECT_NE(message.find("input colorspace or role \"acescg\""), std::string::npos) << message;

  options = ColorOptions{};
  options.ocioConfig = path + ".missing";
  message = errorOf(options);
  EXPECT_NE(message.find("cannot load the OCIO config"), std::string::npos) << message;
  EXPECT_NE(message.find(".missing"), std::string::npos) << message;
}

TEST_F(OcioBracketTest, CacheIdFollowsTheProcessors) {
  ColorOptions a, b;
  a.bracket = "taa_log2";
  b.bracket = "taa_reinhard";
  EXPECT_NE(OcioBracket(a).cacheId(), OcioBracket(b).cacheId());
  EXPECT_EQ(OcioBracket(a).cacheId(), OcioBracket(a).cacheId());
}

}  // namespace
}  // namespace taa::color
