// What the writer keeps so the output can replace the input in a comp: channel names, the
// input's pixel type, pass-through channels with their own types.
#include <gtest/gtest.h>

#include <functional>

#include "io/exr_writer.h"
#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::makeSpec;
using taa::test::readImage;
using taa::test::scratchFolder;

using Names = std::vector<std::string>;

Image filled(int width, int height, int channels, float base) {
  Image image(width, height, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = base + 0.25f * float(i);
  return image;
}

OIIO::TypeDesc formatOf(const OIIO::ImageSpec& spec, const std::string& name) {
  for (int c = 0; c < spec.nchannels; ++c) {
    if (spec.channel_name(c) == name) return spec.channelformat(c);
  }
  return OIIO::TypeUnknown;
}

TEST(OutputFidelity, ChannelNamesAndTheInputsPixelType) {
  const std::string path = scratchFolder() + "/out.exr";
  OIIO::ImageSpec input = makeSpec(4, 3, {"ViewLayer.Combined.R", "ViewLayer.Combined.G",
                                          "ViewLayer.Combined.B", "ViewLayer.Combined.A"});
  input.set_format(OIIO::TypeHalf);
  WriteOptions options;  // pixel type: as input
  options.rgbaNames = {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
                       "ViewLayer.Combined.A"};
  writeExrAtomic(path, filled(4, 3, 4, 0.0f), input, options);
  OIIO::ImageSpec spec;
  readImage(path, spec);
  EXPECT_EQ(spec.channelnames, options.rgbaNames);
  EXPECT_EQ(spec.format, OIIO::TypeHalf);
  EXPECT_EQ(spec.alpha_channel, 3);

  input.set_format(OIIO::TypeFloat);
  writeExrAtomic(path, filled(4, 3, 4, 0.0f), input, options);
  readImage(path, spec);
  EXPECT_EQ(spec.format, OIIO::TypeFloat);

  options.pixelType = PixelType::Half;  // -d overrides
  writeExrAtomic(path, filled(4, 3, 4, 0.0f), input, options);
  readImage(path, spec);
  EXPECT_EQ(spec.format, OIIO::TypeHalf);
}

TEST(OutputFidelity, PassThroughChannelsKeepTheirValuesAndTypes) {
  const std::string path = scratchFolder() + "/out.exr";
  const OIIO::ImageSpec input = makeSpec(4, 3, {"R", "G", "B", "A"});
  ExtraChannels passthrough;
  passthrough.names = {"Normal.X", "depth.Z"};
  passthrough.image = filled(4, 3, 2, 100.0f);
  passthrough.formats = {OIIO::TypeHalf, OIIO::TypeFloat};
  ExtraChannels debug;
  debug.names = {"debug.a"};
  debug.image = filled(4, 3, 1, -5.0f);
  appendExtraChannels(passthrough, debug);
  ASSERT_EQ(passthrough.names, Names({"Normal.X", "depth.Z", "debug.a"}));
  writeExrAtomic(path, filled(4, 3, 4, 0.0f), input, WriteOptions{PixelType::Float}, passthrough);

  OIIO::ImageSpec spec;
  const std::vector<float> pixels = readImage(path, spec);
  EXPECT_EQ(formatOf(spec, "Normal.X"), OIIO::TypeHalf);
  EXPECT_EQ(formatOf(spec, "depth.Z"), OIIO::TypeFloat);
  EXPECT_EQ(formatOf(spec, "R"), OIIO::TypeFloat);
  // Values are exact (multiples of 1/4 fit in half): find them by name in the file's order.
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string name = spec.channel_name(c);
    for (std::size_t k = 0; k < passthrough.names.size(); ++k) {
      if (passthrough.names[k] != name) continue;
      for (int p = 0; p < 12; ++p) {
        EXPECT_EQ(pixels[std::size_t(p) * spec.nchannels + c], passthrough.image.pixels[p * 3 + k])
            << name << " pixel " << p;
      }
    }
  }
}

TEST(OutputFidelity, DuplicateOrMissingNamesAreErrors) {
  const std::string path = scratchFolder() + "/out.exr";
  ExtraChannels extra;
  extra.names = {"A"};
  extra.image = filled(4, 3, 1, 0.0f);
  try {
    writeExrAtomic(path, filled(4, 3, 4, 0.0f), {}, {}, extra);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("A is named twice"), std::string::npos) << e.what();
  }
  WriteOptions three;
  three.rgbaNames = {"R", "G", "B"};
  EXPECT_THROW(writeExrAtomic(path, filled(4, 3, 4, 0.0f), {}, three), Error);
}

TEST(OutputFidelity, ParsePixelTypeAcceptsInput) {
  EXPECT_EQ(parsePixelType("input"), PixelType::AsInput);
  EXPECT_EQ(WriteOptions().pixelType, PixelType::AsInput);
}

}  // namespace
}  // namespace taa::io
