// File layouts readFrame must take as they come: multi-part EXR (parts by name or found by
// channel), tiled files, data windows unlike the display window (overscan, crop), pass-through
// channels.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <functional>

#include "io/frame_reader.h"
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

std::vector<float> pixelsOf(const OIIO::ImageSpec& spec, float base) {
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = base + float(i);
  return pixels;
}

OIIO::ImageSpec namedPart(const std::string& name, int width, int height, const Names& channels) {
  OIIO::ImageSpec spec = makeSpec(width, height, channels);
  spec.attribute("oiio:subimagename", name);
  return spec;
}

// Writes each spec as one part of a multi-part EXR, pixels base 0, 1000, 2000...
void writeMultiPart(const std::string& path, std::vector<OIIO::ImageSpec> parts) {
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out && out->supports("multiimage"));
  ASSERT_TRUE(out->open(path, int(parts.size()), parts.data())) << out->geterror();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) {
      ASSERT_TRUE(out->open(path, parts[i], OIIO::ImageOutput::AppendSubimage));
    }
    const std::vector<float> pixels = pixelsOf(parts[i], 1000.0f * float(i));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data())) << out->geterror();
  }
  ASSERT_TRUE(out->close());
}

TEST(MultiPart, PartsChosenByNameOrFoundByChannel) {
  const std::string folder = scratchFolder();
  // Two parts with the same channel names (R, G, B, A and R, G), as renderers writing one part
  // per pass do, plus a part holding depth.
  writeMultiPart(folder + "/render.0001.exr",
                 {namedPart("rgba", 4, 3, {"R", "G", "B", "A"}),
                  namedPart("motion", 4, 3, {"R", "G"}), namedPart("depth", 4, 3, {"Z"})});
  AovLayout layout;
  layout.color = {folder + "/render.####.exr", {"R", "G", "B", "A"}, "rgba"};
  layout.motion = AovSource{"", {"R", "G"}, "motion"};
  layout.depth = AovSource{"", {"Z"}, ""};  // found: the only part with Z
  const FrameData data = readFrame(layout, 1);
  EXPECT_EQ(data.color.toFloat().pixels[0], 0.0f);        // part 0, first value
  EXPECT_EQ(data.motion.pixels[0], 1000.0f);    // part 1
  EXPECT_EQ(data.motion.pixels[3], 1003.0f);
  EXPECT_EQ(data.depth.pixels[5], 2005.0f);     // part 2
  EXPECT_EQ(data.colorSpec.channelnames, Names({"R", "G", "B", "A"}));

  layout.motion->part = "vectors";
  const Error missing = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(missing.what(), "no part named vectors")) << missing.what();
  EXPECT_TRUE(contains(missing.what(), "rgba, motion, depth")) << missing.what();
  EXPECT_TRUE(contains(missing.what(), "frame 1")) << missing.what();
}

TEST(MultiPart, MissingChannelListsEveryPartsChannels) {
  const std::string folder = scratchFolder();
  writeMultiPart(folder + "/render.0001.exr",
                 {namedPart("rgba", 4, 3, {"R", "G", "B", "A"}), namedPart("depth", 4, 3, {"Z"})});
  AovLayout layout;
  layout.color = {folder + "/render.####.exr", {"R", "G", "B", "A"}, ""};
  layout.motion = AovSource{"", {"forward.u", "forward.v"}, ""};
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "forward.u, forward.v")) << error.what();
  EXPECT_TRUE(contains(error.what(), "part depth: Z")) << error.what();
}

TEST(Tiled, TiledAndScanlineFilesReadTheSame) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec = makeSpec(37, 21, {"R", "G", "B", "A", "Z"});
  const std::vector<float> pixels = pixelsOf(spec, 0.5f);
  writeImage(folder + "/scan.0001.exr", spec, pixels);
  spec.tile_width = 16;
  spec.tile_height = 8;
  writeImage(folder + "/tile.0001.exr", spec, pixels);
  AovLayout layout;
  layout.color = {folder + "/scan.####.exr", {"R", "G", "B", "A"}, ""};
  layout.depth = AovSource{"", {"Z"}, ""};
  const FrameData scan = readFrame(layout, 1);
  layout.color.pattern = folder + "/tile.####.exr";
  const FrameData tile = readFrame(layout, 1);
  EXPECT_EQ(tile.colorSpec.tile_width, 16);  // it really is tiled
  EXPECT_EQ(scan.colorSpec.tile_width, 0);
  EXPECT_EQ(tile.color.toFloat().pixels, scan.color.toFloat().pixels);
  EXPECT_EQ(tile.depth.pixels, scan.depth.pixels);
}

TEST(Windows, OverscanAndCropWindowsAreReportedRelativeToTheDisplay) {
  const std::string folder = scratchFolder();
  // Overscan: 12x8 data window at (-2, -2) around an 8x4 display window at (0, 0).
  OIIO::ImageSpec overscan = makeSpec(12, 8, {"R", "G", "B", "A"});
  overscan.x = -2;
  overscan.y = -2;
  overscan.full_width = 8;
  overscan.full_height = 4;
  writeImage(folder + "/over.0001.exr", overscan, pixelsOf(overscan, 0.0f));
  // Crop: 3x2 data window at (5, 7) inside a 16x12 display at (1, 2).
  OIIO::ImageSpec crop = makeSpec(3, 2, {"R", "G", "B", "A"});
  crop.x = 5;
  crop.y = 7;
  crop.full_x = 1;
  crop.full_y = 2;
  crop.full_width = 16;
  crop.full_height = 12;
  writeImage(folder + "/crop.0001.exr", crop, pixelsOf(crop, 0.0f));

  AovLayout layout;
  layout.color = {folder + "/over.####.exr", {"R", "G", "B", "A"}, ""};
  const FrameData o = readFrame(layout, 1);
  EXPECT_EQ(o.color.width(), 12);
  EXPECT_EQ(o.window.dataX, -2);
  EXPECT_EQ(o.window.dataY, -2);
  EXPECT_EQ(o.window.displayWidth, 8);
  EXPECT_EQ(o.window.displayHeight, 4);
  layout.color.pattern = folder + "/crop.####.exr";
  const FrameData c = readFrame(layout, 1);
  EXPECT_EQ(c.window.dataX, 4);
  EXPECT_EQ(c.window.dataY, 5);
  EXPECT_EQ(c.window.displayWidth, 16);
  EXPECT_EQ(c.colorSpec.full_x, 1);
}

TEST(Passthrough, MatchingChannelsAreReadWithTheirTypes) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec spec =
      makeSpec(4, 3, {"R", "G", "B", "A", "ViewLayer.Normal.X", "ViewLayer.Depth.Z", "crypto.R"});
  spec.channelformats = {OIIO::TypeFloat, OIIO::TypeFloat, OIIO::TypeFloat, OIIO::TypeFloat,
                         OIIO::TypeHalf,  OIIO::TypeFloat, OIIO::TypeFloat};
  writeImage(folder + "/b.0001.exr", spec, pixelsOf(spec, 0.0f));
  AovLayout layout;
  layout.color = {folder + "/b.####.exr", {"R", "G", "B", "A"}, ""};
  layout.passthrough = {"ViewLayer.*", "*.nothing"};
  const FrameData data = readFrame(layout, 1);
  // EXR stores channels sorted by name; pass-through keeps the file's order.
  ASSERT_EQ(data.passthrough.names, Names({"ViewLayer.Depth.Z", "ViewLayer.Normal.X"}));
  EXPECT_EQ(data.passthrough.formats,
            (std::vector<OIIO::TypeDesc>{OIIO::TypeFloat, OIIO::TypeHalf}));
  EXPECT_EQ(data.passthrough.image.channels, 2);
  EXPECT_EQ(data.passthrough.image.width, 4);
  layout.passthrough.clear();
  EXPECT_TRUE(readFrame(layout, 1).passthrough.names.empty());
}

TEST(RadialDepth, NeedsACameraOrAFieldOfView) {
  const std::string folder = scratchFolder();
  const OIIO::ImageSpec spec = makeSpec(8, 4, {"R", "G", "B", "A", "Z"});
  std::vector<float> pixels(8 * 4 * 5, 2.0f);
  writeImage(folder + "/r.0001.exr", spec, pixels);
  AovLayout layout;
  layout.color = {folder + "/r.####.exr", {"R", "G", "B", "A"}, ""};
  layout.depth = AovSource{"", {"Z"}, ""};
  layout.depthConvention.kind = DepthKind::Radial;
  const Error error = errorOf([&] { readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "radial depth needs the camera")) << error.what();
  EXPECT_TRUE(contains(error.what(), "--depth-fov")) << error.what();
  layout.depthConvention.horizontalFovDegrees = 90.0;
  const FrameData data = readFrame(layout, 1);
  // Pixel (0, 0): ray (-3.5/4, -1.5/4, 1) for a 90 degree, 8 pixel wide pinhole.
  EXPECT_NEAR(data.depth.pixels[0], 2.0 / std::sqrt(1.0 + 0.765625 + 0.140625), 1e-6);
}

}  // namespace
}  // namespace taa::io
