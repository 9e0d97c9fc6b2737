#include "io/part_channels.h"

#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <thread>

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

// A decoding thread's buffers: the band as decoded and a band request's rows.
struct BandScratch {
  FrameVector<unsigned char> band;  // frame-sized buffers: kept for the next pass
  std::vector<float> values;
};

// Where a pass's channels lie in a decoded pixel: the file's channels [begin, end), each at
// its byte offset and in its type there.
struct PassLayout {
  int begin = 0, end = 0;
  std::vector<std::size_t> offset;
  std::vector<OIIO::TypeDesc> type;
  std::size_t pixelBytes = 0;
};

PassLayout layoutOf(const Pass& pass, const OIIO::ImageSpec& spec) {
  PassLayout layout;
  layout.begin = spec.nchannels;
  for (const ChannelRequest* request : pass.requests) {
    for (int c : request->channels) {
      layout.begin = std::min(layout.begin, c);
      layout.end = std::max(layout.end, c + 1);
    }
  }
  for (int c = layout.begin; c < layout.end; ++c) {
    const OIIO::TypeDesc type =
        pass.format == OIIO::TypeUnknown ? spec.channelformat(c) : pass.format;
    layout.type.push_back(type);
    layout.offset.push_back(layout.pixelBytes);
    layout.pixelBytes += type.size();
  }
  return layout;
}

// How each request of the pass takes its channels from a decoded pixel.
std::vector<std::vector<ChannelCopy>> copiesOf(const Pass& pass, const PassLayout& layout) {
  std::vector<std::vector<ChannelCopy>> copies;
  for (const ChannelRequest* request : pass.requests) {
    const std::size_t size = request->type.size();
    std::vector<ChannelCopy>& mine = copies.emplace_back(request->channels.size());
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const std::size_t c = std::size_t(request->channels[k] - layout.begin);
      mine[k] = {layout.offset[c], k * size, layout.type[c] == OIIO::TypeHalf,
                 request->type == OIIO::TypeHalf};
    }
  }
  return copies;
}

}  // namespace

void readPartChannels(OIIO::ImageInput& input, const std::string& path, int frame, int part,
                      const OIIO::ImageSpec& spec, const std::vector<ChannelRequest>& requests,
                      int decodeThreads) {
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
  BandScratch callerScratch;  // the calling thread's: kept for the next pass
  for (const Pass& pass : passes) {
    const PassLayout layout = layoutOf(pass, spec);
    const std::vector<std::vector<ChannelCopy>> copies = copiesOf(pass, layout);
    const int bands = (spec.height + bandRows - 1) / bandRows;
    auto rowsOf = [&](int b) { return std::min(bandRows, spec.height - b * bandRows); };
    // A thread's scratch made to hold a band of this pass, once a pass.
    auto sizeForBands = [&](BandScratch& scratch) {
      scratch.band.resize(std::size_t(bandRows) * width * layout.pixelBytes);
    };
    // Each band's pixels to the requests (disjoint rows: bands may be copied on any thread).
    auto copyOut = [&](int b, BandScratch& scratch) {
      const int rows = rowsOf(b);
      const std::size_t count = std::size_t(rows) * width;
      const std::size_t firstPixel = std::size_t(b) * std::size_t(bandRows) * width;
      for (std::size_t r = 0; r < pass.requests.size(); ++r) {
        const ChannelRequest& request = *pass.requests[r];
        const std::size_t size = request.type.size();
        const std::size_t channels = std::size_t(request.outChannels);
        // A band request gets its rows in a scratch buffer, then handed over.
        if (request.band) scratch.values.resize(count * channels);
        auto* out = request.band ? reinterpret_cast<unsigned char*>(scratch.values.data())
                                 : static_cast<unsigned char*>(request.out) +
                                       firstPixel * channels * size;
        copyPixels(scratch.band.data(), layout.pixelBytes, out, channels * size, copies[r],
                   count);
        if (request.band) request.band(firstPixel, count, scratch.values.data());
      }
    };
    // A band from the chunks; false where that reader declines or fails.
    // (Either reads into scratch.band, sized for a band of this pass: sizeForBands.)
    auto fromChunks = [&](int b, BandScratch& scratch) {
      std::string chunkError;  // unused: OIIO reads the band again and says what is wrong
      return chunks && pass.format == OIIO::TypeUnknown &&
             chunks->readRows(spec.y + b * bandRows, rowsOf(b), layout.begin, layout.end,
                              scratch.band.data(), chunkError);
    };
    // A band through OIIO, whose errors name the file, frame and channels.
    auto fromOiio = [&](int b, BandScratch& scratch) {
      const int y = spec.y + b * bandRows, rows = rowsOf(b);
      // OIIO may report a failure only through its error state, so check both.
      // OIIO's OpenEXR reader reads tiled files by tiles only; a band is whole tile rows.
      const bool ok =
          spec.tile_height > 0
              ? input.read_tiles(part, 0, spec.x, spec.x + spec.width, y, y + rows, spec.z,
                                 spec.z + 1, layout.begin, layout.end, pass.format,
                                 scratch.band.data())
              : input.read_scanlines(part, 0, y, y + rows, spec.z, layout.begin, layout.end,
                                     pass.format, scratch.band.data());
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
    };
    // With threads to spare (nothing else runs while this frame is read), the chunks' bands
    // are decoded and copied on `decodeThreads` threads, band b on thread b % threads; a band
    // the chunk reader cannot decode is read by OIIO afterwards, on this thread, in order.
    const int threads = chunks && pass.format == OIIO::TypeUnknown
                            ? std::clamp(decodeThreads, 1, std::max(bands, 1))
                            : 1;
    std::vector<char> decoded(std::size_t(bands), 0);
    if (threads > 1) {
      std::vector<std::exception_ptr> failures(static_cast<std::size_t>(threads));
      auto work = [&](int t, BandScratch& scratch) {
        try {
          sizeForBands(scratch);
          for (int b = t; b < bands; b += threads) {
            if (!fromChunks(b, scratch)) continue;
            copyOut(b, scratch);
            decoded[std::size_t(b)] = 1;
          }
        } catch (...) {
          failures[std::size_t(t)] = std::current_exception();
        }
      };
      std::vector<BandScratch> helperScratch(std::size_t(threads - 1));
      {
        // Joined as this block ends, however it ends (a thread that cannot be started throws).
        struct Helpers {
          std::vector<std::thread> threads;
          ~Helpers() {
            for (std::thread& helper : threads) helper.join();
          }
        } helpers;
        for (int t = 1; t < threads; ++t) {
          helpers.threads.emplace_back(work, t, std::ref(helperScratch[std::size_t(t - 1)]));
        }
        work(0, callerScratch);
      }
      for (const std::exception_ptr& failure : failures) {
        if (failure) std::rethrow_exception(failure);
      }
    }
    sizeForBands(callerScratch);
    for (int b = 0; b < bands; ++b) {
      if (decoded[std::size_t(b)]) continue;
      // Where the threads ran, the chunk reader has failed this band already.
      if (threads > 1 || !fromChunks(b, callerScratch)) fromOiio(b, callerScratch);
      copyOut(b, callerScratch);
    }
  }
}

}  // namespace taa::io
