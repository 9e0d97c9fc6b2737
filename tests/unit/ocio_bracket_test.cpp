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

// Hosts set $OCIO to the studio's config, which has no taa_reinhard: an empty config name is
// the shipped config whatever $OCIO says, and $OCIO is read only when asked for by name.
TEST_F(OcioBracketTest, OcioVariableIsReadOnlyWhenAskedFor) {
  const std::string path = writeUserConfig();
  setenv("OCIO", path.c_str(), 1);
  EXPECT_EQ(loadConfig("").description, "taa's shipped config");
  ColorOptions options;  // the defaults: shipped config, taa_reinhard
  EXPECT_NO_THROW(OcioBracket{options});
  options.ocioConfig = "$OCIO";
  EXPECT_NE(errorOf(options).find("$OCIO (" + path + ")"), std::string::npos) << errorOf(options);

  unsetenv("OCIO");
  const std::string message = errorOf(options);
  EXPECT_NE(message.find("$OCIO is not set"), std::string::npos) << message;
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
