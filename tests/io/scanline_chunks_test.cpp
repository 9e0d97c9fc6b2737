// ScanlineChunkReader: a scanline part's ZIP, ZIPS and uncompressed chunks decoded without
// OpenEXR's per-value path give exactly the bytes OIIO's reader gives; what it does not decode
// it declines; a damaged chunk is a failure, never pixels.
#include "io/scanline_chunks.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::scratchFolder;

// The plain definition: each byte the one before plus its stored value less 128.
std::vector<std::uint8_t> undoZipDeltasPlainly(std::vector<std::uint8_t> bytes) {
  for (std::size_t j = 1; j < bytes.size(); ++j) {
    bytes[j] = std::uint8_t(bytes[j - 1] + bytes[j] - 128);
  }
  return bytes;
}

TEST(ScanlineChunks, UndoingThePredictorMatchesItsDefinitionAtEveryLength) {
  std::mt19937 random(7);
  for (std::size_t n : {0u, 1u, 2u, 3u, 15u, 16u, 17u, 31u, 32u, 33u, 34u, 63u, 64u, 65u, 1001u,
                        4096u, 61440u}) {
    std::vector<std::uint8_t> bytes(n);
    for (auto& b : bytes) b = std::uint8_t(random());
    const std::vector<std::uint8_t> expected = undoZipDeltasPlainly(bytes);
    undoZipDeltas(bytes.data(), n);
    EXPECT_EQ(bytes, expected) << n << " bytes";
  }
}

// Channels of three types, written in an order the file does not keep (it sorts them).
const std::vector<std::string> kNames = {"Z", "R", "G", "B", "A", "id", "layer.N.x"};
const std::vector<OIIO::TypeDesc> kTypes = {OIIO::TypeFloat, OIIO::TypeHalf, OIIO::TypeHalf,
                                            OIIO::TypeHalf,  OIIO::TypeHalf, OIIO::TypeUInt,
                                            OIIO::TypeFloat};

OIIO::ImageSpec specOf(int width, int height, const std::string& compression) {
  OIIO::ImageSpec spec(width, height, int(kNames.size()), OIIO::TypeFloat);
  spec.channelnames = kNames;
  spec.channelformats = kTypes;
  spec.x = -5;
  spec.y = 11;  // the chunks start at the window's top, not at a multiple of 16
  spec.full_width = width + 20;
  spec.full_height = height + 30;
  spec.attribute("compression", compression);
  return spec;
}

// Pixels in the spec's types: smooth where `noise` is false (ZIP shrinks every chunk), random
// bits where it is true (ZIP cannot, and the chunks are stored as they are).
std::vector<unsigned char> pixelsFor(const OIIO::ImageSpec& spec, bool noise) {
  std::mt19937 random(11);
  std::vector<unsigned char> pixels;
  for (int p = 0; p < spec.width * spec.height; ++p) {
    for (int c = 0; c < spec.nchannels; ++c) {
      unsigned char bytes[4];
      const float v = float(p % 97) * 0.25f + float(c);
      const std::uint32_t bits = std::uint32_t(random());
      std::size_t size = 4;
      if (spec.channelformat(c) == OIIO::TypeHalf) {
        const Imath::half h(v);
        std::memcpy(bytes, noise ? static_cast<const void*>(&bits) : &h, 2);
        size = 2;
      } else if (spec.channelformat(c) == OIIO::TypeUInt) {
        const std::uint32_t u = noise ? bits : std::uint32_t(p % 5);
        std::memcpy(bytes, &u, 4);
      } else {
        std::memcpy(bytes, noise ? static_cast<const void*>(&bits) : &v, 4);
      }
      pixels.insert(pixels.end(), bytes, bytes + size);
    }
  }
  return pixels;
}

// One file of `parts` parts, each the same layout.
void writeParts(const std::string& path, const std::vector<OIIO::ImageSpec>& specs, bool noise) {
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path, int(specs.size()), specs.data())) << out->geterror();
  for (std::size_t part = 0; part < specs.size(); ++part) {
    if (part > 0) {
      ASSERT_TRUE(out->open(path, specs[part], OIIO::ImageOutput::AppendSubimage))
          << out->geterror();
    }
    ASSERT_TRUE(out->write_image(OIIO::TypeUnknown, pixelsFor(specs[part], noise).data()))
        << out->geterror();
  }
  ASSERT_TRUE(out->close());
}

std::size_t bytesOf(const OIIO::ImageSpec& spec, int begin, int end) {
  std::size_t bytes = 0;
  for (int c = begin; c < end; ++c) bytes += spec.channelformat(c).size();
  return bytes;
}

TEST(ScanlineChunks, RowsAreTheBytesOiioReadsForEveryCodecItDecodes) {
  const std::string folder = scratchFolder();
  const struct {
    const char* compression;
    bool noise;
    int parts;
  } kFiles[] = {{"zip", false, 1}, {"zips", false, 1}, {"none", false, 1},
                {"zip", true, 1},  {"zip", false, 2},  {"zips", true, 2}};
  constexpr int kWidth = 53, kHeight = 70;  // odd sizes: the last chunk is short
  for (const auto& file : kFiles) {
    const std::string where = std::string(file.compression) + (file.noise ? " noise" : "") +
                              " parts " + std::to_string(file.parts);
    const std::string path = folder + "/" + file.compression + (file.noise ? "-noise" : "") +
                             "-" + std::to_string(file.parts) + ".exr";
    std::vector<OIIO::ImageSpec> specs(std::size_t(file.parts), specOf(kWidth, kHeight, file.compression));
    for (int part = 0; part < file.parts; ++part) {
      specs[std::size_t(part)].attribute("name", "part" + std::to_string(part));
    }
    writeParts(path, specs, file.noise);
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << OIIO::geterror();
    const int part = file.parts - 1;  // the last part: its chunks do not start the file
    const OIIO::ImageSpec spec = input->spec(part, 0);
    auto reader = ScanlineChunkReader::open(path, part, spec);
    ASSERT_TRUE(reader) << where;
    // Bands on and off the chunks' rows, all channels or a middle range of them.
    const struct {
      int y, rows, begin, end;
    } kBands[] = {{spec.y, kHeight, 0, spec.nchannels},
                  {spec.y + 5, 20, 0, spec.nchannels},
                  {spec.y + 32, 38, 2, 6},
                  {spec.y + kHeight - 1, 1, 1, 2}};
    for (const auto& band : kBands) {
      const std::size_t size =
          std::size_t(band.rows) * std::size_t(kWidth) * bytesOf(spec, band.begin, band.end);
      std::vector<unsigned char> expected(size, 0x5A), got(size, 0xA5);
      ASSERT_TRUE(input->read_scanlines(part, 0, band.y, band.y + band.rows, 0, band.begin,
                                        band.end, OIIO::TypeUnknown, expected.data()))
          << input->geterror();
      std::string error;
      ASSERT_TRUE(reader->readRows(band.y, band.rows, band.begin, band.end, got.data(), error))
          << where << ": " << error;
      EXPECT_TRUE(got == expected) << where << ", rows from " << band.y << ", channels "
                                   << band.begin << "-" << band.end;
    }
  }
}

TEST(ScanlineChunks, PartsItDoesNotDecodeAreLeftToOiio) {
  const std::string folder = scratchFolder();
  OIIO::ImageSpec piz = specOf(40, 40, "piz");
  OIIO::ImageSpec tiled = specOf(40, 40, "zip");
  tiled.tile_width = tiled.tile_height = 16;
  for (const auto& [name, spec] : {std::pair{"piz", piz}, std::pair{"tiled", tiled}}) {
    const std::string path = folder + "/" + name + ".exr";
    writeParts(path, {spec}, false);
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << OIIO::geterror();
    EXPECT_FALSE(ScanlineChunkReader::open(path, 0, input->spec())) << name;
  }
  // A header that does not describe the file (another file's, another part) is declined too.
  const std::string zip = folder + "/zip.exr";
  writeParts(zip, {specOf(40, 40, "zip")}, false);
  EXPECT_FALSE(ScanlineChunkReader::open(zip, 0, specOf(41, 40, "zip")));
  EXPECT_FALSE(ScanlineChunkReader::open(zip, 1, specOf(40, 40, "zip")));
  EXPECT_FALSE(ScanlineChunkReader::open(folder + "/missing.exr", 0, specOf(40, 40, "zip")));
}

TEST(ScanlineChunks, ADamagedOrMissingChunkIsAFailureNotPixels) {
  const std::string folder = scratchFolder();
  constexpr int kWidth = 64, kHeight = 64;
  const OIIO::ImageSpec written = specOf(kWidth, kHeight, "zip");
  const std::size_t bandBytes = std::size_t(kWidth) * kHeight * bytesOf(written, 0, written.nchannels);

  // Bytes overwritten in the middle of the pixels: the chunk's checksum no longer holds.
  const std::string corrupt = folder + "/corrupt.exr";
  writeParts(corrupt, {written}, false);
  const auto size = std::filesystem::file_size(corrupt);
  {
    std::fstream file(corrupt, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(std::streamoff(size / 2));
    const std::vector<char> junk(64, char(0xFF));
    file.write(junk.data(), std::streamsize(junk.size()));
  }
  // The file cut short: its last chunks are not there.
  const std::string cut = folder + "/cut.exr";
  writeParts(cut, {written}, false);
  std::filesystem::resize_file(cut, std::filesystem::file_size(cut) * 2 / 3);

  for (const std::string& path : {corrupt, cut}) {
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << OIIO::geterror();
    auto reader = ScanlineChunkReader::open(path, 0, input->spec());
    ASSERT_TRUE(reader) << path;  // the header and the chunk table are intact
    std::vector<unsigned char> band(bandBytes);
    std::string error;
    EXPECT_FALSE(reader->readRows(written.y, kHeight, 0, written.nchannels, band.data(), error))
        << path;
    EXPECT_FALSE(error.empty()) << path;
  }
}

}  // namespace
}  // namespace taa::io
