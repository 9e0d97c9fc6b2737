// taatool's ZIP codec (fast_zlib): zlib's one-shot calls served by libdeflate in a process that
// links it, as taatool does. The streams must stay zlib's format both ways, errors must stay
// zlib's, and OpenEXR (through OIIO) must read back what it wrote.
#include <gtest/gtest.h>
#include <zlib.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <fstream>
#include <random>
#include <vector>

#include "fast_zlib/fast_zlib.h"
#include "io/exr_writer.h"
#include "test_files.h"

namespace taa {
namespace {

// Compressible but not trivial: a gradient with noise in the low bits, like half pixels.
std::vector<std::uint8_t> sampleData(std::size_t size) {
  std::vector<std::uint8_t> data(size);
  std::mt19937 random(7);
  for (std::size_t i = 0; i < size; ++i) {
    data[i] = std::uint8_t((i / 64) % 200 + (random() % 4));
  }
  return data;
}

// zlib's streaming inflate, which this process does not replace.
std::vector<std::uint8_t> inflateWithZlib(const std::vector<std::uint8_t>& stream,
                                          std::size_t size) {
  std::vector<std::uint8_t> out(size);
  z_stream z{};
  EXPECT_EQ(inflateInit(&z), Z_OK);
  z.next_in = const_cast<Bytef*>(stream.data());
  z.avail_in = uInt(stream.size());
  z.next_out = out.data();
  z.avail_out = uInt(out.size());
  EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
  inflateEnd(&z);
  return out;
}

std::vector<std::uint8_t> compressed(const std::vector<std::uint8_t>& data, int level) {
  std::vector<std::uint8_t> stream(compressBound(uLong(data.size())));
  uLongf length = uLongf(stream.size());
  EXPECT_EQ(compress2(stream.data(), &length, data.data(), uLong(data.size()), level), Z_OK);
  stream.resize(length);
  return stream;
}

TEST(FastZlib, ServesZlibsOneShotCallsInThisProcess) {
  EXPECT_TRUE(fast_zlib::active());
  EXPECT_NE(fast_zlib::description().find("libdeflate"), std::string::npos);
}

TEST(FastZlib, CompressesToStreamsZlibReads) {
  const std::vector<std::uint8_t> data = sampleData(200000);
  for (int level : {Z_DEFAULT_COMPRESSION, 0, 1, 4, 9}) {
    SCOPED_TRACE("level " + std::to_string(level));
    const std::vector<std::uint8_t> stream = compressed(data, level);
    if (level != 0) {
      EXPECT_LT(stream.size(), data.size() * 3 / 4);
    }
    EXPECT_EQ(inflateWithZlib(stream, data.size()), data);
  }
}

TEST(FastZlib, UncompressesZlibsStreams) {
  const std::vector<std::uint8_t> data = sampleData(100000);
  std::vector<std::uint8_t> stream(compressBound(uLong(data.size())));
  z_stream z{};
  ASSERT_EQ(deflateInit(&z, 6), Z_OK);  // zlib's own streaming deflate
  z.next_in = const_cast<Bytef*>(data.data());
  z.avail_in = uInt(data.size());
  z.next_out = stream.data();
  z.avail_out = uInt(stream.size());
  ASSERT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  stream.resize(z.total_out);
  deflateEnd(&z);

  std::vector<std::uint8_t> out(data.size() + 100);  // room to spare: the length is reported
  uLongf length = uLongf(out.size());
  ASSERT_EQ(uncompress(out.data(), &length, stream.data(), uLong(stream.size())), Z_OK);
  ASSERT_EQ(length, data.size());
  out.resize(length);
  EXPECT_EQ(out, data);
}

TEST(FastZlib, ErrorsAreZlibs) {
  const std::vector<std::uint8_t> data = sampleData(50000);
  std::vector<std::uint8_t> stream = compressed(data, 1);
  std::vector<std::uint8_t> out(data.size());

  uLongf tooSmall = uLongf(data.size() / 2);
  EXPECT_EQ(uncompress(out.data(), &tooSmall, stream.data(), uLong(stream.size())), Z_BUF_ERROR);

  std::vector<std::uint8_t> truncated(stream.begin(), stream.begin() + stream.size() / 2);
  uLongf length = uLongf(out.size());
  const int truncatedResult =
      uncompress(out.data(), &length, truncated.data(), uLong(truncated.size()));
  EXPECT_TRUE(truncatedResult == Z_DATA_ERROR || truncatedResult == Z_BUF_ERROR)
      << truncatedResult;

  stream[0] = 0xff;  // not a zlib header
  length = uLongf(out.size());
  EXPECT_EQ(uncompress(out.data(), &length, stream.data(), uLong(stream.size())), Z_DATA_ERROR);

  std::vector<std::uint8_t> small(8);
  uLongf smallLength = uLongf(small.size());
  EXPECT_EQ(compress2(small.data(), &smallLength, data.data(), uLong(data.size()), 1),
            Z_BUF_ERROR);
}

// OpenEXR's ZIP and ZIPS codecs through OIIO: what taatool writes reads back exactly, and a
// damaged file is an error, not a crash or silent garbage.
TEST(FastZlib, ExrZipFilesRoundTrip) {
  const std::string folder = test::scratchFolder();
  const int width = 96, height = 40;
  TypedImage image(width, height, 4, SampleType::Half);
  HalfImage& halves = *image.halves();
  for (std::size_t i = 0; i < halves.pixels.size(); ++i) {
    halves.pixels[i] = Imath::half(float((i * 37) % 1000) / 250.0f);
  }
  for (const char* compression : {"zip", "zips", "zip:9"}) {
    SCOPED_TRACE(compression);
    const std::string path = folder + "/frame.exr";
    io::writeExrAtomic(path, image, OIIO::ImageSpec(), io::WriteOptions(io::PixelType::Half,
                                                                        compression));
    OIIO::ImageSpec spec;
    const std::vector<float> pixels = test::readImage(path, spec);
    ASSERT_EQ(pixels.size(), halves.pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      ASSERT_EQ(pixels[i], float(halves.pixels[i])) << "value " << i;
    }

    // Damage the middle of the pixel data: reading must fail.
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekg(0, std::ios::end);
    const std::streamoff size = file.tellg();
    file.seekp(size / 2);
    const std::vector<char> garbage(64, '\x5a');
    file.write(garbage.data(), std::streamsize(garbage.size()));
    file.close();
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input);
    std::vector<float> damaged(pixels.size());
    EXPECT_FALSE(input->read_image(0, 0, 0, 4, OIIO::TypeFloat, damaged.data()) &&
                 damaged == pixels);
  }
}

}  // namespace
}  // namespace taa
