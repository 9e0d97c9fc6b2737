// Which source frames an output frame is made from, and what that means for the order a host
// may render in. One place decides both from the settings: history mode (frame t from the clip
// start, or the last History Frames) and window mode (frames t-K..t+K, any order).
#pragma once

#include "ofx/plugin_parameters.h"

namespace taa::ofx {

// Frames a clip has images for, inclusive (kOfxImageEffectPropFrameRange, rounded).
struct FrameRange {
  int first = 0;
  int last = 0;
  bool operator==(const FrameRange& o) const { return first == o.first && last == o.last; }
};

struct TemporalPlan {
  // The frame resolved: the requested one, held at the clip's first or last frame when the
  // host asks for a time outside the clip (as hosts hold a clip's end frames).
  int frame = 0;
  // The source frames it is made from (the frames-needed action's range), inside the clip:
  // history [first, frame], pushed in order; window [frame - K, frame + K], in any order.
  FrameRange frames;
  // kOfxImageEffectInstancePropSequentialRender for these settings: 1 when a frame needs every
  // frame before it (out-of-order renders are exact but cost the whole history), 2 when the
  // history is bounded (any order is exact and costs at most History Frames pushes), 0 in
  // window mode (frames are independent: any order, at most 2K+1 pushes, one in order).
  int sequentialRender = 1;
};

// The plan for output frame `frame` of a source clip with images over `source`.
TemporalPlan planFrame(int frame, const PluginSettings& settings, FrameRange source);

// The SequentialRender value alone (it does not depend on the frame).
int sequentialRender(const PluginSettings& settings);

}  // namespace taa::ofx
