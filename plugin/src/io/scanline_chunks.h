// Reads the pixels of a scanline EXR part stored as ZIP, ZIPS or uncompressed straight from its
// chunks. OpenEXR 3.1 as Debian builds it undoes ZIP's byte predictor one byte at a time and
// then converts every value through its XDR layer into the caller's frame buffer: for a
// render's every pass that was most of a frame's reading time. Here the predictor runs sixteen
// bytes at a time and each channel's row is copied as it lies (EXR stores values little-endian,
// as this machine does). Anything else (tiles, deep data, another codec, subsampled channels)
// is left to OIIO: `open` says so by returning nothing.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace taa::io {

class ScanlineChunkReader {
 public:
  // The reader of part `part` of `path`, whose header OIIO read as `spec`; null when the part is
  // not one this reader decodes or OpenEXR's core library cannot open the file.
  static std::unique_ptr<ScanlineChunkReader> open(const std::string& path, int part,
                                                   const OIIO::ImageSpec& spec);
  ~ScanlineChunkReader();
  ScanlineChunkReader(const ScanlineChunkReader&) = delete;
  ScanlineChunkReader& operator=(const ScanlineChunkReader&) = delete;

  // Rows [y, y + rows) of the spec's channels [begin, end) into `band`, as OIIO's
  // read_scanlines with TypeUnknown would write them: pixels interleaved, each channel in its
  // file type, decoded on the calling thread. False, with `error` set, when a chunk cannot be
  // read or does not decode to its size (a truncated or corrupt file).
  bool readRows(int y, int rows, int begin, int end, unsigned char* band, std::string& error);

 private:
  struct State;
  explicit ScanlineChunkReader(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// ZIP's byte predictor undone in place: the coder stores each byte of a block as its
// difference from the byte before plus 128 (after putting the block's even bytes first and its
// odd bytes after, which the reader undoes as it copies rows out). Exposed for its test against
// the plain definition.
void undoZipDeltas(std::uint8_t* bytes, std::size_t n);

}  // namespace taa::io
