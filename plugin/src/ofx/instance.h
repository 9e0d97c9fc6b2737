// One effect instance. The output at frame t is, by definition, what taatool gives for t on the
// clip's frames (temporal_plan.h decides the frames). History mode: resolving the clip from its
// first frame (or, with History Frames = N > 0, from frame t - N + 1) up to t. Window mode:
// resolving t from frames t-K..t+K. Renders share the instance's C ABI nodes (each with its own
// GL context), at most TAA_OFX_RENDER_NODES of them (ofx/node_pool.h): a render takes the idle
// node that holds most of its work. History: the node holds the state after the last frame it
// rendered; when t follows t - 1 with the same settings, only frame t is pushed, otherwise the
// node is reset and the plan's frames are pushed again. Window: the node's ring keeps the
// frames it holds between renders; a render drops those its window does not need and pushes
// those it lacks, so t right after t - 1 pushes one frame, and any order is exact. The
// frames-needed action asks the host for the plan's frames. With the Pass clip connected (window
// mode) the output is that pass resolved with the Source's weights (ofx/pass_clip.h).
#pragma once

#include <cstddef>

#include "ofx/node_pool.h"
#include "ofx/ofx_abi.h"
#include "ofx/plugin_parameters.h"
#include "ofx/temporal_plan.h"
#include "taa/taa.h"

namespace taa::ofx {

class Instance {
 public:
  explicit Instance(OfxImageEffectHandle effect);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  // The plan for output frame `time` with the parameters' values at that time.
  TemporalPlan plan(OfxTime time) const;

  // Renders `window` of the output at `time`. Throws std::runtime_error on failure.
  void render(OfxTime time, const OfxRectI& window, RenderScale scale);

  // Frees every node (GL context, history textures, ring); the next render starts from its
  // plan's first frame. Renders in progress keep theirs until they end.
  void purgeCaches();
  // The end of a sequence render: frees the idle nodes but the one used last.
  void endSequence();
  // Nodes that exist now and the most that existed at once (tests).
  std::size_t nodes() const { return pool_.size(); }
  std::size_t peakNodes() const { return pool_.peakSize(); }

 private:
  FrameRange sourceRange(int frame) const;  // the Source clip's, [frame, frame] if unknown
  void renderHistory(NodeSlot& history, const TemporalPlan& plan, const PluginSettings& settings,
                     RenderScale scale) const;
  void renderWindow(NodeSlot& history, const TemporalPlan& plan, FrameRange range,
                    const PluginSettings& settings, RenderScale scale) const;
  // The parameters at `time` and the Pass clips' connections.
  PluginSettings settingsAt(OfxTime time) const;
  // Fetches the frame's images (the Pass clips' too when connected), pushes them into the node
  // and returns the Source's bounds.
  OfxRectI pushFrame(NodeSlot& history, int frame, const PluginSettings& settings,
                     RenderScale scale) const;
  void writeOutput(const NodeSlot& history, OfxTime time, const OfxRectI& window) const;

  OfxImageEffectHandle effect_;
  OfxImageClipHandle source_ = nullptr, depth_ = nullptr, motion_ = nullptr, output_ = nullptr;
  OfxImageClipHandle pass_ = nullptr, passFactor_ = nullptr;
  NodePool pool_;
};

}  // namespace taa::ofx
