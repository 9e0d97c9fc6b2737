#include "io/frame_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::makeSpec;
using taa::test::contains;
using taa::test::errorOf;
using taa::test::scratchFolder;
using taa::test::writeImage;

using Names = std::vector<std::string>;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Runs `read`, expecting a taa::Error; returns it for inspection.
// Writes a 4x3 float EXR whose channel c of pixel p holds value(p, c).
void writeTestExr(const std::string& path, const std::vector<std::string>& channels,
                  const std::function<float(int, int)>& value, int width = 4, int height = 3) {
  std::vector<float> pixels;
  for (int p = 0; p < width * height; ++p) {
    for (int c = 0; c < int(channels.size()); ++c) pixels.push_back(value(p, c));
  }
  writeImage(path, makeSpec(width, height, channels), pixels);
}

AovLayout separateFilesLayout(const std::string& folder) {
  AovLayout layout;
  layout.color = {folder + "/beauty.%04d.exr", {"R", "G", "B", "A"}};
  layout.depth = AovSource{folder + "/depth.@@@@.exr", {"Z"}};
  layout.motion = AovSource{folder + "/mv.#.exr", {"u", "v"}};
  return layout;
}

// The three files of separateFilesLayout() for `frame`, sizes overridable.
void writeSeparateFiles(const std::string& folder, int frame, int depthWidth = 4,
                        int motionHeight = 3) {
  const std::string number = std::to_string(frame);
  const std::string padded = std::string(4 - number.size(), '0') + number;
  writeTestExr(folder + "/beauty." + padded + ".exr", {"R", "G", "B", "A"},
               [](int p, int c) { return float(p) + 0.1f * float(c + 1); });
  writeTestExr(
      folder + "/depth." + padded + ".exr", {"Z"}, [](int p, int) { return float(p + 1); },
      depthWidth, 3);
  writeTestExr(
      folder + "/mv." + padded + ".exr", {"u", "v"},
      [](int p, int c) { return c == 0 ? float(p) : -float(p); }, 4, motionHeight);
}

TEST(ReadFrame, CyclesMultiLayerFileConvertsToInternalConventions) {
  const std::string folder = scratchFolder();
  // Listed in a scrambled order; EXR stores them sorted by name anyway.
  const std::vector<std::string> channels = {
      "ViewLayer.Vector.Y", "ViewLayer.Combined.B", "ViewLayer.Depth.Z", "ViewLayer.Combined.R",
      "ViewLayer.Vector.X", "ViewLayer.Combined.A", "ViewLayer.Combined.G", "ViewLayer.Vector.Z",
      "ViewLayer.Vector.W", "ViewLayer.Normal.X"};
  const auto value = [&](int p, int c) -> float {
    const std::string& name = channels[c];
    if (name == "ViewLayer.Combined.R") return 1.0f + p;
    if (name == "ViewLayer.Combined.G") return 2.0f + p;
    if (name == "ViewLayer.Combined.B") return 3.0f + p;
    if (name == "ViewLayer.Combined.A") return 0.25f;
    if (name == "ViewLayer.Depth.Z") return p == 0 ? 1e10f : 10.0f + p;
    if (name == "ViewLayer.Vector.X") return 0.5f + p;
    if (name == "ViewLayer.Vector.Y") return 1.5f + p;
    return 99.0f;  // Vector.ZW (to next frame) and Normal must not be read
  };
  writeTestExr(folder + "/render.0007.exr", channels, value);

  const FrameData data = readFrame(cyclesLayout(folder + "/render.####.exr"), 7);
  const Image color = data.color.toFloat();

  EXPECT_EQ(data.frame, 7);
  EXPECT_EQ(data.colorPath, folder + "/render.0007.exr");
  EXPECT_EQ(data.colorSpec.width, 4);
  EXPECT_EQ(data.colorSpec.height, 3);
  EXPECT_EQ(data.nonFiniteColorValues, 0);
  ASSERT_EQ(color.channels, 4);
  ASSERT_EQ(data.depth.channels, 1);
  ASSERT_EQ(data.motion.channels, 2);
  for (int p = 0; p < 12; ++p) {
    const int x = p % 4;
    const int y = p / 4;
    SCOPED_TRACE("pixel " + std::to_string(p));
    EXPECT_EQ(color.at(x, y)[0], 1.0f + p);
    EXPECT_EQ(color.at(x, y)[1], 2.0f + p);
    EXPECT_EQ(color.at(x, y)[2], 3.0f + p);
    EXPECT_EQ(color.at(x, y)[3], 0.25f);
    EXPECT_EQ(data.depth.at(x, y)[0], p == 0 ? kInf : 10.0f + p);
    // Cycles: (X, Y) = previous - current with y up, so internal motion is (X, -Y).
    EXPECT_EQ(data.motion.at(x, y)[0], 0.5f + p);
    EXPECT_EQ(data.motion.at(x, y)[1], -(1.5f + p));
  }
}

TEST(ReadFrame, ChannelsComeInTheRequestedOrderNotTheFileOrder) {
  const std::string folder = scratchFolder();
  // Sorted in the file: alpha, beta, delta, gamma. beta lies inside the read range, unasked.
  writeTestExr(folder + "/c.exr", {"alpha", "beta", "gamma", "delta"},
               [](int p, int c) { return float(10 * c + p); });
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"gamma", "alpha", "delta"}};
  const FrameData data = readFrame(layout, 1);
  const Image color = data.color.toFloat();
  for (int p = 0; p < 12; ++p) {
    const float* rgba = color.at(p % 4, p / 4);
    EXPECT_EQ(rgba[0], float(20 + p));
    EXPECT_EQ(rgba[1], float(0 + p));
    EXPECT_EQ(rgba[2], float(30 + p));
    EXPECT_EQ(rgba[3], 1.0f);
  }
}

// The passes handed over band by band as they are decoded (PassBandReceiver: what the window
// resolve packs from) are the channels a whole-frame read gives, every pixel exactly once, in
// order, and `passes.image` stays empty; names and formats are set before any pixel.
TEST(ReadFrame, PassesHandedOverInBandsEqualTheWholeFrameRead) {
  const std::string folder = scratchFolder();
  constexpr int kWidth = 5, kHeight = 150;  // five bands of 32 rows, the last partial
  writeTestExr(folder + "/c.exr", {"A", "B", "DiffDir.R", "Emit.G", "G", "R", "Z"},
               [](int p, int c) { return float(100 * c) + 0.25f * float(p); }, kWidth, kHeight);
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  layout.passes = true;
  const FrameData whole = readFrame(layout, 1);
  ASSERT_EQ(whole.passes.names, Names({"Z", "DiffDir.R", "Emit.G"}));  // the order OIIO gives
  ASSERT_EQ(whole.passes.image.channels, 3);

  std::vector<float> banded;
  std::size_t nextPixel = 0;
  int calls = 0, bands = 0;
  const FrameData data = readFrame(
      layout, 1, {}, [&](const ExtraChannels& passes, int width, int height) -> PassBandSink {
        ++calls;
        EXPECT_EQ(passes.names, whole.passes.names);
        EXPECT_EQ(passes.formats.size(), 3u);
        EXPECT_EQ(width, kWidth);
        EXPECT_EQ(height, kHeight);
        return [&](std::size_t firstPixel, std::size_t count, const float* values) {
          ++bands;
          EXPECT_EQ(firstPixel, nextPixel);
          nextPixel = firstPixel + count;
          banded.insert(banded.end(), values, values + 3 * count);
        };
      });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(bands, 5);
  EXPECT_TRUE(data.passes.image.empty());
  EXPECT_EQ(data.passes.names, whole.passes.names);
  EXPECT_EQ(banded, std::vector<float>(whole.passes.image.pixels.begin(),
                                       whole.passes.image.pixels.end()));
  EXPECT_EQ(data.color.toFloat().pixels, whole.color.toFloat().pixels);
}

TEST(ReadFrame, SeparateFilesPerAovWithEveryPlaceholderKind) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 12);
  AovLayout layout = separateFilesLayout(folder);
  // A file whose vectors point to the next frame, y down, at half resolution.
  layout.motionConvention = {false, false, 2.0f};
  const FrameData data = readFrame(layout, 12);
  const Image color = data.color.toFloat();
  for (int p = 0; p < 12; ++p) {
    const int x = p % 4;
    const int y = p / 4;
    EXPECT_FLOAT_EQ(color.at(x, y)[0], p + 0.1f);
    EXPECT_FLOAT_EQ(color.at(x, y)[3], p + 0.4f);
    EXPECT_EQ(data.depth.at(x, y)[0], float(p + 1));
    EXPECT_EQ(data.motion.at(x, y)[0], -2.0f * p);
    EXPECT_EQ(data.motion.at(x, y)[1], 2.0f * p);
  }
}

TEST(ReadFrame, LayoutWithoutDepthAndMotionLeavesThemEmpty) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 1);
  AovLayout layout = separateFilesLayout(folder);
  layout.depth.reset();
  layout.motion.reset();
  const FrameData data = readFrame(layout, 1);
  EXPECT_FALSE(data.color.empty());
  EXPECT_TRUE(data.depth.empty());
  EXPECT_TRUE(data.motion.empty());
}

TEST(ReadFrame, ThreeChannelColorGetsOpaqueAlpha) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/rgb.exr", {"R", "G", "B"}, [](int p, int c) { return float(p + c); });
  AovLayout layout;
  layout.color = {folder + "/rgb.exr", {"R", "G", "B"}};
  const FrameData data = readFrame(layout, 1);
  const Image color = data.color.toFloat();
  ASSERT_EQ(color.channels, 4);
  for (int p = 0; p < 12; ++p) {
    EXPECT_EQ(color.pixels[p * 4 + 2], float(p + 2));
    EXPECT_EQ(color.pixels[p * 4 + 3], 1.0f);
  }
}

TEST(ReadFrame, NonFiniteValuesAreScrubbedAndCounted) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/c.exr", {"R", "G", "B", "A"}, [](int p, int c) {
    if (p == 0 && c == 0) return kNaN;
    if (p == 1 && c == 1) return kInf;
    if (p == 2 && c == 3) return -kInf;
    return 0.5f;
  });
  writeTestExr(folder + "/z.exr", {"Z"}, [](int p, int) {
    if (p == 0) return kNaN;
    if (p == 1) return -kInf;
    if (p == 2) return kInf;
    if (p == 3) return 1e9f;  // exactly at the threshold: no hit
    return 5e8f;
  });
  writeTestExr(folder + "/mv.exr", {"x", "y"}, [](int p, int c) {
    if (p == 0) return c == 0 ? kNaN : 1.0f;
    if (p == 1) return c == 0 ? 2.0f : kInf;
    return 3.0f;
  });
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  layout.depth = AovSource{folder + "/z.exr", {"Z"}};
  layout.motion = AovSource{folder + "/mv.exr", {"x", "y"}};
  layout.motionConvention.yUp = true;
  const FrameData data = readFrame(layout, 3);
  const Image color = data.color.toFloat();

  EXPECT_EQ(data.nonFiniteColorValues, 3);
  EXPECT_EQ(color.pixels[0], 0.0f);
  EXPECT_EQ(color.pixels[4 + 1], 0.0f);
  EXPECT_EQ(color.pixels[8 + 3], 0.0f);
  EXPECT_EQ(color.pixels[8 + 2], 0.5f);
  for (float value : color.pixels) EXPECT_TRUE(std::isfinite(value));

  EXPECT_EQ(data.depth.pixels[0], kInf);
  EXPECT_EQ(data.depth.pixels[1], kInf);
  EXPECT_EQ(data.depth.pixels[2], kInf);
  EXPECT_EQ(data.depth.pixels[3], kInf);
  EXPECT_EQ(data.depth.pixels[4], 5e8f);

  EXPECT_EQ(data.motion.pixels[0], 0.0f);
  EXPECT_EQ(data.motion.pixels[1], -1.0f);
  EXPECT_EQ(data.motion.pixels[2], 2.0f);
  EXPECT_EQ(data.motion.pixels[3], 0.0f);
  EXPECT_EQ(data.motion.pixels[4], 3.0f);
  EXPECT_EQ(data.motion.pixels[5], -3.0f);
  EXPECT_EQ(data.nonFiniteMotionValues, 2);  // counted for the report (issue 17)
  EXPECT_EQ(data.motionPath, folder + "/mv.exr");
}

// Issue 17: float colour a half output cannot hold is counted, so that the clamp is reported.
TEST(ReadFrame, FloatColorBeyondHalfRangeIsCounted) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/c.exr", {"R", "G", "B", "A"}, [](int p, int c) {
    if (p == 0 && c == 0) return 70000.0f;
    if (p == 3 && c == 2) return -1e30f;
    return p == 4 ? 65504.0f : 0.5f;  // the largest half itself is no clamp
  });
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  EXPECT_EQ(readFrame(layout, 1).colorValuesBeyondHalf, 2);
}

// Issue 17, item 9: a file without the alpha channel is opaque, as --help says; a missing B was
// reported as "lacks channels B, A".
TEST(ReadFrame, MissingAlphaReadsAsOpaqueAndOnlyRequiredChannelsAreListedMissing) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/rgb.exr", {"R", "G", "B"}, [](int p, int c) { return float(p + c); });
  writeTestExr(folder + "/rg.exr", {"R", "G"}, [](int p, int c) { return float(p + c); });
  AovLayout layout;
  layout.color = {folder + "/rgb.exr", {"R", "G", "B", "A"}};
  const Image color = readFrame(layout, 1).color.toFloat();
  for (int p = 0; p < 12; ++p) {
    EXPECT_EQ(color.pixels[p * 4 + 2], float(p + 2));
    EXPECT_EQ(color.pixels[p * 4 + 3], 1.0f);
  }
  layout.color.pattern = folder + "/rg.exr";
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "lacks channel B; channels available: R, G")) << error.what();
  EXPECT_EQ(error.context().channel, "B");
}

TEST(ReadFrame, NonFiniteMaskMarksScrubbedPixelsOnly) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/c.exr", {"R", "G", "B", "A"},
               [](int p, int c) { return p == 5 && c == 2 ? kNaN : 0.5f; });
  writeTestExr(folder + "/clean.exr", {"R", "G", "B", "A"}, [](int, int) { return 0.5f; });
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  const FrameData data = readFrame(layout, 1);
  ASSERT_EQ(data.nonFiniteMask.pixels.size(), 12u);
  for (int p = 0; p < 12; ++p) EXPECT_EQ(data.nonFiniteMask.pixels[p], p == 5 ? 1.0f : 0.0f);
  layout.color.pattern = folder + "/clean.exr";
  EXPECT_TRUE(readFrame(layout, 1).nonFiniteMask.empty());  // none made when nothing scrubbed
}

// Half colour is read as half, bit for bit, and scrubbed and completed in half.
TEST(ReadFrame, HalfColorStaysHalf) {
  const std::string folder = scratchFolder();
  const auto value = [](int p, int c) {
    if (p == 0 && c == 0) return kNaN;
    if (p == 1 && c == 2) return -kInf;
    return 0.1f * float(p) + 0.01f * float(c);  // not exact in half: rounded once, on write
  };
  OIIO::ImageSpec spec = makeSpec(4, 3, {"R", "G", "B"});
  spec.set_format(OIIO::TypeHalf);
  std::vector<float> pixels;
  for (int p = 0; p < 12; ++p) {
    for (int c = 0; c < 3; ++c) pixels.push_back(value(p, c));
  }
  writeImage(folder + "/c.exr", spec, pixels);
  // In file order (read straight into RGBA) and reversed (picked out of the read range).
  for (const bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "B, G, R" : "R, G, B");
    AovLayout layout;
    layout.color = {folder + "/c.exr", reversed ? Names{"B", "G", "R"} : Names{"R", "G", "B"}};
    const FrameData data = readFrame(layout, 1);
    ASSERT_EQ(data.color.type(), SampleType::Half);
    const HalfImage& color = *data.color.halves();
    ASSERT_EQ(color.channels, 4);
    EXPECT_EQ(data.nonFiniteColorValues, 2);
    for (int p = 0; p < 12; ++p) {
      SCOPED_TRACE("pixel " + std::to_string(p));
      for (int c = 0; c < 3; ++c) {
        const float stored = value(p, reversed ? 2 - c : c);
        const Imath::half expected =
            std::isfinite(stored) ? Imath::half(stored) : Imath::half(0.0f);
        EXPECT_EQ(color.at(p % 4, p / 4)[c].bits(), expected.bits());
      }
      EXPECT_EQ(color.at(p % 4, p / 4)[3].bits(), Imath::half(1.0f).bits());
    }
  }
}

TEST(ReadFrame, ColorWithAnyFloatChannelIsFloat) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec = makeSpec(4, 3, {"R", "G", "B", "A"});
  spec.channelformats = {OIIO::TypeHalf, OIIO::TypeHalf, OIIO::TypeHalf, OIIO::TypeFloat};
  writeImage(folder + "/c.exr", spec, std::vector<float>(4 * 3 * 4, 0.25f));
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  const FrameData data = readFrame(layout, 1);
  ASSERT_EQ(data.color.type(), SampleType::Float);
  for (float v : data.color.floats()->pixels) EXPECT_EQ(v, 0.25f);
  layout.color.channels = {"R", "G", "B"};  // the float alpha unasked: half
  EXPECT_EQ(readFrame(layout, 1).color.type(), SampleType::Half);
}

TEST(ReadFrame, KeepsTheColorHeader) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec = makeSpec(4, 3, {"R", "G", "B", "A"});
  spec.x = 3;
  spec.y = 5;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = 10;
  spec.full_height = 12;
  spec.attribute("taa:shot", "sq010_sh020");
  writeImage(folder + "/c.exr", spec, std::vector<float>(4 * 3 * 4, 0.5f));
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  const FrameData data = readFrame(layout, 1);
  EXPECT_EQ(data.colorSpec.x, 3);
  EXPECT_EQ(data.colorSpec.y, 5);
  EXPECT_EQ(data.colorSpec.full_width, 10);
  EXPECT_EQ(data.colorSpec.full_height, 12);
  EXPECT_EQ(data.colorSpec.get_string_attribute("taa:shot"), "sq010_sh020");
  EXPECT_EQ(data.color.width(), 4);
  EXPECT_EQ(data.color.height(), 3);
}

// Issue 25: a UINT channel asked for as colour came back divided by 2^32 - 1, silently.
TEST(ReadFrameErrors, AnIntegerColourOrDepthChannelIsRefusedNamingIt) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec = makeSpec(4, 3, {"R", "G", "B", "A", "id"});
  spec.channelformats = {OIIO::TypeHalf, OIIO::TypeHalf, OIIO::TypeHalf, OIIO::TypeHalf,
                         OIIO::TypeUInt};
  writeImage(folder + "/c.exr", spec, std::vector<float>(4 * 3 * 5, 7.0f));
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "id", "A"}};
  Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().channel, "id");
  EXPECT_TRUE(contains(error.what(), "the color channel id is uint, not half or float"))
      << error.what();
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  layout.depth = AovSource{folder + "/c.exr", {"id"}};
  error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "the depth channel id is uint")) << error.what();
  layout.depth.reset();
  layout.passthrough = {"id"};  // passed through: kept
  EXPECT_NO_THROW(readFrame(layout, 1));
}

TEST(ReadFrameErrors, MissingColorFrameNamesPathAndFrame) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 1);
  const Error error = errorOf([&] { readFrame(separateFilesLayout(folder), 12); });
  EXPECT_EQ(error.context().file, folder + "/beauty.0012.exr");
  EXPECT_EQ(error.context().frame, 12);
  EXPECT_TRUE(contains(error.what(), folder + "/beauty.0012.exr")) << error.what();
  EXPECT_TRUE(contains(error.what(), "frame 12")) << error.what();
}

TEST(ReadFrameErrors, MissingDepthFrameNamesItsPath) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 4);
  std::filesystem::remove(folder + "/depth.0004.exr");
  const Error error = errorOf([&] { readFrame(separateFilesLayout(folder), 4); });
  EXPECT_EQ(error.context().file, folder + "/depth.0004.exr");
  EXPECT_TRUE(contains(error.what(), "depth")) << error.what();
  EXPECT_TRUE(contains(error.what(), "frame 4")) << error.what();
}

TEST(ReadFrameErrors, MissingChannelListsMissingAndAvailableNames) {
  const std::string folder = scratchFolder();
  writeTestExr(folder + "/render.0001.exr", {"ViewLayer.Combined.R", "ViewLayer.Combined.G",
                                             "ViewLayer.Combined.B", "ViewLayer.Combined.A",
                                             "ViewLayer.Depth.Z"},
               [](int, int) { return 1.0f; });
  const Error error = errorOf([&] { readFrame(cyclesLayout(folder + "/render.####.exr"), 1); });
  const std::string message = error.what();
  EXPECT_TRUE(contains(message, "ViewLayer.Vector.X, ViewLayer.Vector.Y")) << message;
  EXPECT_TRUE(contains(message, "ViewLayer.Combined.R")) << message;
  EXPECT_TRUE(contains(message, "ViewLayer.Depth.Z")) << message;
  EXPECT_EQ(error.context().channel, "ViewLayer.Vector.X, ViewLayer.Vector.Y");
  EXPECT_EQ(error.context().file, folder + "/render.0001.exr");
  EXPECT_EQ(error.context().frame, 1);
}

TEST(ReadFrameErrors, DepthSizeDifferentFromColorStatesBothSizes) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 2, /*depthWidth=*/3);
  const Error error = errorOf([&] { readFrame(separateFilesLayout(folder), 2); });
  const std::string message = error.what();
  EXPECT_TRUE(contains(message, "3x3")) << message;
  EXPECT_TRUE(contains(message, "4x3")) << message;
  EXPECT_TRUE(contains(message, "depth")) << message;
  EXPECT_EQ(error.context().file, folder + "/depth.0002.exr");
  // Issue 17: the colour frame may be the wrong one; the message names it with its window.
  EXPECT_TRUE(contains(message, "4x3 at (0, 0) (" + folder + "/beauty.0002.exr)")) << message;
}

TEST(ReadFrameErrors, MotionSizeDifferentFromColorStatesBothSizes) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 2, 4, /*motionHeight=*/5);
  const Error error = errorOf([&] { readFrame(separateFilesLayout(folder), 2); });
  const std::string message = error.what();
  EXPECT_TRUE(contains(message, "4x5")) << message;
  EXPECT_TRUE(contains(message, "4x3")) << message;
  EXPECT_TRUE(contains(message, "motion")) << message;
  EXPECT_EQ(error.context().file, folder + "/mv.0002.exr");
  EXPECT_TRUE(contains(message, "(" + folder + "/beauty.0002.exr)")) << message;
}

TEST(ReadFrameErrors, MotionWindowOriginDifferentFromColorIsAnError) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 2);
  OIIO::ImageSpec shifted = makeSpec(4, 3, {"u", "v"});
  shifted.x = 1;
  writeImage(folder + "/mv.0002.exr", shifted, std::vector<float>(4 * 3 * 2, 0.0f));
  const Error error = errorOf([&] { readFrame(separateFilesLayout(folder), 2); });
  EXPECT_TRUE(contains(error.what(), "4x3 at (1, 0)")) << error.what();
  EXPECT_TRUE(contains(error.what(), "4x3 at (0, 0)")) << error.what();
}

// Issue 17: NaN camera matrices would reproject every pixel to NaN; the header is refused.
TEST(ReadFrameErrors, NonFiniteHeaderMatrixIsAnError) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec = makeSpec(4, 3, {"R", "G", "B", "A"});
  float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  spec.attribute("worldToCamera", OIIO::TypeMatrix44, identity);
  identity[5] = kNaN;
  spec.attribute("worldToNDC", OIIO::TypeMatrix44, identity);
  writeImage(folder + "/c.exr", spec, std::vector<float>(4 * 3 * 4, 0.5f));
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B", "A"}};
  const Error error = errorOf([&] { readFrame(layout, 9); });
  EXPECT_TRUE(contains(error.what(), "the color header's worldToNDC holds NaN or Inf"))
      << error.what();
  EXPECT_EQ(error.context().file, folder + "/c.exr");
  EXPECT_EQ(error.context().frame, 9);
}

// A data window no GPU texture holds is refused when read, naming the file, rather than by GL
// after everything was read and converted (or by the allocator, for a damaged header).
TEST(ReadFrameErrors, ADataWindowBeyondTheTextureLimitIsRefused) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/wide.exr";
  writeTestExr(path, {"R", "G", "B", "A"}, [](int, int) { return 0.5f; }, kMaxImageSide + 1, 2);
  AovLayout layout;
  layout.color = {path, {"R", "G", "B", "A"}};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, path);
  EXPECT_TRUE(contains(error.what(), "data window 16385x2 at (0, 0) is not 1 to 16384 pixels a "
                                     "side"))
      << error.what();
  writeTestExr(path, {"R", "G", "B", "A"}, [](int, int) { return 0.5f; }, kMaxImageSide, 2);
  EXPECT_EQ(readFrame(layout, 1).color.width(), kMaxImageSide);
}

// Widens the dataWindow attribute of the EXR at `path` by `extra` columns in place, as a damaged
// or hand-edited header does: the chunks stay as written, too short for the new window.
void widenDataWindow(const std::string& path, int extra) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string name("dataWindow\0box2i\0", 17);
  const std::size_t at = bytes.find(name);
  ASSERT_NE(at, std::string::npos);
  const std::size_t xMaxAt = at + name.size() + 4 + 8;  // after the size, xMin and yMin
  std::int32_t xMax = 0;
  std::memcpy(&xMax, bytes.data() + xMaxAt, 4);
  xMax += extra;
  file.seekp(std::streamoff(xMaxAt));
  file.write(reinterpret_cast<const char*>(&xMax), 4);
}

// Issue 25: OpenEXR's C++ reader fills the columns a header claims beyond the stored pixels
// with zeros, without an error; the reader refuses such a file, compressed or not, and reads
// the same file undamaged.
TEST(ReadFrameErrors, ADataWindowWiderThanThePixelDataIsRefused) {
  const std::string folder = scratchFolder();
  for (const char* compression : {"zip", "none"}) {
    SCOPED_TRACE(compression);
    const std::string path = folder + "/" + compression + ".exr";
    OIIO::ImageSpec spec = makeSpec(32, 20, {"R", "G", "B", "A"});
    spec.attribute("compression", compression);
    std::vector<float> pixels(32 * 20 * 4);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::sin(float(i));
    writeImage(path, spec, pixels);
    AovLayout layout;
    layout.color = {path, {"R", "G", "B", "A"}};
    EXPECT_EQ(readFrame(layout, 3).color.width(), 32);
    widenDataWindow(path, 32);
    const Error error = errorOf([&] { readFrame(layout, 3); });
    EXPECT_EQ(error.context().file, path);
    EXPECT_EQ(error.context().frame, 3);
    EXPECT_TRUE(contains(error.what(), "the color file's data window is wider than its pixel "
                                       "data"))
        << error.what();
    EXPECT_TRUE(contains(error.what(), "64x20")) << error.what();
  }
}

TEST(ReadFrameErrors, TextFileNamedExrIsRejected) {
  const std::string folder = scratchFolder();
  taa::test::writeTextFile(folder + "/c.exr", "this is not an image\n");
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B"}};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, folder + "/c.exr");
  EXPECT_TRUE(contains(error.what(), "OpenEXR")) << error.what();
}

TEST(ReadFrameErrors, TruncatedExrIsRejected) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/c.exr";
  // Big enough for many scanline blocks, noisy so that compression cannot shrink it away.
  writeTestExr(
      path, {"R", "G", "B", "A"}, [](int p, int c) { return std::sin(float(p * 7 + c * 13)); },
      64, 64);
  const auto size = std::filesystem::file_size(path);
  AovLayout layout;
  layout.color = {path, {"R", "G", "B", "A"}};
  // Cut in the pixel data (OIIO opens it, the read fails) and in the header (open fails).
  std::filesystem::resize_file(path, size / 2);
  Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, path);
  EXPECT_EQ(error.context().frame, 1);
  EXPECT_TRUE(contains(error.what(), "pixels")) << error.what();
  std::filesystem::resize_file(path, 20);
  error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, path);
}

TEST(ReadFrameErrors, PngAsColorIsRejected) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec(4, 3, 3, OIIO::TypeUInt8);
  writeImage(folder + "/c.png", spec, std::vector<float>(4 * 3 * 3, 0.5f));
  AovLayout layout;
  layout.color = {folder + "/c.png", {"R", "G", "B"}};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, folder + "/c.png");
  EXPECT_TRUE(contains(error.what(), "not an OpenEXR file")) << error.what();
  EXPECT_TRUE(contains(error.what(), "png")) << error.what();
}

TEST(ReadFrameErrors, PngNamedExrIsRejected) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec(4, 3, 3, OIIO::TypeUInt8);
  writeImage(folder + "/c.png", spec, std::vector<float>(4 * 3 * 3, 0.5f));
  std::filesystem::rename(folder + "/c.png", folder + "/c.exr");
  AovLayout layout;
  layout.color = {folder + "/c.exr", {"R", "G", "B"}};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_EQ(error.context().file, folder + "/c.exr");
}

TEST(ReadFrameErrors, WrongChannelCountIsAnError) {
  const std::string folder = scratchFolder();
  writeSeparateFiles(folder, 1);
  AovLayout layout = separateFilesLayout(folder);
  layout.motion->channels = {"u"};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "motion")) << error.what();
  layout = separateFilesLayout(folder);
  layout.color.channels = {"R", "G"};
  EXPECT_TRUE(contains(errorOf([&] { readFrame(layout, 1); }).what(), "color"));
}

}  // namespace
}  // namespace taa::io
