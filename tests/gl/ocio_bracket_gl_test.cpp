// The OCIO bracket through the real GPU path: OCIO-generated GLSL compiled on the context,
// LUTs and uniforms bound by OcioGpuResources, values read back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "color/ocio_bracket.h"
#include "color/ocio_gpu_resources.h"
#include "gl_test_support.h"

namespace taa::gl::test {
namespace {

// 0, then log-spaced values from 2^-12 up to half float's maximum 65504.
std::vector<float> halfRangeRamp(int count) {
  std::vector<float> values = {0.0f};
  const double lo = std::log2(1.0 / 4096.0), hi = std::log2(65504.0);
  for (int i = 0; i < count - 1; ++i) values.push_back(float(std::exp2(lo + (hi - lo) * i / (count - 2))));
  return values;
}

struct BracketPass {
  std::vector<float> working;    // taaToWorking(x)
  std::vector<float> roundTrip;  // taaFromWorking(taaToWorking(x))
};

// Runs both bracket functions on `values` (as grey RGB, alpha 1) on the GPU.
BracketPass runBracket(const Functions& gl, const color::OcioBracket& bracket,
                       const std::vector<float>& values, bool roundTrip) {
  const int width = int(values.size());
  std::vector<float> rgba;
  for (float v : values) rgba.insert(rgba.end(), {v, 0.5f * v, 0.25f * v, 1.0f});
  Texture input(gl, width, 1, GL_RGBA32F);
  input.upload(rgba.data(), 4);
  const std::string body = bracket.glsl() + R"(
uniform sampler2D uInput;
void main() {
  vec4 x = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0);
  outColor = )" + std::string(roundTrip ? "taaFromWorking(taaToWorking(x))" : "taaToWorking(x)") +
                           ";\n}\n";
  const color::OcioGpuResources toLuts(gl, bracket.toWorking(), 1);
  const color::OcioGpuResources fromLuts(gl, bracket.fromWorking(), 1 + toLuts.unitCount());
  std::vector<float> pixels =
      renderPass(gl, fragmentShader("bracket_test.frag", body), width, 1, [&](const Program& p) {
        input.bind(0);
        p.set("uInput", 0);
        toLuts.setUniforms(p);
        fromLuts.setUniforms(p);
        toLuts.bind();
        fromLuts.bind();
      });
  BracketPass pass;
  (roundTrip ? pass.roundTrip : pass.working) = std::move(pixels);
  return pass;
}

class OcioBracketGl : public ::testing::Test {
 protected:
  void SetUp() override { context_ = Context::create(Backend::Auto); }
  std::unique_ptr<Context> context_;
};

TEST_F(OcioBracketGl, EveryShippedBracketRoundTripsOverHalfRange) {
  const color::LoadedConfig shipped = color::loadConfig("");
  const std::vector<float> values = halfRangeRamp(512);
  const auto brackets = color::listBrackets(shipped.config);
  ASSERT_GE(brackets.size(), 3u);
  for (const std::string& name : brackets) {
    ColorOptions options;
    options.bracket = name;
    const color::OcioBracket bracket(options);
    const auto rt = runBracket(context_->functions(), bracket, values, true).roundTrip;
    double worst = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const double x = values[i] * (c == 0 ? 1.0 : c == 1 ? 0.5 : 0.25);
        const double error = std::abs(rt[4 * i + c] - x) / std::max(x, 1e-3);
        worst = std::max(worst, error);
      }
      ASSERT_EQ(rt[4 * i + 3], 1.0f) << name;  // alpha untouched
    }
    EXPECT_LE(worst, 1e-3) << "bracket " << name;
    std::printf("bracket %-14s worst relative round-trip error over 0..65504: %.2e\n",
                name.c_str(), worst);
  }
}

// Half float's whole range, both signs: -65504 ... -2^-12, 0, 2^-12 ... 65504.
std::vector<float> signedHalfRangeRamp(int countPerSign) {
  std::vector<float> values = halfRangeRamp(countPerSign);
  for (int i = 1; i < countPerSign; ++i) values.push_back(-values[std::size_t(i)]);
  return values;
}

// Issue 17: scene-linear colour below -4 went through x / (x + 4) to +Inf (and stayed in history),
// around -1000 it came back as -4. Every shipped bracket must map the whole signed half range to
// finite working values and back to within 1e-3, on the GPU.
TEST_F(OcioBracketGl, EveryShippedBracketIsFiniteAndInvertibleOverTheSignedHalfRange) {
  const color::LoadedConfig shipped = color::loadConfig("");
  const std::vector<float> values = signedHalfRangeRamp(512);
  for (const std::string& name : color::listBrackets(shipped.config)) {
    ColorOptions options;
    options.bracket = name;
    const color::OcioBracket bracket(options);
    const auto working = runBracket(context_->functions(), bracket, values, false).working;
    const auto rt = runBracket(context_->functions(), bracket, values, true).roundTrip;
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const double x = values[i] * (c == 0 ? 1.0 : c == 1 ? 0.5 : 0.25);
        ASSERT_TRUE(std::isfinite(working[4 * i + c])) << name << " forward of " << x;
        ASSERT_TRUE(std::isfinite(rt[4 * i + c])) << name << " round trip of " << x;
        EXPECT_LE(std::abs(rt[4 * i + c] - x) / std::max(std::abs(x), 1e-3), 1e-3)
            << name << ": " << x << " comes back as " << rt[4 * i + c];
      }
    }
  }
}

// The bracket that taa shipped before negatives were handled: x / (x + 4) from two log
// transforms (it clamps x <= -4). Non-negative values must go through today's shipped
// taa_reinhard bit for bit as through this one, so that no resolve of such input changes.
const char* kFormerReinhard = R"(ocio_profile_version: 2
roles: {default: linear, scene_linear: linear}
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  none:
    - !<View> {name: Raw, colorspace: linear}
colorspaces:
  - !<ColorSpace> {name: linear}
  - !<ColorSpace>
    name: former_reinhard
    from_scene_reference: !<GroupTransform>
      children:
        - !<LogAffineTransform> {base: 2, lin_side_slope: [0.25, 0.25, 0.25], lin_side_offset: [1, 1, 1], log_side_slope: [-1, -1, -1], log_side_offset: [0, 0, 0]}
        - !<LogAffineTransform> {base: 2, direction: inverse}
        - !<MatrixTransform> {matrix: [-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1], offset: [1, 1, 1, 0]}
)";

TEST_F(OcioBracketGl, ReinhardIsUnchangedForNonNegativeValues) {
  const std::string dir = std::string(TAA_TEST_TMPDIR) + "/former_reinhard";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/config.ocio") << kFormerReinhard;
  ColorOptions former;
  former.ocioConfig = dir + "/config.ocio";
  former.bracket = "former_reinhard";
  ColorOptions shipped;
  shipped.bracket = "taa_reinhard";
  std::vector<float> values = halfRangeRamp(2048);
  for (int i = 0; i <= 1000; ++i) values.push_back(i / 1000.0f);  // shadows, densely
  const Functions& gl = context_->functions();
  const color::OcioBracket formerBracket(former), shippedBracket(shipped);
  const auto expected = runBracket(gl, formerBracket, values, false).working;
  const auto got = runBracket(gl, shippedBracket, values, false).working;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i], expected[i]) << "value " << values[i / 4] << " channel " << i % 4;
  }
  float cpuFormer[3], cpuShipped[3];
  for (float v : values) {
    cpuFormer[0] = cpuShipped[0] = v;
    cpuFormer[1] = cpuShipped[1] = 0.5f * v;
    cpuFormer[2] = cpuShipped[2] = 0.25f * v;
    formerBracket.toWorkingCpu()->applyRGB(cpuFormer);
    shippedBracket.toWorkingCpu()->applyRGB(cpuShipped);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(cpuShipped[c], cpuFormer[c]) << "CPU, value " << v;
  }
}

TEST_F(OcioBracketGl, GpuForwardMatchesCpuProcessorOnARamp) {
  std::vector<float> values;
  for (int i = 0; i < 256; ++i) values.push_back(i / 255.0f * 16.0f);  // 0..16 linear ramp
  for (const char* name : {"taa_log2", "taa_reinhard"}) {
    ColorOptions options;
    options.bracket = name;
    const color::OcioBracket bracket(options);
    const auto gpu = runBracket(context_->functions(), bracket, values, false).working;
    for (std::size_t i = 0; i < values.size(); ++i) {
      float cpu[4] = {values[i], 0.5f * values[i], 0.25f * values[i], 1.0f};
      bracket.toWorkingCpu()->applyRGBA(cpu);
      for (int c = 0; c < 4; ++c) {
        ASSERT_NEAR(gpu[4 * i + c], cpu[c], 1e-4f) << name << " value " << values[i];
      }
    }
  }
}

TEST_F(OcioBracketGl, UserConfigWithLutRunsOnTheGpu) {
  // A user config whose working space is a 1D LUT file: exercises LUT texture upload.
  const std::string dir = std::string(TAA_TEST_TMPDIR) + "/lut_config";
  std::filesystem::create_directories(dir);
  {
    std::ofstream lut(dir + "/sqrt.spi1d");
    lut << "Version 1\nFrom 0.0 65536.0\nLength 4096\nComponents 1\n{\n";
    for (int i = 0; i < 4096; ++i) lut << "  " << std::sqrt(65536.0 * i / 4095.0) << "\n";
    lut << "}\n";
    std::ofstream config(dir + "/config.ocio");
    config << "ocio_profile_version: 2\nsearch_path: \".\"\nroles:\n  default: lin\n"
              "  scene_linear: lin\nfile_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
              "displays:\n  d:\n    - !<View> {name: v, colorspace: lin}\n"
              "colorspaces:\n  - !<ColorSpace> {name: lin}\n"
              "  - !<ColorSpace>\n    name: sqrt_lut\n"
              "    from_scene_reference: !<FileTransform> {src: sqrt.spi1d, interpolation: linear}\n";
  }
  ColorOptions options;
  options.ocioConfig = dir + "/config.ocio";
  options.bracket = "sqrt_lut";
  const color::OcioBracket bracket(options);
  ASSERT_GE(bracket.toWorking()->getNumTextures(), 1u);
  const std::vector<float> values = {0.0f, 0.25f, 3.5f, 100.0f, 2500.0f, 40000.0f};
  const auto gpu = runBracket(context_->functions(), bracket, values, false).working;
  for (std::size_t i = 0; i < values.size(); ++i) {
    float cpu[4] = {values[i], 0.5f * values[i], 0.25f * values[i], 1.0f};
    bracket.toWorkingCpu()->applyRGBA(cpu);
    EXPECT_NEAR(gpu[4 * i], cpu[0], 1e-3f * std::max(1.0f, cpu[0])) << values[i];
    if (values[i] >= 100.0f) {  // where the LUT's linear segments are fine enough for sqrt
      EXPECT_NEAR(gpu[4 * i], std::sqrt(values[i]), 0.01f * std::sqrt(values[i]));
    }
  }
}

}  // namespace
}  // namespace taa::gl::test
