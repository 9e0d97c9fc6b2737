// How many rows the reader decodes and the writer encodes at a time.
#pragma once

#include <OpenImageIO/imageio.h>

namespace taa::io {

// Rows a band of `spec`'s file holds: a whole number of its chunks (tiles, or a codec's
// scanline blocks), so no chunk is coded twice; at least two chunks of ZIP's 16 rows, so
// OpenEXR codes two at once on two cores; and few enough that a band stays small beside a
// frame with every pass: 32 rows (a multiple of every scanline codec's chunk height but
// DWAB's 256).
int rowsPerBand(const OIIO::ImageSpec& spec);

}  // namespace taa::io
