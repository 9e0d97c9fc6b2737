// The first resolve on real GL (llvmpipe here), against scenes with known truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <glm/vec4.hpp>

#include "gl/context.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"
#include "taa/error.h"
#include "scenegen/layered_scene.h"
#include "scenegen/scene_library.h"

namespace taa {
namespace {

// RMS difference of Reinhard-tonemapped RGB, x / (1 + x): the yardstick's space.
double tonemappedRms(const Image& a, const Image& b, int border = 0) {
  double sum = 0.0;
  long count = 0;
  for (int y = border; y < a.height - border; ++y) {
    for (int x = border; x < a.width - border; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double va = a.at(x, y)[c], vb = b.at(x, y)[c];
        const double d = va / (1.0 + va) - vb / (1.0 + vb);
        sum += d * d;
        ++count;
      }
    }
  }
  return std::sqrt(sum / count);
}

// The reconstruction resolve.frag applies to the current frame: a Blackman-Harris-fit Gaussian
// over the 3x3 neighbourhood, each sample weighted by its distance after jitter.
glm::vec4 filteredCurrent(const Image& color, int x, int y, glm::vec2 jitter) {
  glm::vec4 sum(0.0f);
  float weightSum = 0.0f;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int qx = std::clamp(x + dx, 0, color.width - 1);
      const int qy = std::clamp(y + dy, 0, color.height - 1);
      const glm::vec2 d = glm::vec2(dx, dy) + jitter;
      const float w = std::exp(-2.29f * (d.x * d.x + d.y * d.y));
      const float* p = color.at(qx, qy);
      sum += w * glm::vec4(p[0], p[1], p[2], p[3]);
      weightSum += w;
    }
  }
  return sum / weightSum;
}

void expectEqualsFilteredCurrent(const Image& output, const scenes::SceneFrame& frame) {
  for (int y = 0; y < output.height; y += 7) {
    for (int x = 0; x < output.width; x += 5) {
      const glm::vec4 expected = filteredCurrent(frame.color, x, y, frame.jitter);
      for (int c = 0; c < 4; ++c) {
        ASSERT_NEAR(output.at(x, y)[c], expected[c], 1e-4f * (1.0f + std::abs(expected[c])))
            << "pixel " << x << "," << y << " channel " << c;
      }
    }
  }
}

// Default options with the Blackman-Harris fit (the filter above) and without the tonemap
// bracket, so the output is the filter's plain arithmetic.
ResolveOptions withoutBracket() {
  ResolveOptions options;
  options.reconstruction = Reconstruction::BlackmanHarris;
  options.color.bracket = "none";
  return options;
}

class ResolverTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = gl::Context::create(gl::Backend::Auto); }

  scenes::RenderSettings settings_;
  std::unique_ptr<gl::Context> context_;
};

Image resolveFrame(Resolver& resolver, const scenes::SceneFrame& frame) {
  ResolveInput input;
  input.color = &frame.color;
  input.depth = &frame.depth;
  input.motion = &frame.motion;
  input.jitter = frame.jitter;
  return resolver.resolve(input);
}

TEST_F(ResolverTest, FirstFrameIsTheUnjitteredCurrentFrame) {
  auto scene = scenes::makeScene("moving_object", 64, 40);
  Resolver resolver(*context_, withoutBracket());
  const scenes::SceneFrame frame = scene->render(3, settings_);
  expectEqualsFilteredCurrent(resolveFrame(resolver, frame), frame);
}

TEST_F(ResolverTest, OffScreenHistoryFallsBackToCurrentFrame) {
  auto scene = scenes::makeScene("static", 64, 40);
  Resolver resolver(*context_, withoutBracket());
  resolveFrame(resolver, scene->render(1, settings_));
  scenes::SceneFrame frame = scene->render(2, settings_);
  for (float& v : frame.motion.pixels) v = 1000.0f;  // every pixel came from off-screen
  expectEqualsFilteredCurrent(resolveFrame(resolver, frame), frame);
}

TEST_F(ResolverTest, ResetHistoryStartsOver) {
  auto scene = scenes::makeScene("static", 64, 40);
  Resolver resolver(*context_, withoutBracket());
  resolveFrame(resolver, scene->render(1, settings_));
  resolveFrame(resolver, scene->render(2, settings_));
  resolver.resetHistory();
  const scenes::SceneFrame frame = scene->render(3, settings_);
  expectEqualsFilteredCurrent(resolveFrame(resolver, frame), frame);
}

TEST_F(ResolverTest, StaticSceneConvergesTowardSupersampledTruth) {
  auto scene = scenes::makeScene("static", 96, 64);
  Resolver resolver(*context_, ResolveOptions{});
  std::vector<double> errors;
  double rawErrorSum = 0.0;
  const int frames = 24;
  for (int f = 1; f <= frames; ++f) {
    const scenes::SceneFrame frame = scene->render(f, settings_);
    const Image output = resolveFrame(resolver, frame);
    errors.push_back(tonemappedRms(output, frame.truth, 1));
    rawErrorSum += tonemappedRms(frame.color, frame.truth, 1);
  }
  const double rawError = rawErrorSum / frames;
  std::printf("static scene, tonemapped RMS: raw input %.4f, output frame 1 %.4f, frame 8 %.4f, "
              "frame %d %.4f\n", rawError, errors[0], errors[7], frames, errors.back());
  // While the per-pixel sample count is small every frame adds a new jitter position's worth
  // of information; after that the error settles on the reconstruction filter's floor.
  for (int i = 1; i < 4; ++i) {
    EXPECT_LT(errors[i], errors[i - 1]) << "error rose at frame " << i + 1;
  }
  EXPECT_LT(errors.back(), 0.5 * rawError)
      << "final error " << errors.back() << ", raw input " << rawError;
  EXPECT_LT(errors.back(), 0.7 * errors.front());
}

// A rigid translation of a pattern coarse enough (8 px cells, a 12 px wave) that a one-frame
// misalignment shows clearly, with sharp edges that still alias without the resolve.
std::unique_ptr<scenes::Scene> coarseTranslation(int width, int height) {
  scenes::Layer layer;
  layer.texture = [](glm::dvec2 p) {
    const bool odd = (int(std::floor(p.x / 8.0)) + int(std::floor(p.y / 8.0))) % 2 != 0;
    const double wave = 0.5 + 0.5 * std::sin(p.x * 0.5236 + p.y * 0.3);
    const float base = odd ? 1.0f : 0.15f;
    return glm::vec3(base, base * float(wave) + 0.1f, 0.4f * float(wave));
  };
  layer.velocity = scenes::translateVelocity();
  layer.depth = 5.0f;
  return std::make_unique<scenes::LayeredScene>("coarse_translate", width, height,
                                                std::vector<scenes::Layer>{layer});
}

TEST_F(ResolverTest, TranslationIsReprojectedWithoutDrift) {
  auto scene = coarseTranslation(96, 64);
  Resolver resolver(*context_, ResolveOptions{});
  const int frames = 24;
  std::vector<scenes::SceneFrame> rendered;
  std::vector<Image> outputs;
  for (int f = 1; f <= frames + 1; ++f) rendered.push_back(scene->render(f, settings_));
  for (int i = 0; i < frames; ++i) outputs.push_back(resolveFrame(resolver, rendered[i]));

  const int border = 4;  // pixels entering from off-screen start without history
  double earlyError = 0.0, lateError = 0.0, rawError = 0.0;
  for (int i = 8; i < frames; ++i) {
    const double error = tonemappedRms(outputs[i], rendered[i].truth, border);
    const double vsPrevious = tonemappedRms(outputs[i], rendered[i - 1].truth, border);
    const double vsNext = tonemappedRms(outputs[i], rendered[i + 1].truth, border);
    // Aligned with this frame's truth, not lagging or leading by a frame's motion (1.5 px).
    EXPECT_LT(error, 0.6 * vsPrevious) << "frame " << i + 1;
    EXPECT_LT(error, 0.6 * vsNext) << "frame " << i + 1;
    (i < 16 ? earlyError : lateError) += error / 8.0;
    rawError += tonemappedRms(rendered[i].color, rendered[i].truth, border) / 16.0;
  }
  // No accumulating drift or blur: frames 17-24 are no worse than frames 9-16.
  EXPECT_LT(lateError, 1.1 * earlyError);
  EXPECT_LT(0.5 * (earlyError + lateError), rawError);
  std::printf("translation, tonemapped RMS: raw input %.4f, output frames 9-16 %.4f, 17-24 %.4f\n",
              rawError, earlyError, lateError);
}

// Half colour in, half colour out (the pipeline's native path) gives exactly what the float
// path gives for the same values: half samples widen exactly on the GPU, and reading back as
// half rounds as narrowing the float result on the CPU does (Imath, round to nearest even).
TEST_F(ResolverTest, HalfInputAndOutputMatchTheFloatPathBitForBit) {
  auto scene = scenes::makeScene("moving_object", 48, 32);
  Resolver viaFloat(*context_, ResolveOptions{});
  Resolver viaHalf(*context_, ResolveOptions{});
  for (int f = 1; f <= 3; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const scenes::SceneFrame frame = scene->render(f, settings_);
    HalfImage halfColor(frame.color.width, frame.color.height, 4);
    for (std::size_t i = 0; i < frame.color.pixels.size(); ++i) {
      halfColor.pixels[i] = Imath::half(frame.color.pixels[i]);
    }
    const Image floatColor = TypedImage(halfColor).toFloat();
    ResolveInput input;
    input.depth = &frame.depth;
    input.motion = &frame.motion;
    input.jitter = frame.jitter;
    input.color = &floatColor;
    const Image floatOut = viaFloat.resolve(input);
    input.color = &halfColor;
    const TypedImage halfOut = viaHalf.resolve(input, SampleType::Half);
    ASSERT_EQ(halfOut.type(), SampleType::Half);
    const HalfImage& half = *halfOut.halves();
    ASSERT_EQ(half.pixels.size(), floatOut.pixels.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < half.pixels.size(); ++i) {
      if (half.pixels[i].bits() != Imath::half(floatOut.pixels[i]).bits() && ++mismatches <= 3) {
        ADD_FAILURE() << "value " << i << ": float path " << floatOut.pixels[i];
      }
    }
    EXPECT_EQ(mismatches, 0);
  }
}

// The debug target exists only while something reads it; with or without it, and when it comes
// and goes between frames, the result is the same.
TEST_F(ResolverTest, DebugOutputDoesNotChangeTheResult) {
  auto scene = scenes::makeScene("moving_object", 48, 32);
  Resolver plain(*context_, ResolveOptions{});
  Resolver debugged(*context_, ResolveOptions{});
  for (int f = 1; f <= 4; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    debugged.setDebugOutput(f != 3);
    const scenes::SceneFrame frame = scene->render(f, settings_);
    const Image expected = resolveFrame(plain, frame);
    EXPECT_EQ(resolveFrame(debugged, frame).pixels, expected.pixels);
    if (f != 3) {
      const FrameVector<float>& debug = debugged.lastDebug().pixels;
      ASSERT_EQ(debug.size(), expected.pixels.size());
      int kept = 0;
      for (std::size_t i = 1; i < debug.size(); i += 4) kept += debug[i] == 0.0f ? 1 : 0;
      if (f == 1) {
        EXPECT_EQ(kept, 0);  // no history yet
      } else {
        EXPECT_GT(kept, 0);
      }
    }
  }
}

// Without sharpening the resolve pass writes the output itself; with it a separate output pass
// does. Switching between frames rebuilds the targets, and both paths give the same colour (a
// sharpening amount of 1e-6 moves values by about a millionth) from the same history.
TEST_F(ResolverTest, FusedAndSeparateOutputPassesAgree) {
  auto scene = scenes::makeScene("moving_object", 48, 32);
  Resolver fused(*context_, ResolveOptions{});
  Resolver switching(*context_, ResolveOptions{});
  for (int f = 1; f <= 4; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    ResolveOptions options;
    options.sharpen = (f == 2 || f == 3) ? 1e-6f : 0.0f;
    switching.setOptions(options);
    const scenes::SceneFrame frame = scene->render(f, settings_);
    const Image expected = resolveFrame(fused, frame);
    const Image actual = resolveFrame(switching, frame);
    ASSERT_EQ(actual.pixels.size(), expected.pixels.size());
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
      ASSERT_NEAR(actual.pixels[i], expected.pixels[i], 1e-5f * (1.0f + expected.pixels[i]))
          << "value " << i;
    }
    if (f == 1 || f == 4) {
      EXPECT_EQ(actual.pixels, expected.pixels);  // the same program
    }
  }
}

// A bracket whose OCIO shaders sample LUT textures (a user config's 1D LUT, x -> x / 2, exact
// under linear interpolation): each pass must bind its own transform's LUTs, whether the output
// conversion runs in the resolve pass (no sharpening) or in the output pass.
TEST_F(ResolverTest, LutBracketRoundTripsInBothOutputPaths) {
  const std::string dir = std::string(TAA_TEST_TMPDIR) + "/lut_bracket";
  std::filesystem::create_directories(dir);
  {
    std::ofstream lut(dir + "/half.spi1d");
    lut << "Version 1\nFrom 0.0 65536.0\nLength 4097\nComponents 1\n{\n";
    for (int i = 0; i <= 4096; ++i) lut << "  " << 8.0 * i << "\n";
    lut << "}\n";
    std::ofstream config(dir + "/config.ocio");
    config << "ocio_profile_version: 2\nsearch_path: \".\"\nroles:\n  default: lin\n"
              "  scene_linear: lin\n"
              "file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
              "displays:\n  d:\n    - !<View> {name: v, colorspace: lin}\n"
              "colorspaces:\n  - !<ColorSpace> {name: lin}\n"
              "  - !<ColorSpace>\n    name: half_lut\n"
              "    from_scene_reference: !<FileTransform>\n"
              "      {src: half.spi1d, interpolation: linear}\n";
  }
  const Image grey = [] {
    Image image(16, 12, 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
      image.pixels[i] = i % 4 == 3 ? 1.0f : 3.0f;
    }
    return image;
  }();
  for (float sharpen : {0.0f, 1e-6f}) {
    SCOPED_TRACE(sharpen == 0.0f ? "output in the resolve pass" : "output pass");
    ResolveOptions options;
    options.color.ocioConfig = dir + "/config.ocio";
    options.color.bracket = "half_lut";
    options.sharpen = sharpen;
    Resolver resolver(*context_, options);
    ResolveInput input;
    input.color = &grey;
    const Image out = resolver.resolve(input);
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
      ASSERT_NEAR(out.pixels[i], grey.pixels[i], 1e-4f) << "value " << i;
    }
  }
}

TEST_F(ResolverTest, MismatchedPlaneSizeIsAnError) {
  auto scene = scenes::makeScene("static", 32, 20);
  Resolver resolver(*context_, ResolveOptions{});
  scenes::SceneFrame frame = scene->render(1, settings_);
  Image smallDepth(16, 20, 1);
  ResolveInput input;
  input.color = &frame.color;
  input.depth = &smallDepth;
  try {
    resolver.resolve(input);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("depth is 16x20 but color is 32x20"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace taa
