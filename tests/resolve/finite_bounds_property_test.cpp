// Property tests of the resolve (real GL, real OCIO): random finite input over the whole float
// range, in colour, depth, motion and jitter, through both modes and both output types. Every
// output value is finite and, in the default bracket's working space, within the range of the
// input samples that fed the frame widened by that range on each side, and not beyond the
// working range's ends unless an input is (docs/RELIABILITY.md, "Finite in, finite out").
// Issue 25, defect 4 is the case they would have found: a 10x10 patch at -1000 gave +FLT_MAX
// neighbours in the next frame, one at -1e4 gave them in the window mode's frame.
#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "color/shipped_config.h"
#include "gl/context.h"
#include "resolve/resolver.h"
#include "resolve/window_resolver.h"

namespace taa {
namespace {

namespace OCIO = OCIO_NAMESPACE;

constexpr int kWidth = 24, kHeight = 16, kFrames = 6;

// Linear -> the default bracket's working space, by OCIO's CPU processor on the shipped config.
class WorkingSpace {
 public:
  WorkingSpace() {
    std::istringstream text(color::shippedConfigText());
    const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromStream(text);
    processor_ = config->getProcessor("linear", ResolveOptions{}.color.bracket.c_str())
                     ->getDefaultCPUProcessor();
  }
  float operator()(float linear) const {
    float rgb[3] = {linear, linear, linear};
    processor_->applyRGB(rgb);
    return rgb[0];
  }

 private:
  OCIO::ConstCPUProcessorRcPtr processor_;
};

// One random frame: mostly ordinary values, some over the whole float range (both signs), a
// patch of one extreme value, zeros; finite depth (some pixels without a hit) and motion.
struct RandomFrame {
  Image color{kWidth, kHeight, 4}, depth{kWidth, kHeight, 1}, motion{kWidth, kHeight, 2};
  glm::vec2 jitter{0.0f};
};

// Each seed draws its own extremes: how far up and down the values reach (so that a huge
// output is a violation wherever the inputs did not reach that far).
struct Extremes {
  float lowest, highest;
};

Extremes randomExtremes(std::mt19937& random) {
  const float lows[] = {-0.5f, -1000.0f, -1e4f, -65504.0f, -1e20f, -std::numeric_limits<float>::max()};
  const float highs[] = {4.0f, 1000.0f, 65504.0f, 1e20f, std::numeric_limits<float>::max()};
  return {lows[random() % 6], highs[random() % 5]};
}

// A value in [lowest, highest], log-uniform in magnitude from 1e-30 up, either sign.
float anyFloat(std::mt19937& random, Extremes extremes) {
  const bool negative = random() % 2;
  const float reach = negative ? -extremes.lowest : extremes.highest;
  const float exponent =
      std::uniform_real_distribution<float>(-30.0f, std::log10(reach))(random);
  const float magnitude = std::min(std::pow(10.0f, exponent), reach);
  return negative ? -magnitude : magnitude;
}

RandomFrame randomFrame(std::mt19937& random, Extremes extremes) {
  RandomFrame f;
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float patchValue = random() % 2 ? extremes.lowest : anyFloat(random, extremes);
  const int px = int(random() % (kWidth - 6)), py = int(random() % (kHeight - 6));
  const Extremes wide = {-std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool inPatch = x >= px && x < px + 6 && y >= py && y < py + 6;
      float* c = f.color.at(x, y);
      for (int ch = 0; ch < 4; ++ch) {
        const float pick = unit(random);
        c[ch] = inPatch ? patchValue : pick < 0.8f ? 4.0f * unit(random)
                                     : pick < 0.9f ? anyFloat(random, extremes) : 0.0f;
      }
      f.depth.at(x, y)[0] = unit(random) < 0.1f ? std::numeric_limits<float>::infinity()
                                                : std::abs(anyFloat(random, wide)) + 1e-6f;
      const bool wild = unit(random) < 0.05f;
      f.motion.at(x, y)[0] = wild ? anyFloat(random, wide) : 6.0f * unit(random) - 3.0f;
      f.motion.at(x, y)[1] = wild ? anyFloat(random, wide) : 6.0f * unit(random) - 3.0f;
    }
  }
  f.jitter = {unit(random) - 0.5f, unit(random) - 0.5f};
  return f;
}

struct Bounds {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;  // working values of RGB inputs
};

void widen(Bounds& bounds, const RandomFrame& frame, const WorkingSpace& working) {
  for (int i = 0; i < kWidth * kHeight; ++i) {
    for (int ch = 0; ch < 3; ++ch) {
      const float w = working(frame.color.pixels[std::size_t(i) * 4 + ch]);
      bounds.lo = std::min(bounds.lo, w);
      bounds.hi = std::max(bounds.hi, w);
    }
  }
}

// Checks one output against the inputs that fed it; returns the number of violations.
int violations(const Image& out, const Bounds& in, const WorkingSpace& working,
               const std::string& what) {
  const float spread = in.hi - in.lo;
  const float bottom = working(-65504.0f), top = working(65504.0f);
  const float lo = std::max(in.lo - spread, std::min(bottom, in.lo));
  const float hi = std::min(in.hi + spread, std::max(top, in.hi));
  const float slack = 1e-4f * std::max(1.0f, spread);
  int bad = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    for (int ch = 0; ch < 4; ++ch) {
      const float v = out.pixels[std::size_t(i) * 4 + ch];
      bool ok = std::isfinite(v);
      if (ok && ch < 3) {
        const float w = working(v);
        ok = w >= lo - slack && w <= hi + slack;
      }
      if (!ok && ++bad <= 3) {
        ADD_FAILURE() << what << ": pixel (" << i % kWidth << ", " << i / kWidth << ") channel "
                      << ch << " = " << v << "; inputs' working range [" << in.lo << ", "
                      << in.hi << "], allowed [" << lo << ", " << hi << "]";
      }
    }
  }
  return bad;
}

ResolveInput inputOf(const RandomFrame& f) {
  ResolveInput input;
  input.color = &f.color;
  input.depth = &f.depth;
  input.motion = &f.motion;
  input.jitter = f.jitter;
  return input;
}

class FiniteBoundsProperty : public ::testing::Test {
 protected:
  void SetUp() override { context_ = gl::Context::create(gl::Backend::Auto); }
  std::unique_ptr<gl::Context> context_;
  WorkingSpace working_;
};

TEST_F(FiniteBoundsProperty, HistoryModeOutputIsFiniteAndWithinTheInputsRange) {
  ResolveOptions options;
  options.mode = ResolveMode::History;
  Resolver resolver(*context_, options);
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 random(seed);
    const Extremes extremes = randomExtremes(random);
    resolver.resetHistory();
    Bounds seen;  // history carries every frame since the reset
    for (int frame = 1; frame <= kFrames; ++frame) {
      const RandomFrame f = randomFrame(random, extremes);
      widen(seen, f, working_);
      const SampleType type = frame % 2 ? SampleType::Float : SampleType::Half;
      const Image out = resolver.resolve(inputOf(f), type).toFloat();
      ASSERT_EQ(violations(out, seen, working_,
                           "history, seed " + std::to_string(seed) + ", frame " +
                               std::to_string(frame)),
                0);
    }
  }
}

TEST_F(FiniteBoundsProperty, WindowModeOutputIsFiniteAndWithinTheInputsRange) {
  ResolveOptions options;
  options.mode = ResolveMode::Window;
  options.window.radius = 2;
  WindowResolver resolver(*context_, options);
  for (unsigned seed = 1; seed <= 24; ++seed) {
    std::mt19937 random(100 + seed);
    const Extremes extremes = randomExtremes(random);
    resolver.clear();
    std::vector<RandomFrame> frames;
    for (int frame = 0; frame < 5; ++frame) {
      frames.push_back(randomFrame(random, extremes));
      resolver.addFrame(frame, inputOf(frames.back()));
    }
    Bounds seen;
    for (const RandomFrame& f : frames) widen(seen, f, working_);
    for (int frame = 1; frame <= 3; ++frame) {
      const int first = std::max(0, frame - 2), last = std::min(4, frame + 2);
      for (SampleType type : {SampleType::Float, SampleType::Half}) {
        const Image out = resolver.resolve(frame, first, last, type).toFloat();
        ASSERT_EQ(violations(out, seen, working_,
                             "window, seed " + std::to_string(seed) + ", frame " +
                                 std::to_string(frame)),
                  0);
      }
    }
  }
}

// The probe's case itself: a 10x10 patch at -1000 (history) and -1e4 (window) in one frame of
// an ordinary image; no neighbour may come back near float's maximum.
TEST_F(FiniteBoundsProperty, ALargeNegativePatchGivesNoHugeNeighbours) {
  Image plain(kWidth, kHeight, 4);
  for (int i = 0; i < kWidth * kHeight; ++i) {
    for (int ch = 0; ch < 4; ++ch) {
      plain.pixels[std::size_t(i) * 4 + ch] = ch == 3 ? 1.0f : 0.2f + 0.01f * float(i % 7);
    }
  }
  auto withPatch = [&](float value) {
    Image patched = plain;
    for (int y = 3; y < 13; ++y) {
      for (int x = 7; x < 17; ++x) std::fill_n(patched.at(x, y), 3, value);
    }
    return patched;
  };
  auto largest = [](const Image& image) {
    float m = 0.0f;
    for (float v : image.pixels) m = std::max(m, v);
    return m;
  };
  // The bundled sample's case: everything moves by a fraction of a pixel, so history is
  // resampled between texels.
  Image depth(kWidth, kHeight, 1), motion(kWidth, kHeight, 2);
  std::fill(depth.pixels.begin(), depth.pixels.end(), 5.0f);
  for (int i = 0; i < kWidth * kHeight; ++i) {
    motion.pixels[std::size_t(i) * 2] = 0.37f;
    motion.pixels[std::size_t(i) * 2 + 1] = -0.21f;
  }
  Resolver history(*context_, ResolveOptions{});
  for (int frame = 1; frame <= 4; ++frame) {
    const Image color = frame == 2 ? withPatch(-1000.0f) : plain;
    ResolveInput input;
    input.color = &color;
    input.depth = &depth;
    input.motion = &motion;
    input.jitter = {0.3f * float(frame % 2) - 0.15f, 0.2f - 0.1f * float(frame % 3)};
    EXPECT_LE(largest(history.resolve(input, SampleType::Float).toFloat()), 2.0f)
        << "history, frame " << frame;
  }
  ResolveOptions windowOptions;
  windowOptions.mode = ResolveMode::Window;
  windowOptions.window.radius = 1;
  WindowResolver window(*context_, windowOptions);
  const Image patched = withPatch(-1e4f);
  for (int frame = 1; frame <= 3; ++frame) {
    ResolveInput input;
    input.color = frame == 2 ? &patched : &plain;
    input.depth = &depth;
    input.motion = &motion;
    input.jitter = {0.3f * float(frame % 2) - 0.15f, 0.2f - 0.1f * float(frame % 3)};
    window.addFrame(frame, input);
  }
  EXPECT_LE(largest(window.resolve(2, 1, 3, SampleType::Float).toFloat()), 2.0f);
}

}  // namespace
}  // namespace taa
