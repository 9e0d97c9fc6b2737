// Host buffers (taa_buffer: half or float, any strides, rows top or bottom first) to and from
// taa's internal images (interleaved, rows top first), with the input conventions of DESIGN.md
// section 3 applied on the way in exactly as io::readFrame applies them to files. Colour keeps
// the host's sample type, as io::readFrame keeps a file's, so half colour reaches the GPU without
// being widened on the CPU (the resolve samples the same values either way).
#pragma once

#include <OpenImageIO/typedesc.h>

#include <string>
#include <vector>

#include "io/aov_conversion.h"
#include "io/aov_layout.h"
#include "taa/taa.h"
#include "util/image.h"

namespace taa::capi {

// Each throws StatusError(TAA_ERROR_INVALID_ARGUMENT) naming `what` for a null or malformed
// buffer, a channel count it cannot take, or (width, height) different from `expectWidth`,
// `expectHeight` when those are positive.

// 3 or 4 channels -> RGBA (missing A = 1), NaN/Inf -> 0 (counted in *nonFinite if given);
// half for a half buffer, else float.
TypedImage importColor(const taa_buffer& buffer, int* nonFinite = nullptr);
// 1 channel -> planar depth per `convention` (io::convertDepth); radial depth along `ray`
// (io::radialToPlanar), refused without one.
Image importDepth(const taa_buffer& buffer, const io::DepthConvention& convention,
                  int expectWidth, int expectHeight, const io::PixelRay* ray = nullptr);
// 2 channels -> pixels, y down, to the previous frame, per `convention` (io::convertMotion,
// the buffer being the whole display window); NaN/Inf -> 0.
Image importMotion(const taa_buffer& buffer, const io::MotionConvention& convention,
                   int expectWidth, int expectHeight);

// Writes RGBA `image` into `buffer` (3 or 4 channels, the image's size); 3 drops alpha. Samples
// already of the buffer's type are copied, others converted (half widens exactly, float -> half
// rounds as Imath::half, beyond +-65504 clamps to it), so an output read back in the buffer's
// type passes through as is.
void exportColor(const TypedImage& image, const taa_buffer& buffer);

// One pass channel in a host buffer (taa_pass): channel `channel` of `buffer`.
struct PassChannel {
  const taa_buffer* buffer = nullptr;
  int channel = 0;
  std::string name;  // for errors
};

// The channels' values as float, one image channel each in order; `types` gets each one's
// host type (half or float).
Image importPasses(const std::vector<PassChannel>& channels, int width, int height,
                   std::vector<OIIO::TypeDesc>& types);

// Channel sources[i] of `image` into channels[i] (the image's size), each value converted as
// exportColor converts.
void exportPasses(const Image& image, const std::vector<int>& sources,
                  const std::vector<PassChannel>& channels);

}  // namespace taa::capi
