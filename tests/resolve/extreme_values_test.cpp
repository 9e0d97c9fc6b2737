// Colour at the edges of the float range through the whole resolve (real GL): nothing finite
// in becomes non-finite out, in this frame or in any later one through history (issue 17).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gl/context.h"
#include "resolve/resolver.h"

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
