#include "util/frame_buffer_pool.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <new>

namespace taa {
namespace {

// Buffers below this come from the ordinary heap: the pool is for frames, not for everything.
constexpr std::size_t kPooledBufferBytes = std::size_t(1) << 20;

// Enough for the buffers of the frames a pipelined run has in flight at 1080p (about 90 MB
// a frame in 4 buffers, 3 frames) and at 4K in part; the oldest go first.
constexpr std::size_t kMaxKeptBuffers = 16;
constexpr std::size_t kMaxKeptBytes = std::size_t(1) << 30;

struct KeptBuffer {
  void* buffer;
  std::size_t bytes;
};

class Pool {
 public:
  void* take(std::size_t bytes) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto same = std::find_if(kept_.rbegin(), kept_.rend(),
                               [bytes](const KeptBuffer& k) { return k.bytes == bytes; });
      if (same != kept_.rend()) {
        void* buffer = same->buffer;
        keptBytes_ -= bytes;
        kept_.erase(std::next(same).base());
        return buffer;
      }
    }
    return ::operator new(bytes);
  }

  void giveBack(void* buffer, std::size_t bytes) {
    std::deque<KeptBuffer> evicted;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      kept_.push_back({buffer, bytes});
      keptBytes_ += bytes;
      const std::size_t maxBytes = notKept_ > 0 ? 0 : kMaxKeptBytes;
      while (kept_.size() > kMaxKeptBuffers || keptBytes_ > maxBytes) {
        evicted.push_back(kept_.front());
        keptBytes_ -= kept_.front().bytes;
        kept_.pop_front();
      }
    }
    for (const KeptBuffer& k : evicted) ::operator delete(k.buffer);
  }

  void release() {
    std::deque<KeptBuffer> all;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      all.swap(kept_);
      keptBytes_ = 0;
    }
    for (const KeptBuffer& k : all) ::operator delete(k.buffer);
  }

  std::size_t keptBytes() {
    std::lock_guard<std::mutex> lock(mutex_);
    return keptBytes_;
  }

  void keepNone(bool on) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      notKept_ += on ? 1 : -1;
    }
    if (on) release();
  }

  ~Pool() { release(); }

 private:
  std::mutex mutex_;
  std::deque<KeptBuffer> kept_;  // oldest first
  std::size_t keptBytes_ = 0;
  int notKept_ = 0;  // FrameBuffersNotKept alive
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

void* takeFrameBuffer(std::size_t bytes) {
  if (bytes < kPooledBufferBytes) return ::operator new(bytes);
  return pool().take(bytes);
}

void giveBackFrameBuffer(void* buffer, std::size_t bytes) {
  if (bytes < kPooledBufferBytes) {
    ::operator delete(buffer);
    return;
  }
  pool().giveBack(buffer, bytes);
}

void releaseFrameBuffers() { pool().release(); }

std::size_t keptFrameBufferBytes() { return pool().keptBytes(); }

FrameBuffersNotKept::FrameBuffersNotKept() { pool().keepNone(true); }
FrameBuffersNotKept::~FrameBuffersNotKept() { pool().keepNone(false); }

}  // namespace taa
