// The bundle in a host that behaves like one built on the official SDK's host-support library
// (Natron's): clip preferences with remapped components, overscan AOVs, frames outside the
// clip, SequentialRender, purge caches, render scales that differ in x and y, non-square
// pixels. Renders are compared with taatool's output, or with a C ABI node given the
// contract's values directly.
#include <cmath>
#include <cstring>
#include <vector>

#include "ofx_host_fixture.h"
#include "taa/taa.h"

namespace taa::ofxtest {
namespace {

std::string clipArgument(const char* prefix, const char* clip) {
  return std::string(prefix) + clip;
}

TEST_F(OfxHostTest, ClipPreferencesDeclareOutputAndKeepDepthOneChannel) {
  auto effect = instanceWithoutPreferences();
  PropertySet preferences;
  ASSERT_EQ(host_.clipPreferences(*effect, preferences), kOfxStatOK);
  // ofx_abi_strings_test holds kOfxImagePreMultiplied against the specification's value.
  EXPECT_EQ(preferences.getString(kOfxImageEffectPropPreMultiplication), kOfxImagePreMultiplied);
  EXPECT_EQ(preferences.getInt(kOfxImageEffectFrameVarying), 1);
  EXPECT_EQ(preferences.getString(clipArgument(kOfxImageClipPropComponentsPrefix, "Output")),
            kOfxImageComponentRGBA);
  // The host's default for every input is RGBA (the most chromatic input): depth must say Alpha.
  EXPECT_EQ(preferences.getString(clipArgument(kOfxImageClipPropComponentsPrefix, "Depth")),
            kOfxImageComponentAlpha);
  EXPECT_EQ(preferences.getString(clipArgument(kOfxImageClipPropComponentsPrefix, "Motion")),
            kOfxImageComponentRGB);
  EXPECT_EQ(descriptor_.props.getInt(kOfxImageEffectPropSupportsMultipleClipPARs), 0);
  destroy(effect);
}

// With the preferences honoured, depth arrives as one channel and the renders are taatool's.
TEST_F(OfxHostTest, AlphaDepthResolvesLikeTaatool) {
  auto effect = instance();
  EXPECT_EQ(effect->clips.at("Depth").components, kOfxImageComponentAlpha);
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  destroy(effect);
}

// A host that maps the Alpha depth clip to RGBA whatever the plugin asks puts depth in A.
TEST_F(OfxHostTest, DepthRemappedToRgbaIsReadFromAlpha) {
  auto effect = instanceWithoutPreferences();
  PropertySet preferences;
  ASSERT_EQ(host_.clipPreferences(*effect, preferences, false), kOfxStatOK);
  EXPECT_EQ(effect->clips.at("Depth").components, kOfxImageComponentRGBA);
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  destroy(effect);
}

// Overscan AOVs: depth and motion larger than the source (6 pixels more on every side, the
// frame centred in them). The pixels over the source's are the files' pixels: taatool's result.
TEST_F(OfxHostTest, OverscanDepthAndMotionResolveLikeTaatool) {
  auto effect = instance();
  for (const char* clip : {"Depth", "Motion"}) {
    effect->clips.at(clip).bounds = {kBounds.x1 - 6, kBounds.y1 - 6, kBounds.x2 + 6,
                                     kBounds.y2 + 6};
  }
  for (int f = kFirst; f <= kLast; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  destroy(effect);
}

// Depth and motion smaller than the source (2 pixels less on every side): the border has no
// depth (no hit) and no motion, the rest resolves as usual.
TEST_F(OfxHostTest, SmallerDepthAndMotionAreAccepted) {
  auto effect = instance();
  for (const char* clip : {"Depth", "Motion"}) {
    effect->clips.at(clip).bounds = {kBounds.x1 + 2, kBounds.y1 + 2, kBounds.x2 - 2,
                                     kBounds.y2 - 2};
  }
  Image last;
  for (int f = kFirst; f <= kLast; ++f) last = render(*effect, f);
  const Image reference = expected(kLast);
  ASSERT_EQ(last.pixels.size(), reference.pixels.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < last.pixels.size(); ++i) {
    ASSERT_TRUE(std::isfinite(last.pixels[i]));
    sum += std::fabs(last.pixels[i] - reference.pixels[i]);
  }
  EXPECT_LT(sum / double(last.pixels.size()), 1e-2);
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  destroy(effect);
}

// The host asks for frames outside the clip (1-8): frames needed stay inside it, and the output
// holds the clip's first or last resolved frame.
TEST_F(OfxHostTest, FramesOutsideTheClipHoldItsEnds) {
  auto effect = instance();
  PropertySet in, out;
  const std::string sourceRange = clipArgument(kOfxImageClipPropFrameRangePrefix, "Source");
  in.set(kOfxPropTime, {10.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  EXPECT_EQ(out.getDouble(sourceRange, 0), 1.0);
  EXPECT_EQ(out.getDouble(sourceRange, 1), 8.0);
  in.set(kOfxPropTime, {-3.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  EXPECT_EQ(out.getDouble(sourceRange, 0), 1.0);
  EXPECT_EQ(out.getDouble(sourceRange, 1), 1.0);

  EXPECT_LE(maxDifference(render(*effect, 10), expected(8)), 1e-5f);
  EXPECT_LE(maxDifference(render(*effect, 9), expected(8)), 1e-5f);
  EXPECT_LE(maxDifference(render(*effect, -3), expected(1)), 1e-5f);
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  destroy(effect);
}

// History from the clip's start needs the frames in order (1); a bounded history renders
// exactly in any order (2).
TEST_F(OfxHostTest, SequentialRenderFollowsHistoryFrames) {
  auto effect = instance();
  // The descriptor follows the default mode, the window resolve: any order.
  EXPECT_EQ(descriptor_.props.getInt(kOfxImageEffectInstancePropSequentialRender), 0);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 1);
  effect->params.at("historyFrames").intValue = 3;
  EXPECT_EQ(host_.parameterChanged(*effect, "historyFrames"), kOfxStatOK);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 2);
  effect->params.at("historyFrames").intValue = 0;
  EXPECT_EQ(host_.parameterChanged(*effect, "historyFrames"), kOfxStatOK);
  EXPECT_EQ(effect->props.getInt(kOfxImageEffectInstancePropSequentialRender), 1);
  destroy(effect);
}

// Purge caches frees the render threads' nodes: the next frame is resolved from the clip start
// again (its frames fetched again), with the same result.
TEST_F(OfxHostTest, PurgeCachesFreesTheHistory) {
  auto effect = instance();
  for (int f = kFirst; f <= 5; ++f) render(*effect, f);
  const HostClip& source = effect->clips.at("Source");
  int served = source.imagesServed;
  render(*effect, 6);
  EXPECT_EQ(source.imagesServed - served, 1);  // in order: one frame pushed

  EXPECT_EQ(host_.action(kOfxActionPurgeCaches, effect.get()), kOfxStatOK);
  served = source.imagesServed;
  EXPECT_LE(maxDifference(render(*effect, 7), expected(7)), 1e-5f);
  EXPECT_EQ(source.imagesServed - served, 7);  // frames 1-7 again
  destroy(effect);
}

float radicalInverse(int index, int base) {
  double result = 0.0, f = 1.0 / base;
  for (; index > 0; index /= base, f /= base) result += f * (index % base);
  return float(result);
}

taa_buffer topFirstBuffer(const Image& image) {
  taa_buffer b;
  std::memset(&b, 0, sizeof b);
  b.data = const_cast<float*>(image.pixels.data());
  b.width = image.width;
  b.height = image.height;
  b.channels = image.channels;
  b.type = TAA_PIXEL_FLOAT;
  return b;
}

// The contract for a render scale (sx, sy): the images are sx, sy times the size of the render
// the motion vectors and the Halton jitter were made for, so vector and jitter x scale by sx and
// y by sy. Stated directly to a C ABI node: vectors given pre-scaled, jitter given per frame.
Image resolveScaledWithNode(int lastFrame, double sx, double sy) {
  taa_node* node = nullptr;
  EXPECT_EQ(taa_node_create(nullptr, &node), TAA_OK) << taa_last_error();
  EXPECT_EQ(taa_node_set_float(node, "depth-nohit", 1e9f), TAA_OK);
  Image output(64, 40, 4);
  for (int f = kFirst; f <= lastFrame; ++f) {
    Image motion = OfxHostTest::motionFrame(f);
    for (std::size_t p = 0; p < motion.pixels.size(); p += 2) {
      motion.pixels[p] *= float(sx);
      motion.pixels[p + 1] *= float(sy);
    }
    const Image& color = OfxHostTest::colorFrame(f);
    const Image& depth = OfxHostTest::depthFrame(f);
    const taa_buffer c = topFirstBuffer(color), d = topFirstBuffer(depth),
                     m = topFirstBuffer(motion);
    taa_frame frame;
    taa_frame_init(&frame);
    frame.frame = f;
    frame.color = &c;
    frame.depth = &d;
    frame.motion = &m;
    frame.has_jitter = 1;
    frame.jitter[0] = float(sx) * (radicalInverse(f, 2) - 0.5f);
    frame.jitter[1] = float(sy) * (radicalInverse(f, 3) - 0.5f);
    EXPECT_EQ(taa_node_push_frame(node, &frame), TAA_OK) << taa_node_last_error(node);
  }
  const taa_buffer out = topFirstBuffer(output);
  EXPECT_EQ(taa_node_read_output(node, &out), TAA_OK) << taa_node_last_error(node);
  taa_node_destroy(node);
  return output;
}

TEST_F(OfxHostTest, RenderScaleAppliesPerAxis) {
  auto effect = instance();
  for (const auto& [sx, sy] : {std::pair{1.0, 0.5}, std::pair{0.5, 1.0}}) {
    Image rendered;
    for (int f = kFirst; f <= kLast; ++f) rendered = render(*effect, f, kOfxStatOK, sx, sy);
    const Image reference = resolveScaledWithNode(kLast, sx, sy);
    EXPECT_LE(maxDifference(rendered, reference), 1e-5f) << "scale " << sx << ", " << sy;
    // The two axes matter: the same scale in both gives another image.
    EXPECT_GT(maxDifference(reference, resolveScaledWithNode(kLast, sx, sx)), 1e-3f);
  }
  destroy(effect);
}

// Non-square pixels: the values are per pixel, so a pixel aspect ratio of 2 on every clip gives
// taatool's result; depth on another ratio than the colour's is an error, not a silent
// misregistration.
TEST_F(OfxHostTest, NonSquarePixels) {
  auto effect = instance();
  for (auto& [name, clip] : effect->clips) clip.pixelAspectRatio = 2.0;
  for (int f = kFirst; f <= 3; ++f) {
    EXPECT_LE(maxDifference(render(*effect, f), expected(f)), 1e-5f) << "frame " << f;
  }
  effect->clips.at("Depth").pixelAspectRatio = 1.0;
  render(*effect, 4, kOfxStatFailed);
  const std::string message = host_.persistentMessage(*effect);
  EXPECT_NE(message.find("Depth clip at frame 4 has pixel aspect ratio 1, the Source clip 2"),
            std::string::npos)
      << message;
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
