// Which source frames an output frame is made from, and what that means for the order a host
// may render in. One place decides both from the settings, so a new resolve mode (the window
// mode of DESIGN.md section 4: frames t-K..t+K, any order) adds one branch here.
#pragma once

#include "ofx/plugin_parameters.h"

namespace taa::ofx {

// Frames a clip has images for, inclusive (kOfxImageEffectPropFrameRange, rounded).
struct FrameRange {
  int first = 0;
  int last = 0;
};

struct TemporalPlan {
  // The frames pushed into the node, in order: [first, last]. Always inside the source clip's
  // range; `last` is the requested frame, held at the clip's first or last frame when the host
  // asks for a time outside it (as hosts hold a clip's end frames).
  FrameRange frames;
  // kOfxImageEffectInstancePropSequentialRender for these settings: 1 when a frame needs every
  // frame before it (out-of-order renders are exact but cost the whole history), 2 when the
  // history is bounded (any order is exact and costs at most History Frames pushes).
  int sequentialRender = 1;
};

// The plan for output frame `frame` of a source clip with images over `source`.
TemporalPlan planFrame(int frame, const PluginSettings& settings, FrameRange source);

// The SequentialRender value alone (it does not depend on the frame).
int sequentialRender(const PluginSettings& settings);

}  // namespace taa::ofx
