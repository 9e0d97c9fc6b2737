#include "resolve/pass_band_stream.h"

#include <string>

#include "taa/error.h"
#include "util/frame_buffer_pool.h"

namespace taa {

PassBandStream::PassBandStream(int buffers) : buffers_(buffers < 1 ? 1 : buffers) {}

PassSums PassBandStream::take() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !free_.empty() || made_ < buffers_; });
  if (free_.empty()) {
    ++made_;
    return {};
  }
  PassSums sums = std::move(free_.back());
  free_.pop_back();
  return sums;
}

void PassBandStream::publish(int frame, int firstRow, int rows, PassSums sums) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finishedThrough_ && frame <= *finishedThrough_) {
      free_.push_back(std::move(sums));  // its write has ended: nothing will read it
    } else {
      published_.push_back({frame, firstRow, rows, std::move(sums)});
    }
  }
  changed_.notify_all();
}

void PassBandStream::abandon(int frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = frame;
  }
  changed_.notify_all();
}

template <typename Done>
void PassBandStream::recycle(Done done) {
  for (auto it = published_.begin(); it != published_.end();) {
    if (done(*it)) {
      free_.push_back(std::move(it->sums));
      it = published_.erase(it);
    } else {
      ++it;
    }
  }
}

const PassBandStream::Band& PassBandStream::band(int frame, int row) {
  std::unique_lock<std::mutex> lock(mutex_);
  recycle([&](const Band& b) { return b.frame == frame && b.firstRow + b.rows <= row; });
  changed_.notify_all();
  const Band* found = nullptr;
  bool later = false;  // a band of the frame past `row` with none holding it: asked out of order
  changed_.wait(lock, [&] {
    found = nullptr;
    later = false;
    for (const Band& b : published_) {
      if (b.frame != frame) continue;
      if (row >= b.firstRow && row < b.firstRow + b.rows) found = &b;
      later = later || b.firstRow > row;
    }
    return found || later || (abandoned_ && *abandoned_ >= frame);
  });
  if (found) return *found;
  if (later) {
    throw Error("pass rows asked out of order: row " + std::to_string(row) + " of frame " +
                std::to_string(frame) + " after the band holding it went back");
  }
  throw Error("the frame's passes were not resolved: its resolve failed while it was written");
}

void PassBandStream::finished(int frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finishedThrough_ = frame;
    recycle([&](const Band& b) { return b.frame <= frame; });
  }
  changed_.notify_all();
}

void PassBandStream::releaseIdle() {
  std::lock_guard<std::mutex> lock(mutex_);
  const FrameBuffersFreedAtOnce freedAtOnce;  // not kept in the pool: the room is for the read
  made_ -= int(free_.size());
  free_.clear();
}

}  // namespace taa
