// The C ABI nodes of one effect instance, shared by its render threads under a bound. A node
// holds a GL context and, in window mode, a ring of 2K+1 frames (about 625 MB at 1080p, K = 4):
// one node per render thread, kept until PurgeCaches, grew with the host's thread count (16
// threads: ~10 GB). The pool holds at most `maxNodes`; a render takes the idle node that already
// holds most of its work (its ring of the neighbouring frames, its history), makes one while
// fewer exist, else waits for one to come back; EndSequenceRender frees all but one idle node.
// The OpenFX specification lets a fully thread-safe plugin serialise its own renders this way.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ofx/plugin_parameters.h"
#include "ofx/temporal_plan.h"
#include "taa/taa.h"

namespace taa::ofx {

// One node and what it holds, used by one render at a time.
struct NodeSlot {
  taa_node* node = nullptr;      // made by the render that needs it
  std::optional<int> lastFrame;  // history mode: frame whose result the node holds
  int startFrame = 0;            // history mode: the frame that history started from
  std::map<int, OfxRectI> ring;  // window mode: frames in the node's ring, their bounds
  FrameRange range;              // window mode: the Source clip's range they were pushed for
  std::optional<PluginSettings> settings;
  RenderScale scale;
  OfxRectI bounds{};             // of the resolved frame
  std::vector<std::string> passNames;  // window mode: the Pass clip's channels in the node

  NodeSlot() = default;
  ~NodeSlot();
  NodeSlot(const NodeSlot&) = delete;
  NodeSlot& operator=(const NodeSlot&) = delete;
  void forget();  // destroys the node and what it held
};

// The default bound: TAA_OFX_RENDER_NODES (1 to 64) when set, else 2.
std::size_t renderNodesFromEnvironment();

class NodePool {
 public:
  explicit NodePool(std::size_t maxNodes);
  NodePool(const NodePool&) = delete;
  NodePool& operator=(const NodePool&) = delete;

  // How much of a render's work an idle slot holds: the slot with the highest value is taken.
  using Score = std::function<int(const NodeSlot&)>;

  // A slot for one render, released when the returned handle goes: the best idle one, else a
  // new one while fewer than maxNodes exist, else the first one released. While waiting,
  // `aborted` is asked every 50 ms; true throws std::runtime_error.
  std::shared_ptr<NodeSlot> acquire(const Score& score, const std::function<bool()>& aborted);

  // Frees every idle slot's node; slots in use are freed when their render releases them.
  void purge();
  // Frees idle slots beyond the `keep` used last (the end of a sequence render).
  void trim(std::size_t keep);

  std::size_t maxNodes() const { return maxNodes_; }
  // Slots that exist (idle or in use) and the most that existed at once, for tests.
  std::size_t size() const;
  std::size_t peakSize() const;

 private:
  void release(NodeSlot* slot);

  mutable std::mutex mutex_;
  std::condition_variable released_;
  const std::size_t maxNodes_;
  std::vector<std::unique_ptr<NodeSlot>> idle_;  // the last released at the back
  std::vector<std::unique_ptr<NodeSlot>> busy_;
  std::vector<NodeSlot*> purgedWhileBusy_;
  std::size_t peak_ = 0;
};

}  // namespace taa::ofx
