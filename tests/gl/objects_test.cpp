#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/objects.h"
#include "gl_test_support.h"
#include "taa/error.h"
#include "util/image.h"

namespace taa::gl {
namespace {

using ::testing::HasSubstr;

struct FormatCase {
  GLenum internalFormat;
  int components;
  const char* name;
};

class TextureTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override { context_ = Context::create(GetParam()); }
  const Functions& gl() const { return context_->functions(); }
  std::unique_ptr<Context> context_;
};

// Distinct, non-trivial floats per texel and channel (fractions, negatives, large values),
// all normal numbers so no driver may flush them.
std::vector<float> texelData(int width, int height, int components) {
  std::vector<float> data;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < components; ++c) {
        data.push_back((static_cast<float>(x) + 0.1f) * (c % 2 ? -1.0f : 1.0f) +
                       static_cast<float>(y) * 1000.5f + static_cast<float>(c) * 1.0e6f / 3.0f);
      }
    }
  }
  return data;
}

// What a texture of `components` channels reads as in a shader: missing G/B are 0, A is 1.
float expectedRGBA(const std::vector<float>& data, size_t texel, int components, int channel) {
  if (channel < components) return data[texel * components + channel];
  return channel == 3 ? 1.0f : 0.0f;
}

TEST_P(TextureTest, UploadedTexelsAreSampledAndReadBackExactly) {
  const int width = 13, height = 7;
  const FormatCase formats[] = {
      {GL_RGBA32F, 4, "RGBA32F"}, {GL_RG32F, 2, "RG32F"}, {GL_R32F, 1, "R32F"}};
  // texelFetch addresses texels directly; texture() with nearest filtering at pixel centres
  // must agree, which pins down that uploads and gl_FragCoord share the same row order.
  const ShaderSource fetch = test::fragmentShader(
      "fetch.frag",
      "uniform sampler2D uTexture;\n"
      "void main() { outColor = texelFetch(uTexture, ivec2(gl_FragCoord.xy), 0); }\n");
  const ShaderSource sample = test::fragmentShader(
      "sample.frag",
      "uniform sampler2D uTexture;\n"
      "void main() {\n"
      "  outColor = texture(uTexture, gl_FragCoord.xy / vec2(textureSize(uTexture, 0)));\n"
      "}\n");
  for (const FormatCase& format : formats) {
    SCOPED_TRACE(format.name);
    const std::vector<float> data = texelData(width, height, format.components);
    Texture texture(gl(), width, height, format.internalFormat);
    EXPECT_EQ(texture.width(), width);
    EXPECT_EQ(texture.height(), height);
    texture.upload(data.data(), format.components);
    for (const ShaderSource& shader : {fetch, sample}) {
      SCOPED_TRACE(shader.name);
      const std::vector<float> pixels =
          test::renderPass(gl(), shader, width, height, [&](const Program& program) {
            texture.bind(0);
            program.set("uTexture", 0);
          });
      ASSERT_EQ(pixels.size(), static_cast<size_t>(width * height * 4));
      int mismatches = 0;
      for (size_t texel = 0; texel < static_cast<size_t>(width * height); ++texel) {
        for (int c = 0; c < 4; ++c) {
          const float expected = expectedRGBA(data, texel, format.components, c);
          if (pixels[texel * 4 + c] != expected && ++mismatches <= 3) {
            ADD_FAILURE() << "texel " << texel % width << "," << texel / width << " channel "
                          << c << ": got " << pixels[texel * 4 + c] << ", expected " << expected;
          }
        }
      }
      EXPECT_EQ(mismatches, 0);
    }
  }
}

// half -> float through OIIO (libImath's tables are not linked into the tests).
float widen(Imath::half h) {
  float f = 0.0f;
  OIIO::convert_pixel_values(OIIO::TypeHalf, &h, OIIO::TypeFloat, &f, 1);
  return f;
}

// Every finite half value, as RGBA halves (4 per texel), in a 128 x 128 texture.
std::vector<Imath::half> allFiniteHalves() {
  std::vector<Imath::half> halves;
  for (unsigned bits = 0; bits < 0x10000u; ++bits) {
    Imath::half h;
    h.setBits(static_cast<uint16_t>(bits));
    halves.push_back(h.isFinite() ? h : Imath::half(0.0f));
  }
  return halves;
}

TEST_P(TextureTest, HalfUploadIntoRgba16fSamplesExactly) {
  const int width = 128, height = 128;
  const std::vector<Imath::half> halves = allFiniteHalves();
  HalfImage image(width, height, 4);
  image.pixels.assign(halves.begin(), halves.end());
  const Image widened = TypedImage(image).toFloat();
  Texture texture(gl(), width, height, GL_RGBA16F);
  texture.upload(halves.data(), 4, GL_HALF_FLOAT);
  const ShaderSource fetch = test::fragmentShader(
      "fetch.frag",
      "uniform sampler2D uTexture;\n"
      "void main() { outColor = texelFetch(uTexture, ivec2(gl_FragCoord.xy), 0); }\n");
  const std::vector<float> pixels =
      test::renderPass(gl(), fetch, width, height, [&](const Program& program) {
        texture.bind(0);
        program.set("uTexture", 0);
      });
  int mismatches = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    // Subnormal halves are normal floats: none may be flushed.
    if (pixels[i] != widened.pixels[i] && ++mismatches <= 3) {
      ADD_FAILURE() << "half bits " << halves[i].bits() << ": got " << pixels[i];
    }
  }
  EXPECT_EQ(mismatches, 0);
}

// Reading a float attachment back as half must round as Imath does (to nearest, ties to even,
// beyond 65504 to infinity): the resolver reads half output this way, and files written from
// float used Imath. (Rendering into an RGBA16F target would not do: llvmpipe truncates there.)
TEST_P(TextureTest, FloatReadBackAsHalfRoundsLikeImath) {
  const int width = 256, height = 64;
  std::vector<float> values;
  for (unsigned bits = 0; values.size() < std::size_t(width) * height * 4; bits += 3) {
    Imath::half low, high;
    low.setBits(static_cast<uint16_t>(bits & 0x7bfe));
    high.setBits(static_cast<uint16_t>((bits & 0x7bfe) + 1));
    const float a = widen(low), b = widen(high);
    values.push_back(a + 0.5f * (b - a));    // a tie
    values.push_back(-(a + 0.25f * (b - a)));  // nearer the lower magnitude
    values.push_back(a + 0.75f * (b - a));   // nearer the upper
    values.push_back(65504.0f + float(bits % 64) * 16.0f);  // the top, and past it
  }
  Texture texture(gl(), width, height, GL_RGBA32F);
  texture.upload(values.data(), 4);
  const Framebuffer framebuffer(gl(), texture);
  std::vector<Imath::half> halves(values.size());
  framebuffer.readRGBA(halves.data(), GL_HALF_FLOAT);
  int mismatches = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (halves[i].bits() != Imath::half(values[i]).bits() && ++mismatches <= 3) {
      ADD_FAILURE() << values[i] << ": got bits " << halves[i].bits() << ", Imath "
                    << Imath::half(values[i]).bits();
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST_P(TextureTest, LinearFilteringBlendsNeighbours) {
  // Two texels 0 and 1 sampled halfway between their centres give exactly 0.5.
  Texture texture(gl(), 2, 1, GL_R32F, Texture::Filter::Linear);
  const float data[] = {0.0f, 1.0f};
  texture.upload(data, 1);
  const ShaderSource shader = test::fragmentShader(
      "linear.frag",
      "uniform sampler2D uTexture;\n"
      "void main() { outColor = texture(uTexture, vec2(0.5, 0.5)); }\n");
  const std::vector<float> pixels = test::renderPass(gl(), shader, 1, 1, [&](const Program& p) {
    texture.bind(1);
    p.set("uTexture", 1);
  });
  EXPECT_EQ(pixels[0], 0.5f);
}

TEST_P(TextureTest, RejectsBadArguments) {
  EXPECT_THROW(Texture(gl(), 0, 4, GL_RGBA32F), Error);
  EXPECT_THROW(Texture(gl(), 4, 4, GL_RGBA32UI), Error);
  Texture texture(gl(), 4, 4, GL_RGBA32F);
  const std::vector<float> data(4 * 4 * 5, 0.0f);
  EXPECT_THROW(texture.upload(data.data(), 5), Error);
  EXPECT_THROW(texture.upload(nullptr, 4), Error);
}

TEST_P(TextureTest, ObjectsMoveWithoutDoubleDeletion) {
  Texture first(gl(), 4, 4, GL_RGBA32F);
  const GLuint id = first.id();
  Texture second = std::move(first);
  EXPECT_EQ(second.id(), id);
  EXPECT_EQ(first.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state
  Framebuffer framebuffer(gl(), second);
  Framebuffer moved = std::move(framebuffer);
  EXPECT_NE(moved.id(), 0u);
  EXPECT_NO_THROW(checkError(gl(), "moving objects"));
}

TEST_P(TextureTest, CheckErrorNamesTheErrorAndTheStep) {
  gl().BindTexture(0x1234, 0);  // not a texture target: GL_INVALID_ENUM
  try {
    checkError(gl(), "binding a bogus target");
    FAIL() << "checkError did not throw";
  } catch (const Error& error) {
    EXPECT_THAT(error.description(), HasSubstr("GL_INVALID_ENUM"));
    EXPECT_THAT(error.description(), HasSubstr("binding a bogus target"));
  }
  EXPECT_NO_THROW(checkError(gl(), "nothing"));  // the error was consumed
}

// The window resolve's ring is one texture array of 2K+2 layers (resolve/window_budget):
// the probe says how many the driver makes, without allocating them.
TEST_P(TextureTest, TheLargestTextureArrayIsFoundWithoutAllocatingIt) {
  EXPECT_EQ(largestTextureArrayLayers(gl(), 64, 32, 34, GL_RGBA32UI), 34);
  // 34 layers of 4K RGBA32UI are 4.5 GB. A driver holding them all says 34; one that does not
  // (llvmpipe: about 1.6 GB a texture) says the most it makes, and it makes them.
  const int layers = largestTextureArrayLayers(gl(), 3840, 2160, 34, GL_RGBA32UI);
  EXPECT_GE(layers, 1);
  EXPECT_LE(layers, 34);
  if (layers < 34) {
    EXPECT_EQ(largestTextureArrayLayers(gl(), 3840, 2160, layers + 1, GL_RGBA32UI), layers);
  }
  EXPECT_NO_THROW(checkError(gl(), "probing"));  // the refused proxies left no error behind
  std::printf("largest RGBA32UI texture array at 3840x2160: %d layers; at 1920x1080: %d\n",
              layers, largestTextureArrayLayers(gl(), 1920, 1080, 64, GL_RGBA32UI));
}

INSTANTIATE_TEST_SUITE_P(Backends, TextureTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         test::backendParamName);

}  // namespace
}  // namespace taa::gl
