// kOfxActionDescribe and kOfxImageEffectActionDescribeInContext: what the plugin declares.
#pragma once

#include "ofx/ofx_abi.h"

namespace taa::ofx {

// Clip names. Source and Output are the standard filter clips.
constexpr const char* kDepthClip = "Depth";
constexpr const char* kMotionClip = "Motion";
// Optional: another pass resolved with the Source's weights, and a light pass's colour
// (ofx/pass_clip.h).
constexpr const char* kPassClip = "Pass";
constexpr const char* kPassFactorClip = "PassFactor";

OfxStatus describe(OfxImageEffectHandle descriptor);
OfxStatus describeInContext(OfxImageEffectHandle descriptor);

}  // namespace taa::ofx
