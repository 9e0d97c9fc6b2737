// Reads the channels several AOVs want from one part of an EXR file in a single decoding pass.
#pragma once

#include <OpenImageIO/imageio.h>

#include <functional>
#include <string>
#include <vector>

namespace taa::io {

// One AOV's share of a part: which channels, in which order, into what.
struct ChannelRequest {
  std::string aovName;         // names the AOV in errors: "color", "depth", ...
  std::vector<int> channels;   // channel indices in the part, in the order wanted
  std::vector<std::string> names;  // their names, for errors
  OIIO::TypeDesc type;         // TypeHalf or TypeFloat: the type `out` holds
  void* out = nullptr;         // width * height * outChannels values of `type`, row by row
  int outChannels = 0;         // values per pixel in `out`; the first channels.size() are set
  // Instead of `out` (type float, outChannels = channels.size()): each band of rows as it is
  // decoded, pixels [firstPixel, firstPixel + count) of the part (rows top first), the
  // channels interleaved. The frame's channels are then never held whole.
  std::function<void(std::size_t firstPixel, std::size_t count, const float* values)> band;
};

// Fills every request from part `part` of `input` (header `spec`). A multilayer file holds
// colour, depth and vectors in one part, and each read of a channel subset decodes every
// chunk of the part again (ZIP, PIZ, DWA compress all channels of a chunk together), so the
// part is decoded once: rows in bands a whole number of chunks or tiles tall, the channels
// from the lowest to the highest asked for in the file's own types, each request's copied out
// (half widened to float where a request asks); a ZIP, ZIPS or uncompressed scanline part's
// bands come from its chunks directly (io/scanline_chunks), any other's from OIIO. A request for
// a channel stored in another type (uint) is read on its own, converted by OIIO as before. Throws taa::Error naming `path`,
// `frame` and the channels when the file cannot be decoded (truncated, corrupt).
// `decodeThreads` above 1 decodes the chunks' bands on that many threads (the caller's one of
// them), for a caller that waits for the frame with cores idle; `band` callbacks then come
// from any of them, in no order, each for rows of its own.
void readPartChannels(OIIO::ImageInput& input, const std::string& path, int frame, int part,
                      const OIIO::ImageSpec& spec, const std::vector<ChannelRequest>& requests,
                      int decodeThreads = 1);

}  // namespace taa::io
