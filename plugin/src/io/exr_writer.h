// Writes resolved frames as EXR, atomically: into a temporary file in the target folder, then
// renamed over the final path, so no half-written file is ever left at the final path.
#pragma once

#include <OpenImageIO/imageio.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "util/image.h"

namespace taa::io {

// AsInput: the template's type for its first color channel (rgbaNames[0]); half stays half,
// anything else is written as float. Without a template: float.
enum class PixelType { Half, Float, AsInput };

struct WriteOptions {
  WriteOptions(PixelType type = PixelType::AsInput, std::string compressionName = "zip",
               std::vector<std::string> names = {})
      : pixelType(type), compression(std::move(compressionName)), rgbaNames(std::move(names)) {}

  PixelType pixelType = PixelType::AsInput;
  // Any OpenEXR compression OIIO knows: none, zip, piz, dwaa... A bare "zip" or "zips" means
  // level 1 (kDefaultZipLevel), not OpenEXR's 4: on resolved frames it encodes about 25% faster
  // for files about 2.5% larger; "zip:4" (1 to 9) picks a level.
  std::string compression = "zip";
  std::vector<std::string> rgbaNames;  // the 4 color channels' names; empty: R, G, B, A
  // A multi-view file's views (its `multiView` attribute, the default view first); empty: none.
  std::vector<std::string> views;
};

// Channels written after R, G, B, A (diagnostics, pass-through): one name per image channel.
struct ExtraChannels {
  std::vector<std::string> names;
  Image image;  // same size as the RGBA image; empty: none
  std::vector<OIIO::TypeDesc> formats;  // per name (pass-through keeps its type); empty: the
                                        // color's pixel type
  // Instead of `image` (which is then empty): every pixel's channels packed one after another
  // in their `formats` (half or float), as the file lays them out. A render's every pass held
  // so takes 190 bytes a pixel instead of 268 as float while it waits to be written.
  struct Packed {
    int width = 0, height = 0;
    FrameVector<unsigned char> bytes;
    // Or, instead of `bytes`: packs pixels [first, first + count) (rows top first), pixel
    // first + n at to + n * stride, when the writer reaches them, a band at a time, so the
    // packed frame is never held whole. Called in order, one call at a time, on a thread of
    // the writer's (the next band is packed while the last one is coded).
    std::function<void(std::size_t first, std::size_t count, unsigned char* to,
                       std::size_t stride)>
        rows;
  } packed;

  bool isPacked() const { return !packed.bytes.empty() || bool(packed.rows); }
};

// `extra`'s packed channels (ExtraChannels::packed) as float in `image`; nothing when it is not
// packed.
void unpackExtraChannels(ExtraChannels& extra);

// Appends `more`'s channels after `extra`'s (same image size, or `extra` empty: then `more` is
// moved in, not copied, packed or not, which matters for a render's every pass; packed
// channels joined with others are unpacked first).
void appendExtraChannels(ExtraChannels& extra, ExtraChannels more);

// "half" | "float" | "input"; otherwise throws taa::Error.
PixelType parsePixelType(const std::string& text);

// The zlib level of a bare "zip" or "zips" (see WriteOptions::compression).
constexpr int kDefaultZipLevel = 1;

// Accepts the OpenEXR compressions none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab, and
// "name:level" for zip, zips, dwaa and dwab; otherwise throws taa::Error. Lets faces check the
// option before any frame is resolved.
void validateCompression(const std::string& compression);

// The type the colour channels are written as for `options` and `templateSpec` (see PixelType).
// Resolving into this type lets a half output go from the GPU to the file without conversion.
SampleType outputSampleType(const WriteOptions& options, const OIIO::ImageSpec& templateSpec);

// Writes `rgba` (4 channels, covering the template's data window, half or float) to `path` as
// R, G, B, A (or options.rgbaNames), then the extra channels if any. Channel names must be
// unique. Samples are converted only when their type differs from the file's (half into a half
// file goes straight to the encoder).
// The template's display/data windows and metadata are kept; channel names, formats and
// compression come from this call. A template without pixels (width or height 0, e.g. a
// default ImageSpec) means a data and display window of rgba's size at the origin, no metadata.
// A missing parent folder is created. Throws taa::Error naming `path` on any failure, leaving
// neither a file at `path` (an existing one stays untouched) nor a temporary file.
void writeExrAtomic(const std::string& path, const TypedImage& rgba,
                    const OIIO::ImageSpec& templateSpec, const WriteOptions& options,
                    const ExtraChannels& extra = {});
void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options, const ExtraChannels& extra = {});

}  // namespace taa::io
