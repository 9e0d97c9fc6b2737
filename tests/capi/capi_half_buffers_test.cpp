// Half host buffers through the C ABI. The node keeps half colour half (no widening on the CPU),
// so every (input, output) pair of buffer types must give the C++ Resolver's float result on the
// same values, narrowed with Imath::half where the output is half, bit for bit. In C++ rather
// than C to call the Resolver and Imath themselves and to see the NaN/Inf count, which
// importColor keeps from the C ABI. Frames come from the scene generator, as
// make_capi_fixture's do.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "capi/buffer_conversion.h"
#include "gl/context.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"
#include "scenegen/scene_library.h"
#include "taa/taa.h"

namespace {

using taa::HalfImage;
using taa::Image;
using taa::SampleType;
using taa::TypedImage;
using Imath::half;

constexpr int kWidth = 48, kHeight = 32, kFrames = 4;

struct Frame {
  int number = 0;
  HalfImage color;  // half so that float input can carry exactly the same values
  Image depth, motion;
};

std::vector<Frame> makeFrames() {
  auto scene = taa::scenes::makeScene("moving_object", kWidth, kHeight);
  taa::scenes::RenderSettings settings;
  settings.truthSamplesPerAxis = 1;  // the truth is not used here
  std::vector<Frame> frames;
  for (int number = 1; number <= kFrames; ++number) {
    taa::scenes::SceneFrame rendered = scene->render(number, settings);
    Frame frame;
    frame.number = number;
    frame.color = HalfImage(kWidth, kHeight, 4);
    for (std::size_t i = 0; i < rendered.color.pixels.size(); ++i) {
      frame.color.pixels[i] = half(rendered.color.pixels[i]);
    }
    frame.depth = std::move(rendered.depth);
    frame.motion = std::move(rendered.motion);
    frames.push_back(std::move(frame));
  }
  return frames;
}

// A tightly packed, top-first buffer over `view`'s samples.
taa_buffer bufferOver(taa::ImageView view) {
  taa_buffer buffer{};
  buffer.data = const_cast<void*>(view.data);
  buffer.width = view.width;
  buffer.height = view.height;
  buffer.channels = view.channels;
  buffer.type = view.type == SampleType::Half ? TAA_PIXEL_HALF : TAA_PIXEL_FLOAT;
  return buffer;
}

using NodePtr = std::unique_ptr<taa_node, decltype(&taa_node_destroy)>;

NodePtr makeNode() {
  taa_node* node = nullptr;
  EXPECT_EQ(taa_node_create(nullptr, &node), TAA_OK) << taa_last_error();
  return NodePtr(node, &taa_node_destroy);
}

// Pushes `frames` into a fresh node with colour buffers of type `in`, reading every output into
// a buffer of type `out`.
std::vector<TypedImage> resolve(const std::vector<Frame>& frames, SampleType in, SampleType out,
                                const char* outputType = "float") {
  NodePtr node = makeNode();
  std::vector<TypedImage> outputs;
  if (!node) return outputs;
  EXPECT_EQ(taa_node_set_string(node.get(), "output-type", outputType), TAA_OK)
      << taa_node_last_error(node.get());
  for (const Frame& f : frames) {
    const TypedImage color = in == SampleType::Half ? TypedImage(f.color)
                                                    : TypedImage(TypedImage(f.color).toFloat());
    const taa_buffer colorBuffer = bufferOver(&color);
    const taa_buffer depthBuffer = bufferOver(&f.depth);
    const taa_buffer motionBuffer = bufferOver(&f.motion);
    taa_frame frame;
    taa_frame_init(&frame);
    frame.frame = f.number;
    frame.color = &colorBuffer;
    frame.depth = &depthBuffer;
    frame.motion = &motionBuffer;
    EXPECT_EQ(taa_node_push_frame(node.get(), &frame), TAA_OK) << taa_node_last_error(node.get());
    TypedImage output(kWidth, kHeight, 4, out);
    const taa_buffer outputBuffer = bufferOver(&output);
    EXPECT_EQ(taa_node_read_output(node.get(), &outputBuffer), TAA_OK)
        << taa_node_last_error(node.get());
    outputs.push_back(std::move(output));
  }
  return outputs;
}

// The C++ Resolver's float results on float colour: what the node gave for float buffers before
// it kept half colour, and a reference that does not go through the node.
std::vector<Image> resolveDirectly(const std::vector<Frame>& frames) {
  auto context = taa::gl::Context::create(taa::gl::Backend::Auto);
  taa::Resolver resolver(*context, taa::ResolveOptions{});
  std::vector<Image> outputs;
  for (const Frame& f : frames) {
    const Image color = TypedImage(f.color).toFloat();
    taa::ResolveInput input;
    input.color = &color;
    input.depth = &f.depth;
    input.motion = &f.motion;
    input.jitter = taa::frameJitter(f.number, taa::JitterOptions{});
    outputs.push_back(resolver.resolve(input));
  }
  return outputs;
}

// Each sample's bits (half or float), so that comparisons tell -0 from 0 and see NaN.
std::vector<std::uint32_t> sampleBits(const TypedImage& image) {
  std::vector<std::uint32_t> bits;
  if (const HalfImage* halves = image.halves()) {
    for (half value : halves->pixels) bits.push_back(value.bits());
  } else {
    for (float value : image.floats()->pixels) {
      std::uint32_t word;
      std::memcpy(&word, &value, 4);
      bits.push_back(word);
    }
  }
  return bits;
}

// How many samples differ in type or bits.
int mismatches(const TypedImage& actual, const TypedImage& expected) {
  if (actual.type() != expected.type()) return -1;
  const std::vector<std::uint32_t> a = sampleBits(actual), e = sampleBits(expected);
  if (a.size() != e.size()) return -1;
  int count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += a[i] != e[i];
  return count;
}

// A float image as `type`: itself, or narrowed by Imath::half.
TypedImage as(const Image& image, SampleType type) {
  if (type == SampleType::Float) return image;
  HalfImage narrowed(image.width, image.height, image.channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) narrowed.pixels[i] = half(image.pixels[i]);
  return narrowed;
}

const char* name(SampleType type) { return type == SampleType::Half ? "half" : "float"; }

TEST(CapiHalfBuffers, EveryBufferTypePairGivesTheFloatResult) {
  const std::vector<Frame> frames = makeFrames();
  const std::vector<Image> reference = resolveDirectly(frames);
  const SampleType pairs[][2] = {{SampleType::Float, SampleType::Float},
                                 {SampleType::Half, SampleType::Half},
                                 {SampleType::Half, SampleType::Float},
                                 {SampleType::Float, SampleType::Half}};
  for (const auto& pair : pairs) {
    const std::vector<TypedImage> outputs = resolve(frames, pair[0], pair[1]);
    ASSERT_EQ(outputs.size(), frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      EXPECT_EQ(mismatches(outputs[i], as(reference[i], pair[1])), 0)
          << name(pair[0]) << " in, " << name(pair[1]) << " out, frame " << frames[i].number;
    }
  }
}

// "output-type" half: the result is read back from GL as half (rounded as Imath narrows), so a
// half buffer gets the narrowed float result bit for bit and a float buffer its widening.
TEST(CapiHalfBuffers, HalfReadBackGivesTheNarrowedResult) {
  const std::vector<Frame> frames = makeFrames();
  const std::vector<Image> reference = resolveDirectly(frames);
  for (SampleType out : {SampleType::Half, SampleType::Float}) {
    const std::vector<TypedImage> outputs = resolve(frames, SampleType::Half, out, "half");
    ASSERT_EQ(outputs.size(), frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const TypedImage narrowed = as(reference[i], SampleType::Half);
      const TypedImage expected =
          out == SampleType::Half ? narrowed : TypedImage(narrowed.toFloat());
      EXPECT_EQ(mismatches(outputs[i], expected), 0)
          << name(out) << " buffer, frame " << frames[i].number;
    }
  }
  NodePtr node = makeNode();
  EXPECT_EQ(taa_node_set_string(node.get(), "output-type", "double"), TAA_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(taa_node_last_error(node.get())).find("float|half"), std::string::npos)
      << taa_node_last_error(node.get());
}

TEST(CapiHalfBuffers, NonFiniteHalfColorResolvesAsZero) {
  std::vector<Frame> dirty = makeFrames();
  std::vector<Frame> clean = dirty;
  const half values[] = {std::numeric_limits<half>::infinity(),
                         -std::numeric_limits<half>::infinity(),
                         std::numeric_limits<half>::quiet_NaN()};
  for (Frame& frame : dirty) {
    for (int k = 0; k < 3; ++k) frame.color.at(5 + 9 * k, 7 + 6 * k)[k] = values[k];
  }
  for (Frame& frame : clean) {
    for (int k = 0; k < 3; ++k) frame.color.at(5 + 9 * k, 7 + 6 * k)[k] = half(0.0f);
  }
  const std::vector<TypedImage> fromDirty = resolve(dirty, SampleType::Half, SampleType::Half);
  const std::vector<TypedImage> fromClean = resolve(clean, SampleType::Half, SampleType::Half);
  ASSERT_EQ(fromDirty.size(), fromClean.size());
  for (std::size_t i = 0; i < fromDirty.size(); ++i) {
    EXPECT_EQ(mismatches(fromDirty[i], fromClean[i]), 0) << "frame " << dirty[i].number;
  }
}

// 2x1 pixels of 3 channels: one value that is not a float's round number, the three
// non-finite kinds, the largest half and -0.
half fromBits(std::uint16_t bits) {
  half value;
  value.setBits(bits);
  return value;
}

const std::uint16_t kHalfInput[6] = {half(0.1f).bits(), 0x7c00, 0x7e00, 0xfc00, 0x7bff, 0x8000};

TEST(CapiHalfBuffers, HalfColorImportsAsHalfWithNonFiniteScrubbedAndCounted) {
  const taa_buffer buffer = bufferOver(taa::ImageView(kHalfInput, SampleType::Half, 2, 1, 3));
  int nonFinite = -1;
  const TypedImage color = taa::capi::importColor(buffer, &nonFinite);
  ASSERT_EQ(color.type(), SampleType::Half);
  EXPECT_EQ(nonFinite, 3);
  const std::vector<std::uint32_t> expected = {kHalfInput[0], 0, 0, 0x3c00,  // missing A = 1
                                               0,             0x7bff, 0x8000, 0x3c00};
  EXPECT_EQ(sampleBits(color), expected);

  // The float path on the widened values (what the node did before) gives the same values.
  std::vector<float> widened;
  for (std::uint16_t bits : kHalfInput) widened.push_back(float(fromBits(bits)));
  int floatNonFinite = -1;
  const TypedImage floats = taa::capi::importColor(
      bufferOver(taa::ImageView(widened.data(), SampleType::Float, 2, 1, 3)), &floatNonFinite);
  ASSERT_EQ(floats.type(), SampleType::Float);
  EXPECT_EQ(floatNonFinite, 3);
  EXPECT_EQ(mismatches(floats, color.toFloat()), 0);
}

TEST(CapiHalfBuffers, ExportCopiesTheBufferTypeAndConvertsTheOther) {
  HalfImage halves(2, 1, 4);
  for (std::size_t i = 0; i < 6; ++i) halves.pixels[i] = fromBits(kHalfInput[i]);
  halves.pixels[6] = half(-2.5f);
  halves.pixels[7] = half(1.0f);
  Image floats(2, 1, 4);
  floats.pixels = {0.1f, 1e-8f, 70000.0f, 0.5f, 1.0f / 3.0f, -0.0f, 2049.0f, 1.0f};

  for (const TypedImage& image : {TypedImage(halves), TypedImage(floats)}) {
    for (SampleType type : {SampleType::Half, SampleType::Float}) {
      TypedImage expected = image.type() == SampleType::Half && type == SampleType::Half
                                ? image
                                : as(image.toFloat(), type);
      if (image.type() == SampleType::Float && type == SampleType::Half) {
        expected.halves()->pixels[2] = half(65504.0f);  // 70000 clamps: see the next test
      }
      TypedImage output(2, 1, 4, type);
      taa::capi::exportColor(image, bufferOver(&output));
      EXPECT_EQ(mismatches(output, expected), 0)
          << name(image.type()) << " image into a " << name(type) << " buffer";
    }
  }
}

// Issue 17: a float result beyond half's range became +-Inf in a host's half buffer. It is the
// largest finite half instead, as the GL read-back into a half output clamps (finite_range.glsl).
TEST(CapiHalfBuffers, FloatBeyondHalfRangeClampsInAHalfBuffer) {
  Image floats(2, 1, 4);
  floats.pixels = {70000.0f, -1e30f, std::numeric_limits<float>::max(), 1.0f,
                   65519.0f, -65520.0f, 0.5f, 1.0f};
  TypedImage output(2, 1, 4, SampleType::Half);
  taa::capi::exportColor(TypedImage(floats), bufferOver(&output));
  const std::vector<float> expected = {65504.0f, -65504.0f, 65504.0f, 1.0f,
                                       65504.0f, -65504.0f, 0.5f, 1.0f};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(float(output.halves()->pixels[i]), expected[i]) << "value " << floats.pixels[i];
  }
}

}  // namespace
