// One effect instance. The output at frame t is, by definition, what taatool gives for t on the
// clip's frames (temporal_plan.h decides the frames). History mode: resolving the clip from its
// first frame (or, with History Frames = N > 0, from frame t - N + 1) up to t. Window mode:
// resolving t from frames t-K..t+K. Each render thread keeps its own C ABI node (its own GL
// context). History: the node holds the state after the last frame it rendered; when the host
// asks for t right after t - 1 on that thread with the same settings, only frame t is pushed,
// otherwise the node is reset and the plan's frames are pushed again. Window: the node's ring
// keeps the frames it holds between renders; a render drops those its window does not need and
// pushes those it lacks, so t right after t - 1 pushes one frame, and any order is exact. The
// frames-needed action asks the host for the plan's frames.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

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

  // Frees every thread's node (GL context, history textures); the next render of each thread
  // starts from its plan's first frame. Waits for renders in progress.
  void purgeCaches();

 private:
  struct ThreadHistory {
    std::mutex mutex;              // held by the render using it, and by purgeCaches
    taa_node* node = nullptr;
    std::optional<int> lastFrame;  // history mode: frame whose result the node holds
    int startFrame = 0;            // history mode: the frame that history started from
    std::map<int, OfxRectI> ring;  // window mode: frames in the node's ring, their bounds
    FrameRange range;              // window mode: the Source clip's range they were pushed for
    std::optional<PluginSettings> settings;
    RenderScale scale;
    OfxRectI bounds{};             // of the resolved frame
    ~ThreadHistory();
    void forget();  // destroys the node and what it held
  };

  FrameRange sourceRange(int frame) const;  // the Source clip's, [frame, frame] if unknown
  std::shared_ptr<ThreadHistory> historyOfThisThread();
  void renderHistory(ThreadHistory& history, const TemporalPlan& plan,
                     const PluginSettings& settings, RenderScale scale) const;
  void renderWindow(ThreadHistory& history, const TemporalPlan& plan, FrameRange range,
                    const PluginSettings& settings, RenderScale scale) const;
  // Fetches the frame's images, pushes them into the node and returns the Source's bounds.
  OfxRectI pushFrame(ThreadHistory& history, int frame, const PluginSettings& settings,
                     RenderScale scale) const;
  void writeOutput(const ThreadHistory& history, OfxTime time, const OfxRectI& window) const;

  OfxImageEffectHandle effect_;
  OfxImageClipHandle source_ = nullptr, depth_ = nullptr, motion_ = nullptr, output_ = nullptr;
  std::mutex historiesMutex_;
  std::map<std::thread::id, std::shared_ptr<ThreadHistory>> histories_;
};

}  // namespace taa::ofx
