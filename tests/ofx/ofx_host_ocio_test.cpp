// Colour inside a host: hosts set $OCIO to the studio's config, which has none of taa's names.
// taa's brackets are its own maths and work in any config; the config serves the input and
// output colorspaces (Automatic: $OCIO when set, as taatool). A name the picked config lacks is
// a persistent message on the effect naming the config and what it offers, not a failed
// render without a word.
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "ofx_host_fixture.h"

namespace taa::ofxtest {
namespace {

namespace fs = std::filesystem;

// A studio-like config: scene-linear reference, a gamma space, a named transform; no taa_*.
std::string writeStudioConfig() {
  const fs::path dir = fs::path(TAA_TEST_TMPDIR) /
                       ("studio_" + std::string(::testing::UnitTest::GetInstance()
                                                    ->current_test_info()
                                                    ->name()));
  fs::create_directories(dir);
  const fs::path path = dir / "studio.ocio";
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
)";
  return path.string();
}

class OfxHostOcioTest : public OfxHostTest {
 protected:
  void SetUp() override {
    studio_ = writeStudioConfig();
    setenv("OCIO", studio_.c_str(), 1);
  }
  void TearDown() override { unsetenv("OCIO"); }

  void set(HostEffect& effect, const std::string& name, const std::string& value) {
    effect.params.at(name).stringValue = value;
    EXPECT_EQ(host_.parameterChanged(effect, name), kOfxStatOK) << name;
  }
  void choose(HostEffect& effect, int source) {
    effect.params.at("ocioConfigSource").intValue = source;
    EXPECT_EQ(host_.parameterChanged(effect, "ocioConfigSource"), kOfxStatOK);
  }

  std::string studio_;
};

TEST_F(OfxHostOcioTest, StudioOcioVariableDoesNotChangeTheDefaults) {
  auto effect = instance();
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  for (int f = kFirst; f <= 3; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  destroy(effect);
}

TEST_F(OfxHostOcioTest, TaasBracketWorksInTheStudioConfigAndMissingNamesAreReported) {
  auto effect = instance();
  choose(*effect, 1);  // $OCIO: taa_reinhard is taa's, not the config's, and works
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  EXPECT_LE(maxDifference(render(*effect, 1), expected(1)), 1e-5f);

  set(*effect, "colorspaceIn", "acescg_typo");
  std::string message = host_.persistentMessage(*effect);
  EXPECT_NE(message.find("OfxMessageError: TAA Resolve: unknown input colorspace or role "
                         "\"acescg_typo\" in the OCIO config $OCIO (" +
                         studio_ + "), which offers the colorspaces lin, gamma_half"),
            std::string::npos)
      << message;
  render(*effect, 2, kOfxStatFailed);
  message = host_.persistentMessage(*effect);
  EXPECT_NE(message.find("acescg_typo"), std::string::npos) << message;
  set(*effect, "colorspaceIn", "scene_linear");
  EXPECT_EQ(host_.persistentMessage(*effect), "");

  set(*effect, "bracket", "gamma_half");  // a bracket of the config's own
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  for (int f = kFirst; f <= 3; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f),
                            expectedWith(f, "taatool-studio-gamma",
                                         {"--ocio-config", studio_, "--bracket", "gamma_half"})),
              1e-5f)
        << "frame " << f;
  }
  // The bracket matters: the comparison can fail.
  EXPECT_GT(maxDifference(expected(3), expectedWith(3, "taatool-studio-gamma",
                                                      {"--ocio-config", studio_, "--bracket",
                                                       "gamma_half"})),
            1e-4f);
  destroy(effect);
}

TEST_F(OfxHostOcioTest, ConfigFileParameter) {
  auto effect = instance();
  choose(*effect, 2);  // File, none named yet
  EXPECT_NE(host_.persistentMessage(*effect).find("OCIO Config File is empty"),
            std::string::npos)
      << host_.persistentMessage(*effect);
  set(*effect, "ocioConfigFile", studio_);
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  set(*effect, "bracket", "no_such_bracket");
  EXPECT_NE(host_.persistentMessage(*effect).find("in the OCIO config " + studio_),
            std::string::npos)
      << host_.persistentMessage(*effect);
  set(*effect, "bracket", "none");
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  EXPECT_LE(maxDifference(render(*effect, 1),
                          expectedWith(1, "taatool-studio-none",
                                       {"--ocio-config", studio_, "--bracket", "none"})),
            1e-5f);
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
