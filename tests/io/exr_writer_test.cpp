#include "io/exr_writer.h"

#include <gtest/gtest.h>

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "io/stale_temp_files.h"
#include "io/temporary_file.h"
#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {
namespace fs = std::filesystem;

using taa::test::listFolder;
using taa::test::makeSpec;
using taa::test::readImage;
using taa::test::contains;
using taa::test::errorOf;
using taa::test::scratchFolder;

using Names = std::vector<std::string>;

// An image's samples as a plain vector, to compare with what readImage returns.
std::vector<float> plain(const taa::FrameVector<float>& samples) {
  return {samples.begin(), samples.end()};
}

// A Cycles-like header: data window 5x3 at (4, 5) inside a 16x12 display window at (1, 2),
// five channels, piz, render metadata.
OIIO::ImageSpec cyclesLikeTemplate() {
  OIIO::ImageSpec spec =
      makeSpec(5, 3, {"ViewLayer.Combined.A", "ViewLayer.Combined.B", "ViewLayer.Combined.G",
                      "ViewLayer.Combined.R", "ViewLayer.Depth.Z"});
  spec.x = 4;
  spec.y = 5;
  spec.full_x = 1;
  spec.full_y = 2;
  spec.full_width = 16;
  spec.full_height = 12;
  spec.attribute("compression", "piz");
  spec.attribute("BlenderMultiChannel", "Blender V2.55.1 and newer");
  spec.attribute("Camera", "CamShot");
  spec.attribute("cycles.ViewLayer.samples", 64);
  spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{24, 1}.data());
  const float worldToCamera[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 2, 3, 4, 1};
  spec.attribute("worldToCamera", OIIO::TypeMatrix44, worldToCamera);
  return spec;
}

// `value` rounded to the nearest half, through OIIO's own conversion.
float roundedToHalf(float value) {
  std::uint16_t half = 0;
  OIIO::convert_pixel_values(OIIO::TypeFloat, &value, OIIO::TypeHalf, &half);
  float back = 0.0f;
  OIIO::convert_pixel_values(OIIO::TypeHalf, &half, OIIO::TypeFloat, &back);
  return back;
}

Image makeRgba(int width, int height, const std::function<float(int, int)>& value) {
  Image image(width, height, 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = value(int(i / 4), int(i % 4));
  }
  return image;
}

void expectNoTemporaryFiles(const std::string& folder) {
  for (const std::string& name : listFolder(folder)) {
    EXPECT_FALSE(contains(name, "taa-tmp")) << "left behind: " << name;
  }
}

TEST(ParsePixelType, HalfAndFloat) {
  EXPECT_EQ(parsePixelType("half"), PixelType::Half);
  EXPECT_EQ(parsePixelType("float"), PixelType::Float);
  for (const std::string text : {"", "double", "uint8", "Half "}) {
    EXPECT_TRUE(contains(errorOf([&] { parsePixelType(text); }).what(), "\"" + text + "\""));
  }
}

TEST(ValidateCompression, AcceptsOpenExrCompressions) {
  for (const std::string name : {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a",
                                 "dwaa", "dwab", "zip:9", "zips:1", "dwaa:45", "dwab:200.5"}) {
    EXPECT_NO_THROW(validateCompression(name)) << name;
  }
}

TEST(ValidateCompression, RejectsUnknownNamesAndBadLevels) {
  for (const std::string name : {"", "lzw", "ZIP", "zip:", "zip:fast", "piz:3", "dwaa:-1",
                                 "jpeg", "zip 9"}) {
    const Error error = errorOf([&] { validateCompression(name); });
    EXPECT_TRUE(contains(error.what(), "\"" + name + "\"")) << error.what();
  }
}

// Issue 17, item 9: zip:0 and zip:99 passed the check (zlib has levels 1 to 9).
TEST(ValidateCompression, RejectsLevelsOutOfRange) {
  for (const std::string name : {"zip:0", "zip:99", "zips:10", "zip:1.5", "dwaa:0", "dwab:inf"}) {
    const Error error = errorOf([&] { validateCompression(name); });
    EXPECT_TRUE(contains(error.what(), "out of range in \"" + name + "\"")) << error.what();
  }
}

TEST(WriteExrAtomic, FloatRoundTripKeepsValuesWindowsAndMetadata) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/out.0001.exr";
  const Image rgba = makeRgba(5, 3, [](int p, int c) { return 0.123456789f * p - 3.3f * c; });
  writeExrAtomic(path, rgba, cyclesLikeTemplate(), {PixelType::Float, "zip"});

  OIIO::ImageSpec spec;
  const std::vector<float> pixels = readImage(path, spec);
  EXPECT_EQ(spec.channelnames, Names({"R", "G", "B", "A"}));
  EXPECT_EQ(spec.format, OIIO::TypeFloat);
  EXPECT_EQ(pixels, plain(rgba.pixels));  // float is exact
  // Data window and display window.
  EXPECT_EQ(spec.x, 4);
  EXPECT_EQ(spec.y, 5);
  EXPECT_EQ(spec.width, 5);
  EXPECT_EQ(spec.height, 3);
  EXPECT_EQ(spec.full_x, 1);
  EXPECT_EQ(spec.full_y, 2);
  EXPECT_EQ(spec.full_width, 16);
  EXPECT_EQ(spec.full_height, 12);
  // Metadata kept; the old layout's description dropped; compression from the options.
  EXPECT_EQ(spec.get_string_attribute("Camera"), "CamShot");
  EXPECT_EQ(spec.get_int_attribute("cycles.ViewLayer.samples"), 64);
  const OIIO::ParamValue* fps = spec.find_attribute("FramesPerSecond", OIIO::TypeRational);
  ASSERT_NE(fps, nullptr);
  EXPECT_EQ(static_cast<const int*>(fps->data())[0], 24);
  const OIIO::ParamValue* matrix = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
  ASSERT_NE(matrix, nullptr);
  EXPECT_EQ(static_cast<const float*>(matrix->data())[10], -1.0f);
  EXPECT_EQ(static_cast<const float*>(matrix->data())[13], 3.0f);
  EXPECT_EQ(spec.find_attribute("BlenderMultiChannel"), nullptr);
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
  expectNoTemporaryFiles(folder);
}

// Extra channels keep their own types (a render's passes: light half, data float) and their
// values, row by row across the bands the writer packs (256 rows), in a data window that does
// not start at the origin, whichever type the colour is.
TEST(WriteExrAtomic, ExtraChannelsKeepTheirTypesAndValuesAcrossBands) {
  const std::string folder = scratchFolder();
  constexpr int kWidth = 7, kHeight = 600;  // three bands, the last one partial
  OIIO::ImageSpec templateSpec = makeSpec(kWidth, kHeight, {"R", "G", "B", "A"});
  templateSpec.y = -20;
  templateSpec.full_height = kHeight + 40;
  const Image rgba =
      makeRgba(kWidth, kHeight, [](int p, int c) { return 0.01f * float(p) + float(c); });
  ExtraChannels extra;
  extra.names = {"DiffDir.R", "IndexOB.X", "Position.X"};  // in the order EXR sorts them
  extra.formats = {OIIO::TypeHalf, OIIO::TypeFloat, OIIO::TypeFloat};
  extra.image = Image(kWidth, kHeight, 3);
  for (std::size_t p = 0; p < std::size_t(kWidth) * kHeight; ++p) {
    extra.image.pixels[3 * p] = 0.5f + 0.001f * float(p);
    extra.image.pixels[3 * p + 1] = float(p % 5);
    extra.image.pixels[3 * p + 2] = 1234.5678f + float(p);  // beyond what half holds exactly
  }
  for (const PixelType colourType : {PixelType::Half, PixelType::Float}) {
    SCOPED_TRACE(colourType == PixelType::Half ? "half colour" : "float colour");
    const std::string path = folder + (colourType == PixelType::Half ? "/h.exr" : "/f.exr");
    writeExrAtomic(path, rgba, templateSpec, {colourType, "zip"}, extra);
    OIIO::ImageSpec spec;
    const std::vector<float> pixels = readImage(path, spec);
    ASSERT_EQ(spec.channelnames, Names({"R", "G", "B", "A", "DiffDir.R", "IndexOB.X",
                                        "Position.X"}));
    const OIIO::TypeDesc colour = colourType == PixelType::Half ? OIIO::TypeHalf : OIIO::TypeFloat;
    EXPECT_EQ(spec.channelformat(0), colour);
    EXPECT_EQ(spec.channelformat(4), OIIO::TypeHalf);
    EXPECT_EQ(spec.channelformat(5), OIIO::TypeFloat);
    EXPECT_EQ(spec.y, -20);
    for (std::size_t p = 0; p < std::size_t(kWidth) * kHeight; ++p) {
      for (std::size_t c = 0; c < 4; ++c) {
        const float wanted = rgba.pixels[4 * p + c];
        ASSERT_EQ(pixels[7 * p + c],
                  colourType == PixelType::Half ? roundedToHalf(wanted) : wanted)
            << "pixel " << p << " channel " << c;
      }
      ASSERT_EQ(pixels[7 * p + 4], roundedToHalf(extra.image.pixels[3 * p])) << "pixel " << p;
      ASSERT_EQ(pixels[7 * p + 5], extra.image.pixels[3 * p + 1]) << "pixel " << p;
      ASSERT_EQ(pixels[7 * p + 6], extra.image.pixels[3 * p + 2]) << "pixel " << p;
    }
  }
  expectNoTemporaryFiles(folder);
}

// Channels handed over packed in their types (ExtraChannels::packed, as a render's finished
// passes wait to be written) are written as given, across bands; joined with float channels
// (diagnostics beside them) they are unpacked first and come out the same; a packed block of
// the wrong size is refused.
TEST(WriteExrAtomic, PackedExtraChannelsAreWrittenAsGivenAndJoinAsFloat) {
  const std::string folder = scratchFolder();
  constexpr int kWidth = 5, kHeight = 300;  // ten bands of zip's 32 rows
  const OIIO::ImageSpec templateSpec = makeSpec(kWidth, kHeight, {"R", "G", "B", "A"});
  const Image rgba = makeRgba(kWidth, kHeight, [](int p, int c) { return 0.25f * float(p + c); });
  const std::size_t pixels = std::size_t(kWidth) * kHeight;
  ExtraChannels packed;
  packed.names = {"DiffDir.R", "Position.X"};
  packed.formats = {OIIO::TypeHalf, OIIO::TypeFloat};
  packed.packed.width = kWidth;
  packed.packed.height = kHeight;
  packed.packed.bytes.resize(pixels * 6);
  for (std::size_t p = 0; p < pixels; ++p) {
    const Imath::half h(0.5f + 0.001f * float(p));
    const float f = 1234.5678f + float(p);
    std::memcpy(&packed.packed.bytes[6 * p], &h, 2);
    std::memcpy(&packed.packed.bytes[6 * p + 2], &f, 4);
  }
  const auto check = [&](const std::string& path, std::size_t stride) {
    OIIO::ImageSpec spec;
    const std::vector<float> values = readImage(path, spec);
    ASSERT_EQ(spec.channelformat(4), OIIO::TypeHalf);
    ASSERT_EQ(spec.channelformat(5), OIIO::TypeFloat);
    for (std::size_t p = 0; p < pixels; ++p) {
      ASSERT_EQ(values[stride * p + 4], roundedToHalf(0.5f + 0.001f * float(p))) << p;
      ASSERT_EQ(values[stride * p + 5], 1234.5678f + float(p)) << p;
    }
  };
  writeExrAtomic(folder + "/packed.exr", rgba, templateSpec, {PixelType::Half, "zip"}, packed);
  check(folder + "/packed.exr", 6);

  ExtraChannels joined = packed;
  ExtraChannels debug;
  debug.names = {"debug.x"};
  debug.image = Image(kWidth, kHeight, 1);
  appendExtraChannels(joined, debug);
  EXPECT_FALSE(joined.isPacked());
  writeExrAtomic(folder + "/joined.exr", rgba, templateSpec, {PixelType::Half, "zip"}, joined);
  check(folder + "/joined.exr", 7);

  // Packed on demand, a band at a time: the writer asks for every pixel once, in order.
  ExtraChannels onDemand = packed;
  onDemand.packed.bytes.clear();
  std::vector<std::pair<std::size_t, std::size_t>> asked;
  onDemand.packed.rows = [&](std::size_t first, std::size_t count, unsigned char* to,
                              std::size_t stride) {
    asked.emplace_back(first, count);
    for (std::size_t n = 0; n < count; ++n) {
      std::memcpy(to + n * stride, &packed.packed.bytes[6 * (first + n)], 6);
    }
  };
  writeExrAtomic(folder + "/on-demand.exr", rgba, templateSpec, {PixelType::Half, "zip"},
                 onDemand);
  check(folder + "/on-demand.exr", 6);
  ASSERT_EQ(asked.size(), 10u);  // 300 rows of zip: nine bands of 32 rows and one of 12
  EXPECT_EQ(asked[0], std::make_pair(std::size_t(0), std::size_t(32) * kWidth));
  EXPECT_EQ(asked[9], std::make_pair(std::size_t(288) * kWidth, std::size_t(12) * kWidth));
  ExtraChannels onDemandJoined = onDemand;
  appendExtraChannels(onDemandJoined, debug);
  writeExrAtomic(folder + "/on-demand-joined.exr", rgba, templateSpec, {PixelType::Half, "zip"},
                 onDemandJoined);
  check(folder + "/on-demand-joined.exr", 7);

  ExtraChannels wrong = packed;
  wrong.packed.bytes.resize(pixels * 6 - 1);
  const std::string error =
      errorOf([&] { writeExrAtomic(folder + "/wrong.exr", rgba, templateSpec, {}, wrong); })
          .what();
  EXPECT_TRUE(contains(error, "packed extra channels must match")) << error;
  expectNoTemporaryFiles(folder);
}

TEST(WriteExrAtomic, HalfRoundTripWithinHalfPrecision) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/out.exr";
  // Multiples of 1/8 are exact in half; 0.1 is not.
  const Image exact = makeRgba(5, 3, [](int p, int c) { return 0.125f * p + c; });
  writeExrAtomic(path, exact, cyclesLikeTemplate(), {PixelType::Half, "piz"});
  OIIO::ImageSpec spec;
  EXPECT_EQ(readImage(path, spec), plain(exact.pixels));
  EXPECT_EQ(spec.format, OIIO::TypeHalf);

  const Image inexact =
      makeRgba(5, 3, [](int p, int c) { return 0.1f + 1.37f * p + 0.01f * c; });
  writeExrAtomic(path, inexact, cyclesLikeTemplate(), {PixelType::Half, "piz"});
  const std::vector<float> pixels = readImage(path, spec);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    // Exactly the nearest half: the file holds halves, converted once.
    EXPECT_EQ(pixels[i], roundedToHalf(inexact.pixels[i]));
    EXPECT_NEAR(pixels[i], inexact.pixels[i], std::abs(inexact.pixels[i]) * 1e-3f);
  }
  EXPECT_NE(pixels, plain(inexact.pixels));
}

TEST(WriteExrAtomic, CompressionComesFromTheOptions) {
  const std::string folder = scratchFolder();
  const Image rgba = makeRgba(5, 3, [](int p, int c) { return float(p + c); });
  for (const std::string compression : {"none", "rle", "piz", "pxr24", "b44a", "dwaa"}) {
    const std::string path = folder + "/" + compression + ".exr";
    writeExrAtomic(path, rgba, cyclesLikeTemplate(), {PixelType::Half, compression});
    OIIO::ImageSpec spec;
    readImage(path, spec);
    // OIIO may append a level ("dwaa:45"), so compare the name part.
    EXPECT_EQ(spec.get_string_attribute("compression").substr(0, compression.size()),
              compression);
  }
}

std::string fileBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// The file's bytes with the value of its capDate attribute (the time of writing, which OIIO
// stamps) blanked: two writes a second apart are otherwise different files.
std::string fileBytesButDate(const std::string& path) {
  std::string bytes = fileBytes(path);
  const std::string name("capDate\0string\0", 15);
  const auto at = bytes.find(name);
  if (at != std::string::npos && at + name.size() + 4 <= bytes.size()) {
    std::uint32_t size = 0;
    std::memcpy(&size, bytes.data() + at + name.size(), 4);
    const std::size_t value = at + name.size() + 4;
    if (value + size <= bytes.size()) std::fill_n(bytes.begin() + long(value), size, '0');
  }
  return bytes;
}

// Half samples into a half file go to the encoder untouched; with extra channels they are
// widened to float first, which is exact, so the file holds the same halves.
TEST(WriteExrAtomic, HalfImageIsWrittenBitForBit) {
  const std::string folder = scratchFolder();
  HalfImage rgba(5, 3, 4);
  for (std::size_t i = 0; i < rgba.pixels.size(); ++i) {
    rgba.pixels[i] = Imath::half(0.1f + 1.37f * float(i));
  }
  ExtraChannels extra;
  extra.names = {"debug.x"};
  extra.image = Image(5, 3, 1);
  for (const bool withExtra : {false, true}) {
    SCOPED_TRACE(withExtra ? "with an extra channel" : "RGBA only");
    const std::string path = folder + (withExtra ? "/extra.exr" : "/rgba.exr");
    writeExrAtomic(path, TypedImage(rgba), cyclesLikeTemplate(), {PixelType::Half, "zip"},
                   withExtra ? extra : ExtraChannels{});
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input);
    EXPECT_EQ(input->spec().channelformat(0), OIIO::TypeHalf);
    std::vector<Imath::half> read(rgba.pixels.size());
    ASSERT_TRUE(input->read_image(0, 0, 0, 4, OIIO::TypeHalf, read.data()));
    for (std::size_t i = 0; i < read.size(); ++i) {
      EXPECT_EQ(read[i].bits(), rgba.pixels[i].bits()) << i;
    }
  }
  // A float output of half samples widens them exactly.
  const std::string floatPath = folder + "/float.exr";
  writeExrAtomic(floatPath, TypedImage(rgba), cyclesLikeTemplate(), {PixelType::Float, "zip"});
  OIIO::ImageSpec spec;
  EXPECT_EQ(readImage(floatPath, spec), plain(TypedImage(rgba).toFloat().pixels));
  EXPECT_EQ(spec.format, OIIO::TypeFloat);
}

// A bare zip is zip at kDefaultZipLevel, a given level is honoured.
TEST(WriteExrAtomic, BareZipMeansTheDefaultLevel) {
  const std::string folder = scratchFolder();
  const Image rgba = makeRgba(64, 48, [](int p, int c) { return std::sin(0.37f * p + c); });
  const OIIO::ImageSpec none;
  for (const std::string compression : {"zip", "zip:1", "zip:9", "zips", "zips:1"}) {
    writeExrAtomic(folder + "/" + compression + ".exr", rgba, none, {PixelType::Half, compression});
  }
  ASSERT_EQ(kDefaultZipLevel, 1);
  EXPECT_EQ(fileBytesButDate(folder + "/zip.exr"), fileBytesButDate(folder + "/zip:1.exr"));
  EXPECT_EQ(fileBytesButDate(folder + "/zips.exr"), fileBytesButDate(folder + "/zips:1.exr"));
  EXPECT_NE(fileBytesButDate(folder + "/zip.exr"), fileBytesButDate(folder + "/zip:9.exr"));
}

TEST(WriteExrAtomic, WithoutTemplatePixelsTheWindowIsTheImage) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/plain.exr";
  const Image rgba = makeRgba(3, 2, [](int p, int c) { return float(p * 4 + c); });
  writeExrAtomic(path, rgba, OIIO::ImageSpec(), {PixelType::Float, "zip"});
  OIIO::ImageSpec spec;
  EXPECT_EQ(readImage(path, spec), plain(rgba.pixels));
  EXPECT_EQ(spec.x, 0);
  EXPECT_EQ(spec.full_width, 3);
  EXPECT_EQ(spec.full_height, 2);
}

TEST(WriteExrAtomic, ReplacesAnExistingFile) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/out.exr";
  const Image first = makeRgba(5, 3, [](int, int) { return 1.0f; });
  const Image second = makeRgba(5, 3, [](int, int) { return 2.0f; });
  writeExrAtomic(path, first, cyclesLikeTemplate(), {PixelType::Float, "zip"});
  writeExrAtomic(path, second, cyclesLikeTemplate(), {PixelType::Float, "zip"});
  OIIO::ImageSpec spec;
  EXPECT_EQ(readImage(path, spec), plain(second.pixels));
  EXPECT_EQ(listFolder(folder), Names({"out.exr"}));
}

TEST(WriteExrAtomic, CreatesAMissingParentFolder) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/new/deeper/out.exr";
  writeExrAtomic(path, makeRgba(5, 3, [](int, int) { return 0.5f; }), cyclesLikeTemplate(), {});
  EXPECT_TRUE(fs::is_regular_file(path));
  EXPECT_EQ(listFolder(folder + "/new/deeper"), Names({"out.exr"}));
}

TEST(WriteExrAtomic, UnknownCompressionWritesNothing) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/out.exr";
  const Error error = errorOf([&] {
    writeExrAtomic(path, makeRgba(5, 3, [](int, int) { return 0.5f; }), cyclesLikeTemplate(),
                   {PixelType::Half, "lzma"});
  });
  EXPECT_EQ(error.context().file, path);
  EXPECT_TRUE(contains(error.what(), "lzma")) << error.what();
  EXPECT_TRUE(listFolder(folder).empty());
}

TEST(WriteExrAtomic, ParentThatIsAFileFailsAndLeavesNothing) {
  const std::string folder = scratchFolder();
  taa::test::writeTextFile(folder + "/blocker", "a file, not a folder");
  const std::string path = folder + "/blocker/out.exr";
  const Error error = errorOf([&] {
    writeExrAtomic(path, makeRgba(5, 3, [](int, int) { return 0.5f; }), cyclesLikeTemplate(), {});
  });
  EXPECT_EQ(error.context().file, path);
  EXPECT_TRUE(contains(error.what(), path)) << error.what();
  EXPECT_EQ(listFolder(folder), Names({"blocker"}));
}

TEST(WriteExrAtomic, FailedRenameRemovesTheTemporaryFile) {
  const std::string folder = scratchFolder();
  // A non-empty folder sits at the final path: the EXR is written, the rename must fail.
  const std::string path = folder + "/out.exr";
  fs::create_directories(path + "/inside");
  const Error error = errorOf([&] {
    writeExrAtomic(path, makeRgba(5, 3, [](int, int) { return 0.5f; }), cyclesLikeTemplate(), {});
  });
  EXPECT_EQ(error.context().file, path);
  EXPECT_EQ(listFolder(folder), Names({"out.exr"}));
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
  expectNoTemporaryFiles(folder);
}

TEST(WriteExrAtomic, FailedWriteKeepsTheExistingFile) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/out.exr";
  const Image original = makeRgba(5, 3, [](int, int) { return 1.0f; });
  writeExrAtomic(path, original, cyclesLikeTemplate(), {PixelType::Float, "zip"});
  // An image that does not match the template's data window must not touch the file.
  errorOf([&] {
    writeExrAtomic(path, makeRgba(4, 3, [](int, int) { return 2.0f; }), cyclesLikeTemplate(),
                   {PixelType::Float, "zip"});
  });
  OIIO::ImageSpec spec;
  EXPECT_EQ(readImage(path, spec), plain(original.pixels));
  EXPECT_EQ(listFolder(folder), Names({"out.exr"}));
}

TEST(WriteExrAtomic, SizeMismatchStatesBothSizes) {
  const std::string folder = scratchFolder();
  const Error error = errorOf([&] {
    writeExrAtomic(folder + "/o.exr", makeRgba(4, 3, [](int, int) { return 0.0f; }),
                   cyclesLikeTemplate(), {});
  });
  EXPECT_TRUE(contains(error.what(), "4x3")) << error.what();
  EXPECT_TRUE(contains(error.what(), "5x3")) << error.what();
}

// Issue 25, defect 3: temporaries had predictable names (".NAME.taa-tmp-HOST-PID-N.exr") and
// were opened with O_TRUNC, so a link planted at one had its target overwritten. Links planted
// at every name the old scheme would give this process's first hundred writes must not be
// followed.
TEST(WriteExrAtomic, LinksPlantedAtTemporaryNamesAreNeverFollowed) {
  const std::string folder = scratchFolder();
  const std::string victim = folder + "/victim.txt";
  taa::test::writeTextFile(victim, "precious");
  for (int n = 0; n < 100; ++n) {
    fs::create_symlink(victim, folder + "/" + temporaryFileName("out.exr", std::to_string(n)));
  }
  writeExrAtomic(folder + "/out.exr", makeRgba(5, 3, [](int, int) { return 0.5f; }),
                 cyclesLikeTemplate(), {});
  std::ifstream in(victim);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "precious");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(folder + "/out.exr")));
}

TEST(TemporaryFile, NamesAreUnguessableAndCreatedExclusively) {
  const std::string folder = scratchFolder();
  const fs::path target = fs::path(folder) / "out.exr";
  const TemporaryFile first(target), second(target);
  EXPECT_NE(first.path(), second.path());
  for (const TemporaryFile* file : {&first, &second}) {
    const std::string name = file->path().filename().string();
    const std::string prefix = temporaryFileName("out.exr", "");
    ASSERT_EQ(name.compare(0, prefix.size() - 4, prefix, 0, prefix.size() - 4), 0) << name;
    const std::string unique = name.substr(prefix.size() - 4, name.size() - prefix.size());
    EXPECT_EQ(unique.size(), 16u) << name;
    EXPECT_EQ(unique.find_first_not_of("0123456789abcdef"), std::string::npos) << name;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(file->path())));
  }
  const fs::path kept = first.path();
  { const TemporaryFile dropped(target); }  // not committed: removed
  EXPECT_EQ(listFolder(folder).size(), 2u);
  EXPECT_TRUE(fs::exists(kept));
}

TEST(TemporaryFile, AFolderThatCannotBeWrittenIsAnErrorNamingIt) {
  const std::string folder = scratchFolder() + "/missing";
  const Error error = errorOf([&] { TemporaryFile file(fs::path(folder) / "out.exr"); });
  EXPECT_TRUE(contains(error.what(), "cannot create a temporary file in " + folder))
      << error.what();
}

}  // namespace
}  // namespace taa::io
