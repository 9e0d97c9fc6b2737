// Colour at the edges of the float range through the whole resolve (real GL): nothing finite
// in becomes non-finite out, in this frame or in any later one through history (issue 17).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gl/context.h"
#include "resolve/resolver.h"
#include "resolve/window_resolver.h"

namespace taa {
namespace {

constexpr int kWidth = 16, kHeight = 8;

// Columns `width` pixels wide of `values` (cycling), RGB = value, A = 1. At width 4 pixels 1
// and 2 of a column see only their own value in their 3x3 neighbourhood.
Image columns(const std::vector<float>& values, int width = 4) {
  Image image(kWidth, kHeight, 4);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float v = values[std::size_t(x / width) % values.size()];
      float* p = image.at(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 1.0f;
    }
  }
  return image;
}

// Values a renderer or comp produces out of gamut, down to half float's lowest.
const std::vector<float> kNegatives = {-5.0f, -1000.0f, -65504.0f, -0.5f};

int nonFiniteCount(const float* values, std::size_t count) {
  int bad = 0;
  for (std::size_t i = 0; i < count; ++i) bad += std::isfinite(values[i]) ? 0 : 1;
  return bad;
}

class ExtremeValuesTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = gl::Context::create(gl::Backend::Auto); }

  TypedImage resolve(Resolver& resolver, const Image& color, SampleType type,
                     glm::vec2 jitter = {0.0f, 0.0f}) {
    ResolveInput input;
    input.color = &color;
    input.jitter = jitter;
    return resolver.resolve(input, type);
  }

  std::unique_ptr<gl::Context> context_;
};

// Defect 2: with the default bracket, -5 and below became +Inf and stayed in history.
TEST_F(ExtremeValuesTest, NegativeColourStaysFiniteThroughHistoryWithEveryShippedBracket) {
  for (const char* bracket : {"taa_reinhard", "taa_log2", "none"}) {
    ResolveOptions options;
    options.color.bracket = bracket;
    Resolver resolver(*context_, options);
    const Image negative = columns(kNegatives);
    const Image normal = columns({0.5f});
    for (int frame = 1; frame <= 4; ++frame) {
      // Frames 1 and 2 hold the negatives, 3 and 4 do not: history must recover too.
      const Image& color = frame <= 2 ? negative : normal;
      const TypedImage out = resolve(resolver, color, SampleType::Float,
                                     {0.25f * float(frame % 2), -0.125f});
      const Image& result = *out.floats();
      ASSERT_EQ(nonFiniteCount(result.pixels.data(), result.pixels.size()), 0)
          << bracket << ", frame " << frame;
      for (int x = 1; x < kWidth; x += 4) {
        // Inside a column the value comes back (to the bracket's float precision).
        const float expected = frame <= 2 ? kNegatives[std::size_t(x / 4)] : 0.5f;
        EXPECT_NEAR(result.at(x, 4)[0], expected, 1e-3f * std::abs(expected))
            << bracket << ", frame " << frame << ", column " << x;
      }
    }
  }
}

// Item 9: colour near float's maximum came back as NaN/Inf. A float output keeps it finite, a
// half output clamps it to half's largest finite value.
TEST_F(ExtremeValuesTest, ColourNearFloatMaxGivesFiniteOutputOfEitherType) {
  const float big = std::numeric_limits<float>::max();
  const Image color = columns({0.25f, big, -big, 3e38f, 1e20f});
  for (const char* bracket : {"taa_reinhard", "taa_log2", "none"}) {
    ResolveOptions options;
    options.color.bracket = bracket;
    Resolver resolver(*context_, options);
    for (int frame = 1; frame <= 3; ++frame) {
      const TypedImage asFloat = resolve(resolver, color, SampleType::Float);
      const Image& f = *asFloat.floats();
      ASSERT_EQ(nonFiniteCount(f.pixels.data(), f.pixels.size()), 0) << bracket;
    }
    const Image h = resolve(resolver, color, SampleType::Half).toFloat();  // widened exactly
    EXPECT_EQ(nonFiniteCount(h.pixels.data(), h.pixels.size()), 0) << bracket;
    EXPECT_EQ(h.at(5, 3)[0], 65504.0f) << bracket;
    EXPECT_EQ(h.at(9, 3)[0], -65504.0f) << bracket;
  }
}

// The window resolve keeps colour as halves in its ring: a working value beyond half's range
// (no bracket, or a user bracket that does not compress) became Inf there and NaN in the
// gathered sum. Both output types come back finite, a half output clamped as above.
TEST_F(ExtremeValuesTest, WindowResolveOfColourNearFloatMaxIsFiniteInEitherType) {
  const float big = std::numeric_limits<float>::max();
  const Image color = columns({0.25f, big, -big, 3e38f, 1e20f});
  for (const char* bracket : {"taa_reinhard", "taa_log2", "none"}) {
    ResolveOptions options;
    options.mode = ResolveMode::Window;
    options.window.radius = 1;
    options.color.bracket = bracket;
    WindowResolver resolver(*context_, options);
    for (int frame = 1; frame <= 3; ++frame) {
      ResolveInput input;
      input.color = &color;
      input.jitter = {0.25f * float(frame % 2), -0.125f};
      resolver.addFrame(frame, input);
    }
    const TypedImage asFloat = resolver.resolve(2, 1, 3, SampleType::Float);
    const Image& f = *asFloat.floats();
    EXPECT_EQ(nonFiniteCount(f.pixels.data(), f.pixels.size()), 0) << bracket;
    EXPECT_NEAR(f.at(1, 3)[0], 0.25f, 1e-3f) << bracket;
    const Image h = resolver.resolve(2, 1, 3, SampleType::Half).toFloat();
    EXPECT_EQ(nonFiniteCount(h.pixels.data(), h.pixels.size()), 0) << bracket;
    EXPECT_EQ(h.at(5, 3)[0], 65504.0f) << bracket;
    EXPECT_EQ(h.at(9, 3)[0], -65504.0f) << bracket;
  }
}

// The window ring kept working-space colour as halves: with the default bracket (x / (x + 4)
// has 2^-11 of half between 0.9995 and 1) a flat highlight of 5000 came back as 4092 and one
// above 16380 as float's maximum. Every shipped bracket now returns them within 0.5% (the
// ring adds 4e-6; the rest is float arithmetic near the top of x / (x + 4): 0.23% at 60000).
TEST_F(ExtremeValuesTest, WindowResolveKeepsHighlightsToAHalfPercent) {
  const std::vector<std::vector<float>> groups = {{0.01f, 1.0f, 100.0f, 1000.0f},
                                                  {5000.0f, 20000.0f, 60000.0f, 65504.0f}};
  for (const char* bracket : {"taa_reinhard", "taa_log2", "none"}) {
    ResolveOptions options;
    options.mode = ResolveMode::Window;
    options.window.radius = 1;
    options.color.bracket = bracket;
    for (const std::vector<float>& values : groups) {
      const Image color = columns(values);
      WindowResolver resolver(*context_, options);
      for (int frame = 1; frame <= 3; ++frame) {
        ResolveInput input;
        input.color = &color;
        resolver.addFrame(frame, input);
      }
      const Image out = *resolver.resolve(2, 1, 3, SampleType::Float).floats();
      for (std::size_t i = 0; i < values.size(); ++i) {
        for (int x : {int(4 * i) + 1, int(4 * i) + 2}) {  // inside the column
          EXPECT_NEAR(out.at(x, 3)[0], values[i], 5e-3f * values[i])
              << bracket << ", value " << values[i] << ", x " << x;
        }
      }
    }
  }
}

// Found with the reliability tests: Lanczos' negative lobes beside a two-pixel highlight lift the
// reconstruction past 1 in the x / (x + 4) working space, whose inverse made it +Inf (100) or
// 103 from 40. The overshoot now stays within a bounded factor of the highlight.
TEST_F(ExtremeValuesTest, RingingBesideAHighlightStaysBounded) {
  for (float highlight : {40.0f, 100.0f, 1000.0f, 60000.0f}) {
    Resolver resolver(*context_, ResolveOptions{});
    const Image color = columns({highlight, 0.0f}, 2);
    const Image out = resolve(resolver, color, SampleType::Float, {0.499f, 0.499f}).toFloat();
    ASSERT_EQ(nonFiniteCount(out.pixels.data(), out.pixels.size()), 0) << highlight;
    for (float v : out.pixels) ASSERT_LE(v, 2.1f * highlight + 4.0f) << highlight;
  }
}

}  // namespace
}  // namespace taa
