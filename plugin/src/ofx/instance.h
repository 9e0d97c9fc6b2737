// One effect instance. History: the output at frame t is, by definition, what taatool gives for
// t when resolving the clip from its first frame (or, with History Frames = N > 0, from frame
// t - N + 1) up to t. Each render thread keeps its own C ABI node (its own GL context) with the
// state after the last frame it rendered; when the host asks for t right after t - 1 on that
// thread with the same settings, only frame t is pushed, otherwise the node is reset and
// frames start..t are pushed again (the frames-needed action asks the host for them).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "ofx/ofx_abi.h"
#include "ofx/plugin_parameters.h"
#include "taa/taa.h"

namespace taa::ofx {

class Instance {
 public:
  explicit Instance(OfxImageEffectHandle effect);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  // The frames frame `time` is resolved from: [first, time].
  OfxRangeD framesNeeded(OfxTime time) const;

  // Renders `window` of the output at `time`. Throws std::runtime_error on failure.
  void render(OfxTime time, const OfxRectI& window, double renderScaleX);

 private:
  struct ThreadHistory {
    taa_node* node = nullptr;
    std::optional<int> lastFrame;  // frame whose result the node holds
    int startFrame = 0;            // the frame that history started from
    std::optional<PluginSettings> settings;
    double renderScale = 1.0;
    OfxRectI bounds{};
  };

  int firstFrame(int frame, const PluginSettings& settings) const;
  ThreadHistory& historyOfThisThread();
  void pushFrame(ThreadHistory& history, int frame) const;
  void writeOutput(ThreadHistory& history, OfxTime time, const OfxRectI& window) const;

  OfxImageEffectHandle effect_;
  OfxImageClipHandle source_ = nullptr, depth_ = nullptr, motion_ = nullptr, output_ = nullptr;
  std::mutex historiesMutex_;
  std::map<std::thread::id, std::unique_ptr<ThreadHistory>> histories_;
};

}  // namespace taa::ofx
