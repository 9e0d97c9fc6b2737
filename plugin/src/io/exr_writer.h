// Writes resolved frames as EXR, atomically: into a temporary file in the target folder, then
// renamed over the final path, so no half-written file is ever left at the final path.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

#include "util/image.h"

namespace taa::io {

enum class PixelType { Half, Float };

struct WriteOptions {
  PixelType pixelType = PixelType::Half;
  std::string compression = "zip";  // any OpenEXR compression OIIO knows: none, zip, piz, dwaa...
};

// "half" | "float"; otherwise throws taa::Error.
PixelType parsePixelType(const std::string& text);

// Writes `rgba` (4 channels, covering the template's data window) to `path` as R, G, B, A.
// The template's display/data windows and metadata are kept; channel names, formats and
// compression come from this call.
void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options);

}  // namespace taa::io
