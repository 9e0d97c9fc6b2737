// kOfxImageEffectActionGetClipPreferences: how the host is to map the clips before taa sees
// them, and what the output is.
#pragma once

#include "ofx/ofx_abi.h"

namespace taa::ofx {

// - Output: RGBA, premultiplied, frame varying (the resolve of frame t differs from frame t-1
//   even where the source does not change: the jitter moves and history accumulates).
// - Depth: the components connected to it, so a one-channel (Alpha) depth stays one channel
//   instead of becoming RGBA with depth in A.
// - Motion: the components connected to it (vectors in R and G).
// Pixel aspect ratios are the host's to conform (SupportsMultipleClipPARs is 0).
OfxStatus clipPreferences(OfxImageEffectHandle effect, OfxPropertySetHandle outArgs);

}  // namespace taa::ofx
