#include "io/exr_chunk_check.h"

#include <OpenEXR/openexr.h>

#include <vector>

namespace taa::io {
namespace {

// OpenEXR's core reports errors on stderr by default; here they are the caller's to word.
void silent(exr_const_context_t, exr_result_t, const char*) {}

// Decodes part `part`'s chunk at `y` into scratch memory; the core refuses a chunk that
// decompresses to fewer bytes than the window asks for.
exr_result_t decodeChunk(exr_context_t context, int part, const exr_chunk_info_t& chunk) {
  exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
  exr_result_t result = exr_decoding_initialize(context, part, &chunk, &decoder);
  std::vector<unsigned char> scratch;
  if (result == EXR_ERR_SUCCESS) {
    std::size_t bytes = 0;
    for (int c = 0; c < decoder.channel_count; ++c) {
      const exr_coding_channel_info_t& ch = decoder.channels[c];
      bytes += std::size_t(ch.height) * std::size_t(ch.width) * std::size_t(ch.bytes_per_element);
    }
    scratch.resize(bytes + 1);
    std::size_t offset = 0;
    for (int c = 0; c < decoder.channel_count; ++c) {
      exr_coding_channel_info_t& ch = decoder.channels[c];
      ch.decode_to_ptr = scratch.data() + offset;
      ch.user_bytes_per_element = ch.bytes_per_element;
      ch.user_data_type = ch.data_type;
      ch.user_pixel_stride = ch.bytes_per_element;
      ch.user_line_stride = ch.width * ch.bytes_per_element;
      offset += std::size_t(ch.height) * std::size_t(ch.user_line_stride);
    }
    result = exr_decoding_choose_default_routines(context, part, &decoder);
    if (result == EXR_ERR_SUCCESS) result = exr_decoding_run(context, part, &decoder);
  }
  exr_decoding_destroy(context, &decoder);
  return result;
}

}  // namespace

std::string firstChunkMismatch(const std::string& path) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = silent;
  exr_context_t context = nullptr;
  if (exr_start_read(&context, path.c_str(), &init) != EXR_ERR_SUCCESS) return "";  // OIIO says
  std::string why;
  int parts = 0;
  exr_get_count(context, &parts);
  for (int part = 0; part < parts && why.empty(); ++part) {
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_compression_t compression = EXR_COMPRESSION_NONE;
    exr_attr_box2i_t window{};
    exr_chunk_info_t chunk{};
    if (exr_get_storage(context, part, &storage) != EXR_ERR_SUCCESS ||
        storage != EXR_STORAGE_SCANLINE ||
        exr_get_compression(context, part, &compression) != EXR_ERR_SUCCESS ||
        exr_get_data_window(context, part, &window) != EXR_ERR_SUCCESS ||
        exr_read_scanline_chunk_info(context, part, window.min.y, &chunk) != EXR_ERR_SUCCESS) {
      continue;  // nothing this check can say; OIIO's reader reports what it finds
    }
    // Uncompressed data is its own size; compressed data shows its size when decompressed.
    const bool shortRaw = compression == EXR_COMPRESSION_NONE &&
                          chunk.packed_size != chunk.unpacked_size;
    if (shortRaw || decodeChunk(context, part, chunk) == EXR_ERR_CORRUPT_CHUNK) {
      why = "part " + std::to_string(part) + "'s first chunk holds " +
            std::to_string(chunk.packed_size) + " bytes" +
            (shortRaw ? "" : " (compressed)") + " where its data window " +
            std::to_string(window.max.x - window.min.x + 1) + "x" +
            std::to_string(window.max.y - window.min.y + 1) + " needs " +
            std::to_string(chunk.unpacked_size);
    }
  }
  exr_finish(&context);
  return why;
}

}  // namespace taa::io
