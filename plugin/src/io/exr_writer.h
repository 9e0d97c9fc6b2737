// Writes resolved frames as EXR, atomically: into a temporary file in the target folder, then
// renamed over the final path, so no half-written file is ever left at the final path.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "util/image.h"

namespace taa::io {

enum class PixelType { Half, Float };

struct WriteOptions {
  PixelType pixelType = PixelType::Half;
  std::string compression = "zip";  // any OpenEXR compression OIIO knows: none, zip, piz, dwaa...
};

// Channels written after R, G, B, A (diagnostics, pass-through): one name per image channel.
struct ExtraChannels {
  std::vector<std::string> names;
  Image image;  // same size as the RGBA image; empty: none
};

// "half" | "float"; otherwise throws taa::Error.
PixelType parsePixelType(const std::string& text);

// Accepts the OpenEXR compressions none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab, and
// "name:level" for zip, zips, dwaa and dwab; otherwise throws taa::Error. Lets faces check the
// option before any frame is resolved.
void validateCompression(const std::string& compression);

// Writes `rgba` (4 channels, covering the template's data window) to `path` as R, G, B, A, then
// the extra channels if any.
// The template's display/data windows and metadata are kept; channel names, formats and
// compression come from this call. A template without pixels (width or height 0, e.g. a
// default ImageSpec) means a data and display window of rgba's size at the origin, no metadata.
// A missing parent folder is created. Throws taa::Error naming `path` on any failure, leaving
// neither a file at `path` (an existing one stays untouched) nor a temporary file.
void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options, const ExtraChannels& extra = {});

}  // namespace taa::io
