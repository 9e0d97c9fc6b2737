// taa-read-bench: decodes every channel of part 0 of each file twice, through OIIO's OpenEXR
// reader and through io/scanline_chunks, in bands of rows as the frame reader does, and prints
// the CPU and wall milliseconds of each and whether the two gave the same bytes
// (docs/PERFORMANCE.md, "Reading ZIP chunks"). Each file is read once before it is timed, so both find it in the
// page cache. OIIO's time leaves out opening the file (the frame reader has it open already);
// the chunk reader's includes opening it again. Linked with taatool's ZIP codec, so OIIO's
// path runs on libdeflate as in taatool.
//   taa-read-bench <file.exr>...
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "io/scanline_bands.h"
#include "io/scanline_chunks.h"
#include "process_time.h"

namespace {

using taa::bench::cpuSeconds;
using taa::bench::wallSeconds;

struct Timing {
  double cpu = 0, wall = 0;
};

// The whole part's channels, band by band into `band`, each band then copied into `frame`.
template <typename ReadBand>
Timing timeBands(const OIIO::ImageSpec& spec, std::vector<unsigned char>& band,
                 std::vector<unsigned char>& frame, ReadBand readBand) {
  const int rows = taa::io::rowsPerBand(spec);
  const std::size_t rowBytes = spec.pixel_bytes(true) * std::size_t(spec.width);
  band.resize(std::size_t(rows) * rowBytes);
  frame.resize(std::size_t(spec.height) * rowBytes);
  const double cpu = cpuSeconds(), wall = wallSeconds();
  for (int y = spec.y; y < spec.y + spec.height; y += rows) {
    const int count = std::min(rows, spec.y + spec.height - y);
    if (!readBand(y, count)) {
      std::fprintf(stderr, "taa-read-bench: cannot read rows from %d\n", y);
      std::exit(1);
    }
    std::copy(band.begin(), band.begin() + std::ptrdiff_t(std::size_t(count) * rowBytes),
              frame.begin() + std::ptrdiff_t(std::size_t(y - spec.y) * rowBytes));
  }
  return {cpuSeconds() - cpu, wallSeconds() - wall};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: taa-read-bench <file.exr>...\n");
    return 2;
  }
  std::vector<unsigned char> band, viaOiio, viaChunks;
  Timing oiio, chunks;
  int mismatches = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string path = argv[i];
    for (int pass = 0; pass < 2; ++pass) {  // the first pass only warms the page cache
      auto input = OIIO::ImageInput::open(path);
      if (!input) {
        std::fprintf(stderr, "taa-read-bench: %s\n", OIIO::geterror().c_str());
        return 1;
      }
      const OIIO::ImageSpec spec = input->spec();
      const Timing a = timeBands(spec, band, viaOiio, [&](int y, int rows) {
        return input->read_scanlines(0, 0, y, y + rows, 0, 0, spec.nchannels, OIIO::TypeUnknown,
                                     band.data());
      });
      const double openCpu = cpuSeconds(), openWall = wallSeconds();
      auto reader = taa::io::ScanlineChunkReader::open(path, 0, spec);
      if (!reader) {
        std::fprintf(stderr, "taa-read-bench: %s: not a part the chunk reader decodes\n",
                     path.c_str());
        return 1;
      }
      Timing b{cpuSeconds() - openCpu, wallSeconds() - openWall};
      std::string error;
      const Timing decode = timeBands(spec, band, viaChunks, [&](int y, int rows) {
        return reader->readRows(y, rows, 0, spec.nchannels, band.data(), error);
      });
      b.cpu += decode.cpu;
      b.wall += decode.wall;
      if (pass == 1) {
        oiio.cpu += a.cpu, oiio.wall += a.wall;
        chunks.cpu += b.cpu, chunks.wall += b.wall;
        mismatches += viaOiio != viaChunks;
      }
    }
  }
  const double files = argc - 1;
  std::printf("OIIO's reader:  %.0f ms CPU, %.0f ms wall a file\n", 1e3 * oiio.cpu / files,
              1e3 * oiio.wall / files);
  std::printf("chunk reader:   %.0f ms CPU, %.0f ms wall a file\n", 1e3 * chunks.cpu / files,
              1e3 * chunks.wall / files);
  std::printf("%d of %d files decoded to different bytes\n", mismatches, argc - 1);
  return mismatches == 0 ? 0 : 1;
}
