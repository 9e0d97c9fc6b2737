#include "io/part_channels.h"

#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

#include "taa/error.h"
#include "io/scanline_bands.h"
#include "io/scanline_chunks.h"
#include "util/frame_buffer_pool.h"

namespace taa::io {
namespace {

bool halfOrFloat(OIIO::TypeDesc type) {
  return type == OIIO::TypeHalf || type == OIIO::TypeFloat;
}

// "a", "a and b", "a, b and c".
std::string listed(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  }
  return text;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// One decoding pass: channels [begin, end) of every row, in `format` (TypeUnknown: each
// channel in its file type), feeding `requests`.
struct Pass {
  OIIO::TypeDesc format;
  std::vector<const ChannelRequest*> requests;
};

// How one channel goes from a decoded pixel to a request's pixel.
struct ChannelCopy {
  std::size_t from = 0, to = 0;  // byte offsets within the decoded and the request's pixel
  bool fromHalf = false, toHalf = false;
};

// Copies `count` pixels' channels from `from` (pixels `fromStride` bytes apart) to `to` (pixels
// `toStride` bytes apart). Pixel by pixel, all channels at once: a band of a render's every pass
// is tens of megabytes, and a pass over it per channel fetched it from memory 70 times. Half
// widens to float exactly; float narrows to half only for values that came from half.
void copyPixels(const unsigned char* from, std::size_t fromStride, unsigned char* to,
                std::size_t toStride, const std::vector<ChannelCopy>& channels,
                std::size_t count) {
  for (std::size_t i = 0; i < count; ++i, from += fromStride, to += toStride) {
    for (const ChannelCopy& c : channels) {
      // memcpy of a constant size compiles to a move; of a variable size, to a library call.
      if (c.fromHalf == c.toHalf) {
        if (c.fromHalf) {
          std::memcpy(to + c.to, from + c.from, 2);
        } else {
          std::memcpy(to + c.to, from + c.from, 4);
        }
      } else if (c.fromHalf) {
        Imath::half h;
        std::memcpy(&h, from + c.from, sizeof h);
        const float f = h;
        std::memcpy(to + c.to, &f, sizeof f);
      } else {
        float f;
        std::memcpy(&f, from + c.from, sizeof f);
        const Imath::half h(f);
        std::memcpy(to + c.to, &h, sizeof h);
      }
    }
  }
}

}  // namespace

void readPartChannels(OIIO::ImageInput& input, const std::string& path, int frame, int part,
                      const OIIO::ImageSpec& spec, const std::vector<ChannelRequest>& requests) {
  // Requests whose channels are all half or float share one pass in the file's types; any
  // other is decoded on its own, converted to its type by OIIO.
  std::vector<Pass> passes;
  Pass shared{OIIO::TypeUnknown, {}};
  for (const ChannelRequest& request : requests) {
    const bool native = std::all_of(request.channels.begin(), request.channels.end(),
                                    [&](int c) { return halfOrFloat(spec.channelformat(c)); });
    if (native) {
      shared.requests.push_back(&request);
    } else {
      passes.push_back({request.type, {&request}});
    }
  }
  if (!shared.requests.empty()) passes.insert(passes.begin(), shared);

  const std::size_t width = std::size_t(spec.width);
  const int bandRows = rowsPerBand(spec);
  // Channels in their file types of a ZIP, ZIPS or uncompressed scanline part are decoded from
  // the chunks (io/scanline_chunks); where that reader declines or fails, OIIO reads the band,
  // and its errors are the ones reported.
  const bool anyNative = std::any_of(passes.begin(), passes.end(), [](const Pass& pass) {
    return pass.format == OIIO::TypeUnknown;
  });
  std::unique_ptr<ScanlineChunkReader> chunks =
      anyNative ? ScanlineChunkReader::open(path, part, spec) : nullptr;
  FrameVector<unsigned char> band;  // a frame-sized buffer: kept for the next frame
  std::vector<float> bandValues;     // a band request's rows (ChannelRequest::band)
  for (const Pass& pass : passes) {
    int begin = spec.nchannels, end = 0;
    for (const ChannelRequest* request : pass.requests) {
      for (int c : request->channels) {
        begin = std::min(begin, c);
        end = std::max(end, c + 1);
      }
    }
    // Where each channel of the range lies within a decoded pixel, and its type there.
    std::vector<std::size_t> offset(std::size_t(end - begin));
    std::vector<OIIO::TypeDesc> type(std::size_t(end - begin));
    std::size_t pixelBytes = 0;
    for (int c = begin; c < end; ++c) {
      type[std::size_t(c - begin)] =
          pass.format == OIIO::TypeUnknown ? spec.channelformat(c) : pass.format;
      offset[std::size_t(c - begin)] = pixelBytes;
      pixelBytes += type[std::size_t(c - begin)].size();
    }
    band.resize(std::size_t(bandRows) * width * pixelBytes);

    for (int y = spec.y; y < spec.y + spec.height; y += bandRows) {
      const int rows = std::min(bandRows, spec.y + spec.height - y);
      std::string chunkError;  // unused: OIIO reads the band again and says what is wrong
      const bool decoded = chunks && pass.format == OIIO::TypeUnknown &&
                           chunks->readRows(y, rows, begin, end, band.data(), chunkError);
      // OIIO may report a failure only through its error state, so check both.
      // OIIO's OpenEXR reader reads tiled files by tiles only; a band is whole tile rows.
      bool ok = decoded;
      if (!decoded) {
        ok = spec.tile_height > 0
                 ? input.read_tiles(part, 0, spec.x, spec.x + spec.width, y, y + rows, spec.z,
                                    spec.z + 1, begin, end, pass.format, band.data())
                 : input.read_scanlines(part, 0, y, y + rows, spec.z, begin, end, pass.format,
                                        band.data());
      }
      if (!ok || input.has_error()) {
        std::string reason = input.geterror();
        if (reason.empty()) reason = "unknown error";
        std::vector<std::string> aovs, names;
        for (const ChannelRequest* request : pass.requests) {
          aovs.push_back(request->aovName);
          names.insert(names.end(), request->names.begin(), request->names.end());
        }
        throw Error("cannot read the " + listed(aovs) +
                        " pixels (truncated or corrupt file?): " + reason,
                    {path, frame, joined(names)});
      }
      const std::size_t count = std::size_t(rows) * width;
      const std::size_t firstPixel = std::size_t(y - spec.y) * width;
      for (const ChannelRequest* request : pass.requests) {
        const std::size_t size = request->type.size();
        const std::size_t channels = std::size_t(request->outChannels);
        // A band request gets its rows in a scratch buffer, then handed over.
        if (request->band) bandValues.resize(count * channels);
        auto* out = request->band ? reinterpret_cast<unsigned char*>(bandValues.data())
                                  : static_cast<unsigned char*>(request->out) +
                                        firstPixel * channels * size;
        std::vector<ChannelCopy> copies(request->channels.size());
        for (std::size_t k = 0; k < copies.size(); ++k) {
          const std::size_t c = std::size_t(request->channels[k] - begin);
          copies[k] = {offset[c], k * size, type[c] == OIIO::TypeHalf,
                       request->type == OIIO::TypeHalf};
        }
        copyPixels(band.data(), pixelBytes, out, channels * size, copies, count);
        if (request->band) request->band(firstPixel, count, bandValues.data());
      }
    }
  }
}

}  // namespace taa::io
