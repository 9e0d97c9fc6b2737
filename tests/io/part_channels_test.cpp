// readPartChannels: several AOVs' channels of one part decoded in one pass, in row bands, with
// every codec's chunk height, tiles, a data window off the origin and channel types mixed; on
// one thread and on several.
#include "io/part_channels.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::contains;
using taa::test::errorOf;
using taa::test::scratchFolder;

constexpr int kWidth = 37, kHeight = 150;  // 150 rows: bands of 64 and 256 end part-way

// A value no two (pixel, channel) pairs share, exact in half: what channel c holds at pixel p.
float valueAt(int p, int c) { return float((p * 5 + c * 3) % 1024) / 8.0f - 40.0f; }

// Channels: A half, B float, C uint, D half, E float, in the order written; the file may keep
// another (OIIO puts A, taken for alpha, after B), so readers look channels up by name.
const std::vector<std::string> kNames = {"A", "B", "C", "D", "E"};
const std::vector<OIIO::TypeDesc> kTypes = {OIIO::TypeHalf, OIIO::TypeFloat, OIIO::TypeUInt,
                                            OIIO::TypeHalf, OIIO::TypeFloat};

// Writes the file with `compression`, tiled when tileSize > 0, its data window at (3, -7).
void writeMixed(const std::string& path, const std::string& compression, int tileSize) {
  OIIO::ImageSpec spec(kWidth, kHeight, int(kNames.size()), OIIO::TypeFloat);
  spec.channelnames = kNames;
  spec.channelformats = kTypes;
  spec.x = 3;
  spec.y = -7;
  spec.full_width = kWidth + 10;
  spec.full_height = kHeight + 10;
  spec.attribute("compression", compression);
  if (tileSize > 0) {
    spec.tile_width = spec.tile_height = tileSize;
  }
  // Native layout: each channel in its own type, packed.
  std::vector<unsigned char> pixels;
  for (int p = 0; p < kWidth * kHeight; ++p) {
    for (int c = 0; c < int(kNames.size()); ++c) {
      const float v = valueAt(p, c);
      unsigned char bytes[4];
      std::size_t size = 4;
      if (kTypes[std::size_t(c)] == OIIO::TypeHalf) {
        const Imath::half h(v);
        std::memcpy(bytes, &h, 2);
        size = 2;
      } else if (kTypes[std::size_t(c)] == OIIO::TypeUInt) {
        const std::uint32_t u = std::uint32_t(p % 7);
        std::memcpy(bytes, &u, 4);
      } else {
        std::memcpy(bytes, &v, 4);
      }
      pixels.insert(pixels.end(), bytes, bytes + size);
    }
  }
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeUnknown, pixels.data())) << out->geterror();
  out->close();
}

std::unique_ptr<OIIO::ImageInput> openInput(const std::string& path, OIIO::ImageSpec& spec) {
  auto input = OIIO::ImageInput::open(path);
  if (input) spec = input->spec();
  return input;
}

int indexOf(const OIIO::ImageSpec& spec, const std::string& name) {
  return spec.channelindex(name);
}

TEST(PartChannels, EveryRequestGetsItsChannelsWhateverTheCodecOrTiling) {
  const std::string folder = scratchFolder();
  const struct {
    const char* compression;
    int tile;
    int threads;  // decodeThreads: 3 over the five bands of 32 rows (or more) left unevenly
  } kFiles[] = {{"none", 0, 1}, {"zip", 0, 1}, {"zips", 0, 1}, {"piz", 0, 1}, {"dwab", 0, 1},
                {"pxr24", 0, 1}, {"zip", 32, 1}, {"piz", 48, 1}, {"none", 0, 3}, {"zip", 0, 3},
                {"zips", 0, 3}, {"piz", 0, 3}, {"zip", 32, 3}};
  for (const auto& file : kFiles) {
    const std::string path =
        folder + "/" + file.compression + "-" + std::to_string(file.tile) + ".exr";
    writeMixed(path, file.compression, file.tile);
    OIIO::ImageSpec spec;
    auto input = openInput(path, spec);
    ASSERT_TRUE(input) << OIIO::geterror();

    const std::size_t count = std::size_t(kWidth) * kHeight;
    // Half out of half channels, asked out of file order into a wider pixel (colour's way).
    std::vector<Imath::half> dAndA(count * 4, Imath::half(99.0f));
    // Float out of a float channel and a half one (depth's and motion's way).
    std::vector<float> eAndD(count * 2);
    // A uint channel, converted by OIIO on its own pass (normalised, as OIIO reads uint).
    std::vector<float> c(count);
    const std::vector<ChannelRequest> requests = {
        {"color", {indexOf(spec, "D"), indexOf(spec, "A")}, {"D", "A"}, OIIO::TypeHalf,
         dAndA.data(), 4},
        {"motion", {indexOf(spec, "E"), indexOf(spec, "D")}, {"E", "D"}, OIIO::TypeFloat,
         eAndD.data(), 2},
        {"ids", {indexOf(spec, "C")}, {"C"}, OIIO::TypeFloat, c.data(), 1}};
    readPartChannels(*input, path, 5, 0, spec, requests, file.threads);

    const std::string where = std::string(file.compression) + " tile " +
                              std::to_string(file.tile) + " threads " +
                              std::to_string(file.threads);
    // Every codec here is lossless on these values but DWAB, which is lossy on half and float
    // colour-like channels: compare it loosely.
    const bool lossy = std::string(file.compression) == "dwab";
    int wrong = 0;
    for (std::size_t p = 0; p < count; ++p) {
      const auto near = [&](float got, float want) {
        return lossy ? std::abs(got - want) <= 0.05f * std::abs(want) + 0.05f : got == want;
      };
      wrong += !near(float(dAndA[p * 4 + 0]), valueAt(int(p), 3));
      wrong += !near(float(dAndA[p * 4 + 1]), valueAt(int(p), 0));
      wrong += float(dAndA[p * 4 + 2]) != 99.0f;  // beyond the request: untouched
      wrong += !near(eAndD[p * 2 + 0], valueAt(int(p), 4));
      wrong += !near(eAndD[p * 2 + 1], valueAt(int(p), 3));
      wrong += c[p] != float(p % 7) / 4294967295.0f;
    }
    EXPECT_EQ(wrong, 0) << where;
  }
}

TEST(PartChannels, ADamagedFileNamesEveryAovOfThePassAndItsChannels) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/cut.exr";
  writeMixed(path, "zip", 0);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) * 2 / 3);
  for (int threads : {1, 3}) {
    OIIO::ImageSpec spec;
    auto input = openInput(path, spec);
    ASSERT_TRUE(input) << OIIO::geterror();
    std::vector<float> a(std::size_t(kWidth) * kHeight), b(a.size());
    const Error error = errorOf([&] {
      readPartChannels(*input, path, 12, 0, spec,
                       {{"color", {indexOf(spec, "A")}, {"A"}, OIIO::TypeFloat, a.data(), 1},
                        {"depth", {indexOf(spec, "B")}, {"B"}, OIIO::TypeFloat, b.data(), 1}},
                       threads);
    });
    EXPECT_TRUE(contains(error.what(),
                         "cannot read the color and depth pixels (truncated or corrupt"))
        << error.what() << " (threads " << threads << ")";
    EXPECT_EQ(error.context().file, path);
    EXPECT_EQ(error.context().frame, 12);
    EXPECT_EQ(error.context().channel, "A, B");
  }
}

// A band request (the passes' way) on several threads: every pixel handed over once, with its
// values, whichever thread decoded its band.
TEST(PartChannels, BandsDecodedOnSeveralThreadsReachTheBandRequestOnceEach) {
  const std::string folder = scratchFolder();
  const std::string path = folder + "/bands.exr";
  writeMixed(path, "zip", 0);
  OIIO::ImageSpec spec;
  auto input = openInput(path, spec);
  ASSERT_TRUE(input) << OIIO::geterror();
  const std::size_t count = std::size_t(kWidth) * kHeight;
  std::vector<float> values(count * 2, -1.0f);
  std::vector<int> visits(count, 0);
  std::mutex mutex;
  ChannelRequest request{"passes", {indexOf(spec, "B"), indexOf(spec, "D")}, {"B", "D"},
                         OIIO::TypeFloat, nullptr, 2, {}};
  request.band = [&](std::size_t first, std::size_t n, const float* band) {
    std::lock_guard<std::mutex> lock(mutex);
    for (std::size_t i = 0; i < n; ++i) {
      ++visits[first + i];
      values[2 * (first + i)] = band[2 * i];
      values[2 * (first + i) + 1] = band[2 * i + 1];
    }
  };
  readPartChannels(*input, path, 3, 0, spec, {request}, 3);
  int wrong = 0;
  for (std::size_t p = 0; p < count; ++p) {
    wrong += visits[p] != 1;
    wrong += values[2 * p] != valueAt(int(p), 1);
    wrong += values[2 * p + 1] != valueAt(int(p), 3);
  }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace taa::io
