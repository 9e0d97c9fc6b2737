// Writes resolved frames as EXR, atomically: into a temporary file in the target folder, then
// renamed over the final path, so no half-written file is ever left at the final path.
#pragma once

#include <OpenImageIO/imageio.h>

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
  std::string compression = "zip";  // any OpenEXR compression OIIO knows: none, zip, piz, dwaa...
  std::vector<std::string> rgbaNames;  // the 4 color channels' names; empty: R, G, B, A
};

// Channels written after R, G, B, A (diagnostics, pass-through): one name per image channel.
struct ExtraChannels {
  std::vector<std::string> names;
  Image image;  // same size as the RGBA image; empty: none
  std::vector<OIIO::TypeDesc> formats;  // per name (pass-through keeps its type); empty: the
                                        // color's pixel type
};

// Appends `more`'s channels after `extra`'s (same image size, or `extra` empty).
void appendExtraChannels(ExtraChannels& extra, const ExtraChannels& more);

// "half" | "float" | "input"; otherwise throws taa::Error.
PixelType parsePixelType(const std::string& text);

// Accepts the OpenEXR compressions none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab, and
// "name:level" for zip, zips, dwaa and dwab; otherwise throws taa::Error. Lets faces check the
// option before any frame is resolved.
void validateCompression(const std::string& compression);

// Writes `rgba` (4 channels, covering the template's data window) to `path` as R, G, B, A (or
// options.rgbaNames), then the extra channels if any. Channel names must be unique.
// The template's display/data windows and metadata are kept; channel names, formats and
// compression come from this call. A template without pixels (width or height 0, e.g. a
// default ImageSpec) means a data and display window of rgba's size at the origin, no metadata.
// A missing parent folder is created. Throws taa::Error naming `path` on any failure, leaving
// neither a file at `path` (an existing one stays untouched) nor a temporary file.
void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options, const ExtraChannels& extra = {});

}  // namespace taa::io
