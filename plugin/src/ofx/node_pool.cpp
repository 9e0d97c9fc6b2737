#include "ofx/node_pool.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace taa::ofx {

NodeSlot::~NodeSlot() { forget(); }

void NodeSlot::forget() {
  if (node) taa_node_destroy(node);
  node = nullptr;
  lastFrame.reset();
  ring.clear();
  settings.reset();
}

std::size_t renderNodesFromEnvironment() {
  constexpr std::size_t kDefault = 2, kMost = 64;
  const char* text = std::getenv("TAA_OFX_RENDER_NODES");
  if (!text || !*text) return kDefault;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 1 || value > long(kMost)) return kDefault;
  return std::size_t(value);
}

NodePool::NodePool(std::size_t maxNodes) : maxNodes_(std::max<std::size_t>(1, maxNodes)) {}

std::shared_ptr<NodeSlot> NodePool::acquire(const Score& score,
                                            const std::function<bool()>& aborted) {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (!idle_.empty()) {
      // The best scored, the most recently released among equals.
      std::size_t best = idle_.size() - 1;
      int bestScore = score(*idle_[best]);
      for (std::size_t i = idle_.size() - 1; i-- > 0;) {
        const int s = score(*idle_[i]);
        if (s > bestScore) {
          best = i;
          bestScore = s;
        }
      }
      busy_.push_back(std::move(idle_[best]));
      idle_.erase(idle_.begin() + std::ptrdiff_t(best));
      break;
    }
    if (busy_.size() < maxNodes_) {
      busy_.push_back(std::make_unique<NodeSlot>());
      peak_ = std::max(peak_, busy_.size());
      break;
    }
    released_.wait_for(lock, std::chrono::milliseconds(50));
    if (idle_.empty() && busy_.size() >= maxNodes_ && aborted && aborted()) {
      throw std::runtime_error("render aborted by host while waiting for one of the " +
                               std::to_string(maxNodes_) +
                               " render nodes (TAA_OFX_RENDER_NODES) to be free");
    }
  }
  NodeSlot* slot = busy_.back().get();
  return std::shared_ptr<NodeSlot>(slot, [this](NodeSlot* s) { release(s); });
}

void NodePool::release(NodeSlot* slot) {
  std::unique_ptr<NodeSlot> owned;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = std::find_if(busy_.begin(), busy_.end(),
                                 [slot](const auto& s) { return s.get() == slot; });
    if (it == busy_.end()) return;
    owned = std::move(*it);
    busy_.erase(it);
    const auto purged = std::find(purgedWhileBusy_.begin(), purgedWhileBusy_.end(), slot);
    if (purged != purgedWhileBusy_.end()) {
      purgedWhileBusy_.erase(purged);
      owned->forget();
    }
    idle_.push_back(std::move(owned));
  }
  released_.notify_one();
}

void NodePool::purge() {
  std::vector<std::unique_ptr<NodeSlot>> freed;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    freed.swap(idle_);
    for (const auto& slot : busy_) purgedWhileBusy_.push_back(slot.get());
  }
  freed.clear();  // nodes destroyed outside the lock: it may take a while
}

void NodePool::trim(std::size_t keep) {
  std::vector<std::unique_ptr<NodeSlot>> freed;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    while (idle_.size() > keep) {
      freed.push_back(std::move(idle_.front()));
      idle_.erase(idle_.begin());
    }
  }
}

std::size_t NodePool::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return idle_.size() + busy_.size();
}

std::size_t NodePool::peakSize() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return peak_;
}

}  // namespace taa::ofx
