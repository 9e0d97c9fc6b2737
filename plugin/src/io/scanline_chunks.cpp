#include "io/scanline_chunks.h"

#include <OpenEXR/openexr.h>
#include <libdeflate.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cstring>
#include <vector>

namespace taa::io {
namespace {

// The context's errors come back as result codes; OpenEXR's default handler would print them.
void ignoreError(exr_const_context_t, exr_result_t, const char*) {}

struct DecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

// A decompressor and the chunk buffers of one thread (a reader thread lives as long as its
// run): a chunk's few megabytes are allocated once a thread, not once a chunk or a file.
struct ThreadScratch {
  std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> decompressor{
      libdeflate_alloc_decompressor()};
  std::vector<std::uint8_t> packed, inflated;
};

ThreadScratch& threadScratch() {
  thread_local ThreadScratch scratch;
  return scratch;
}

// Copies `width` values of `size` bytes, `from` packed, `to` `stride` bytes apart.
void copyRow(const std::uint8_t* from, std::size_t size, std::size_t width, std::uint8_t* to,
             std::size_t stride) {
  // memcpy of a constant size compiles to a move.
  if (size == 2) {
    for (std::size_t x = 0; x < width; ++x, from += 2, to += stride) std::memcpy(to, from, 2);
  } else {
    for (std::size_t x = 0; x < width; ++x, from += 4, to += stride) std::memcpy(to, from, 4);
  }
}

// Copies `width` values of `size` bytes that start at the even byte `offset` of a ZIP block held
// as its two halves (`even`: the block's bytes 0, 2, 4...; `odd`: 1, 3, 5...), putting each
// value's bytes back together, to `to`, `stride` bytes apart.
void copyRowFromHalves(const std::uint8_t* even, const std::uint8_t* odd, std::size_t offset,
                       std::size_t size, std::size_t width, std::uint8_t* to, std::size_t stride) {
  even += offset / 2;
  odd += offset / 2;
  if (size == 2) {
    for (std::size_t x = 0; x < width; ++x, to += stride) {
      const std::uint16_t value = std::uint16_t(even[x] | odd[x] << 8);
      std::memcpy(to, &value, 2);
    }
  } else {
    for (std::size_t x = 0; x < width; ++x, even += 2, odd += 2, to += stride) {
      const std::uint32_t value = std::uint32_t(even[0]) | std::uint32_t(odd[0]) << 8 |
                                  std::uint32_t(even[1]) << 16 | std::uint32_t(odd[1]) << 24;
      std::memcpy(to, &value, 4);
    }
  }
}

#if defined(__SSE2__)
// The running byte sums of `deltas` (each less 128) within the register, plus `carry` (every
// byte the sum so far).
inline __m128i runningSums(__m128i deltas, __m128i carry) {
  __m128i x = _mm_sub_epi8(deltas, _mm_set1_epi8(char(-128)));
  x = _mm_add_epi8(x, _mm_slli_si128(x, 1));
  x = _mm_add_epi8(x, _mm_slli_si128(x, 2));
  x = _mm_add_epi8(x, _mm_slli_si128(x, 4));
  x = _mm_add_epi8(x, _mm_slli_si128(x, 8));
  return _mm_add_epi8(x, carry);
}

// Every byte of `x` set to its last byte.
inline __m128i lastByteEverywhere(__m128i x) {
  const __m128i high = _mm_unpackhi_epi8(x, x);                  // bytes 8..15, each twice
  const __m128i word = _mm_shufflehi_epi16(high, 0xFF);          // byte 15 in the top words
  return _mm_shuffle_epi32(word, 0xFF);
}
#endif

struct FileChannel {
  std::size_t size = 0;    // bytes a value
  std::size_t offset = 0;  // where its values start within a line of a chunk
};

}  // namespace

void undoZipDeltas(std::uint8_t* bytes, std::size_t n) {
  // A running sum from 128, so that the first byte, taken as a delta less 128, is itself.
  std::uint8_t sum = 128;
  std::size_t i = 0;
#if defined(__SSE2__)
  __m128i carry = _mm_set1_epi8(char(sum));
  for (; i + 16 <= n; i += 16) {
    auto* at = reinterpret_cast<__m128i*>(bytes + i);
    const __m128i sums = runningSums(_mm_loadu_si128(at), carry);
    _mm_storeu_si128(at, sums);
    carry = lastByteEverywhere(sums);
  }
  sum = std::uint8_t(_mm_cvtsi128_si32(carry));
#endif
  for (; i < n; ++i) bytes[i] = sum = std::uint8_t(sum + bytes[i] - 128);
}

struct ScanlineChunkReader::State {
  exr_context_t context = nullptr;
  int part = 0;
  bool zipped = false;            // ZIP or ZIPS; else stored as is
  int firstRow = 0, rowCount = 0;  // the data window's rows
  std::size_t width = 0;
  int linesPerChunk = 1;
  std::size_t lineBytes = 0;  // one line of a chunk, every channel
  std::vector<FileChannel> channels;  // by the spec's channel index

  ~State() {
    if (context) exr_finish(&context);
  }

  // Decodes the chunk that starts at row `chunkY` and copies its rows within [y, y + rows) of
  // channels [begin, end) into `band` (pixelBytes a pixel, bandOffset[c - begin] each channel).
  std::string decodeChunk(int chunkY, int y, int rows, int begin, int end, std::uint8_t* band,
                          std::size_t pixelBytes,
                          const std::vector<std::size_t>& bandOffset) const {
    exr_chunk_info_t info;
    exr_result_t result = exr_read_scanline_chunk_info(context, part, chunkY, &info);
    if (result != EXR_ERR_SUCCESS) return exr_get_default_error_message(result);
    const std::size_t expected = std::size_t(info.height) * lineBytes;
    if (info.start_y != chunkY || info.height < 1 || info.unpacked_size != expected ||
        info.packed_size > expected || (!zipped && info.packed_size != expected)) {
      return "the chunk at row " + std::to_string(chunkY) + " does not match its header";
    }
    ThreadScratch& scratch = threadScratch();
    scratch.packed.resize(info.packed_size);
    result = exr_read_chunk(context, part, &info, scratch.packed.data());
    if (result != EXR_ERR_SUCCESS) return exr_get_default_error_message(result);
    const int from = std::max(y, info.start_y), to = std::min(y + rows, info.start_y + info.height);
    if (info.packed_size == expected) {  // a chunk ZIP could not shrink is stored as is
      for (int row = from; row < to; ++row) {
        const std::uint8_t* line =
            scratch.packed.data() + std::size_t(row - info.start_y) * lineBytes;
        std::uint8_t* pixels = band + std::size_t(row - y) * width * pixelBytes;
        for (int c = begin; c < end; ++c) {
          const FileChannel& channel = channels[std::size_t(c)];
          copyRow(line + channel.offset, channel.size, width,
                  pixels + bandOffset[std::size_t(c - begin)], pixelBytes);
        }
      }
      return {};
    }
    scratch.inflated.resize(expected);
    std::size_t inflatedBytes = 0;
    if (!scratch.decompressor ||
        libdeflate_zlib_decompress(scratch.decompressor.get(), scratch.packed.data(),
                                   info.packed_size, scratch.inflated.data(), expected,
                                   &inflatedBytes) != LIBDEFLATE_SUCCESS ||
        inflatedBytes != expected) {
      return "the chunk at row " + std::to_string(chunkY) + " does not inflate to its size";
    }
    // The deltas summed in place; the block's bytes are then read from its two halves as each
    // row is copied out, with no de-interleaved copy of the block.
    undoZipDeltas(scratch.inflated.data(), expected);
    const std::uint8_t* even = scratch.inflated.data();
    const std::uint8_t* odd = even + (expected + 1) / 2;
    for (int row = from; row < to; ++row) {
      const std::size_t line = std::size_t(row - info.start_y) * lineBytes;
      std::uint8_t* pixels = band + std::size_t(row - y) * width * pixelBytes;
      for (int c = begin; c < end; ++c) {
        const FileChannel& channel = channels[std::size_t(c)];
        copyRowFromHalves(even, odd, line + channel.offset, channel.size, width,
                          pixels + bandOffset[std::size_t(c - begin)], pixelBytes);
      }
    }
    return {};
  }
};

std::unique_ptr<ScanlineChunkReader> ScanlineChunkReader::open(const std::string& path, int part,
                                                               const OIIO::ImageSpec& spec) {
  // EXR's values are little-endian: rows are copied as they lie only on such a machine.
  if (__BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__ || spec.tile_width > 0 || spec.deep) {
    return nullptr;
  }
  auto state = std::make_unique<State>();
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &ignoreError;
  if (exr_start_read(&state->context, path.c_str(), &init) != EXR_ERR_SUCCESS) return nullptr;
  exr_storage_t storage;
  exr_compression_t compression;
  exr_attr_box2i_t window;
  const exr_attr_chlist_t* list = nullptr;
  int partCount = 0;
  if (exr_get_count(state->context, &partCount) != EXR_ERR_SUCCESS || part < 0 ||
      part >= partCount ||
      exr_get_storage(state->context, part, &storage) != EXR_ERR_SUCCESS ||
      storage != EXR_STORAGE_SCANLINE ||
      exr_get_compression(state->context, part, &compression) != EXR_ERR_SUCCESS ||
      (compression != EXR_COMPRESSION_ZIP && compression != EXR_COMPRESSION_ZIPS &&
       compression != EXR_COMPRESSION_NONE) ||
      exr_get_data_window(state->context, part, &window) != EXR_ERR_SUCCESS ||
      exr_get_scanlines_per_chunk(state->context, part, &state->linesPerChunk) !=
          EXR_ERR_SUCCESS ||
      exr_get_channels(state->context, part, &list) != EXR_ERR_SUCCESS || !list) {
    return nullptr;
  }
  state->part = part;
  state->zipped = compression != EXR_COMPRESSION_NONE;
  state->firstRow = window.min.y;
  state->rowCount = window.max.y - window.min.y + 1;
  state->width = std::size_t(window.max.x - window.min.x + 1);
  // The header OIIO read must describe the same pixels, channel for channel (by name: OIIO
  // orders a layer's R, G, B, A as such, the file alphabetically).
  if (window.min.x != spec.x || window.min.y != spec.y || int(state->width) != spec.width ||
      state->rowCount != spec.height || list->num_channels != spec.nchannels ||
      state->linesPerChunk < 1) {
    return nullptr;
  }
  std::vector<FileChannel> inFileOrder(std::size_t(list->num_channels));
  std::size_t lineBytes = 0;
  for (int k = 0; k < list->num_channels; ++k) {
    const exr_attr_chlist_entry_t& entry = list->entries[k];
    if (entry.x_sampling != 1 || entry.y_sampling != 1) return nullptr;
    const std::size_t size = entry.pixel_type == EXR_PIXEL_HALF ? 2 : 4;
    inFileOrder[std::size_t(k)] = {size, lineBytes * state->width};
    lineBytes += size;
  }
  state->lineBytes = lineBytes * state->width;
  state->channels.resize(std::size_t(spec.nchannels));
  std::vector<bool> taken(inFileOrder.size(), false);
  for (int c = 0; c < spec.nchannels; ++c) {
    int match = -1;
    for (int k = 0; k < list->num_channels; ++k) {
      if (!taken[std::size_t(k)] && spec.channelnames[std::size_t(c)] == list->entries[k].name.str) {
        match = k;
        break;
      }
    }
    if (match < 0 || inFileOrder[std::size_t(match)].size != spec.channelformat(c).size()) {
      return nullptr;
    }
    taken[std::size_t(match)] = true;
    state->channels[std::size_t(c)] = inFileOrder[std::size_t(match)];
  }
  return std::unique_ptr<ScanlineChunkReader>(new ScanlineChunkReader(std::move(state)));
}

ScanlineChunkReader::ScanlineChunkReader(std::unique_ptr<State> state)
    : state_(std::move(state)) {}

ScanlineChunkReader::~ScanlineChunkReader() = default;

bool ScanlineChunkReader::readRows(int y, int rows, int begin, int end, unsigned char* band,
                                   std::string& error) {
  const State& s = *state_;
  std::vector<std::size_t> bandOffset(std::size_t(end - begin));
  std::size_t pixelBytes = 0;
  for (int c = begin; c < end; ++c) {
    bandOffset[std::size_t(c - begin)] = pixelBytes;
    pixelBytes += s.channels[std::size_t(c)].size;
  }
  // The chunks that hold the rows: chunks start every linesPerChunk rows from the window's top.
  const int first = s.firstRow + (y - s.firstRow) / s.linesPerChunk * s.linesPerChunk;
  const int count = (y + rows - first + s.linesPerChunk - 1) / s.linesPerChunk;
  // One chunk after another on the calling thread: decoding a band's chunks on OIIO's thread
  // pool was measured and not kept (more CPU for the whole run: docs/PERFORMANCE.md).
  for (int k = 0; k < count; ++k) {
    error = s.decodeChunk(first + k * s.linesPerChunk, y, rows, begin, end, band, pixelBytes,
                          bandOffset);
    if (!error.empty()) return false;
  }
  return true;
}

}  // namespace taa::io
