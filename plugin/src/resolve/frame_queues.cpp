#include "resolve/frame_queues.h"

#include <algorithm>
#include <chrono>

namespace taa {
namespace {

std::launch policyFor(int depth) {
  return depth > 0 ? std::launch::async : std::launch::deferred;
}

// Waits for every future left (a failure elsewhere must not leave threads touching freed
// state), swallowing their errors: the first error is already on its way out.
template <typename R>
void settle(std::future<R>& future) {
  // A deferred task has not started; waiting on it would run it.
  if (future.valid() && future.wait_for(std::chrono::seconds(0)) != std::future_status::deferred) {
    future.wait();
  }
}

void drain(std::deque<std::future<io::FrameData>>& pending) {
  for (auto& future : pending) settle(future);
}

void drain(std::deque<std::pair<std::future<void>, int>>& pending) {
  for (auto& [future, index] : pending) settle(future);
}

}  // namespace

ReadAhead::ReadAhead(std::vector<int> frames, int depth, Read read)
    : frames_(std::move(frames)), depth_(std::max(0, depth)), read_(std::move(read)) {}

ReadAhead::~ReadAhead() { drain(pending_); }

void ReadAhead::fill() {
  while (started_ < frames_.size() && started_ <= taken_ + std::size_t(depth_)) {
    const int frame = frames_[started_++];
    const bool callerWaits = depth_ == 0;
    pending_.push_back(std::async(policyFor(depth_),
                                  [this, frame, callerWaits] { return read_(frame, callerWaits); }));
  }
}

io::FrameData ReadAhead::next() {
  fill();
  std::future<io::FrameData> front = std::move(pending_.front());
  pending_.pop_front();
  ++taken_;
  fill();
  return front.get();
}

void ReadAhead::setDepth(int depth) { depth_ = std::max(0, depth); }

WriteBehind::WriteBehind(int depth, std::function<void(int)> done)
    : depth_(std::max(0, depth)), done_(std::move(done)) {}

WriteBehind::~WriteBehind() { drain(pending_); }

void WriteBehind::push(std::function<void()> write, int index) {
  pending_.emplace_back(std::async(policyFor(depth_), std::move(write)), index);
  while (int(pending_.size()) > depth_) finishOldest();
  // Writes already done are reported now, not when the queue next fills: a farm's PROGRESS
  // line then trails its rename by at most the frame being resolved (issue 25).
  while (!pending_.empty() &&
         pending_.front().first.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    finishOldest();
  }
}

void WriteBehind::setDepth(int depth) { depth_ = std::max(0, depth); }

void WriteBehind::finishOldest() {
  auto [future, index] = std::move(pending_.front());
  pending_.pop_front();
  future.get();
  if (done_) done_(index);
}

void WriteBehind::finish() {
  while (!pending_.empty()) finishOldest();
}

}  // namespace taa
