#include "util/frame_buffer_pool.h"

#include "util/address_sanitizer.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <mutex>
#include <new>

namespace taa {
namespace {

// Buffers below this come from the ordinary heap: the pool is for frames, not for everything.
constexpr std::size_t kPooledBufferBytes = std::size_t(1) << 20;

// Enough for the buffers of the frames a pipelined run has in flight at 1080p (about 90 MB
// a frame in 4 buffers, 3 frames) and at 4K in part, and for a 1080p frame with every pass
// (about 20 buffers, 450 MB: FrameBuffersKeptFrameToFrame); the oldest go first.
constexpr std::size_t kMaxKeptBuffers = 32;
constexpr std::size_t kMaxKeptBytes = std::size_t(1) << 30;

// Frame buffers are mapped from a huge page's boundary (2 MiB on x86-64), and where the pool
// keeps none (FrameBuffersNotKept) the kernel is asked to back them with huge pages
// (transparent huge pages in their "madvise" mode, Debian's default): there every frame's
// buffers are new, every 4 KiB page of them faults on first touch, and a run with every pass of
// a render (about 400 MB read and as much written a frame) spent a third of its CPU time in
// those faults and their page clearing on a virtual machine; one fault a huge page instead of
// 512 took about a quarter off its time a frame. Kept buffers fault once, and huge pages made
// the runs that keep them slower (docs/PERFORMANCE.md, "Huge pages"). Where the kernel has
// none, or says no, the mapping stays as 4 KiB pages and works as before.
constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

std::size_t mappedBytes(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

// Under AddressSanitizer buffers stay on the heap, where it checks their bounds exactly.
#if TAA_ADDRESS_SANITIZER
void* mapFrameBuffer(std::size_t bytes, bool) { return ::operator new(bytes); }
void unmapFrameBuffer(void* buffer, std::size_t) { ::operator delete(buffer); }
#else
void* mapFrameBuffer(std::size_t bytes, bool hugePages) {
  const std::size_t length = mappedBytes(bytes);
  // Mapped a huge page longer, then trimmed so that it starts on a huge page's boundary.
  void* raw = mmap(nullptr, length + kHugePageBytes, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  if (aligned > start) munmap(raw, aligned - start);
  munmap(reinterpret_cast<void*>(aligned + length), start + kHugePageBytes - aligned);
  void* buffer = reinterpret_cast<void*>(aligned);
#ifdef MADV_HUGEPAGE
  if (hugePages) madvise(buffer, length, MADV_HUGEPAGE);  // a refusal changes only the speed
#endif
  return buffer;
}

void unmapFrameBuffer(void* buffer, std::size_t bytes) { munmap(buffer, mappedBytes(bytes)); }
#endif

struct KeptBuffer {
  void* buffer;
  std::size_t bytes;
  std::uint64_t givenBack;  // the pool's count of buffers given back when this one was
};

thread_local int freedAtOnce = 0;  // FrameBuffersFreedAtOnce alive on this thread

class Pool {
 public:
  void* take(std::size_t bytes) {
    bool hugePages;
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
      hugePages = !keeps();  // it will not be kept
    }
    return mapFrameBuffer(bytes, hugePages);
  }

  void giveBack(void* buffer, std::size_t bytes) {
    if (freedAtOnce > 0) {
      unmapFrameBuffer(buffer, bytes);
      return;
    }
    std::deque<KeptBuffer> evicted;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      kept_.push_back({buffer, bytes, ++givenBack_});
      keptBytes_ += bytes;
      const std::size_t maxBytes = keeps() ? kMaxKeptBytes : 0;
      while (kept_.size() > kMaxKeptBuffers || keptBytes_ > maxBytes) {
        evicted.push_back(kept_.front());
        keptBytes_ -= kept_.front().bytes;
        kept_.pop_front();
      }
    }
    for (const KeptBuffer& k : evicted) unmapFrameBuffer(k.buffer, k.bytes);
  }

  void release() {
    std::deque<KeptBuffer> all;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      all.swap(kept_);
      keptBytes_ = 0;
    }
    for (const KeptBuffer& k : all) unmapFrameBuffer(k.buffer, k.bytes);
  }

  std::size_t keptBytes() {
    std::lock_guard<std::mutex> lock(mutex_);
    return keptBytes_;
  }

  void keepNone(bool on) { count(notKept_, on); }
  void keepFrameToFrame(bool on) { count(keptFrameToFrame_, on); }

  // Frees the buffers given back up to `mark` (a count of givenBack_) and not taken since;
  // returns the count now.
  std::uint64_t releaseGivenBackBefore(std::uint64_t mark) {
    std::deque<KeptBuffer> idle;
    std::uint64_t now;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = kept_.begin(); it != kept_.end();) {
        if (it->givenBack <= mark) {
          idle.push_back(*it);
          keptBytes_ -= it->bytes;
          it = kept_.erase(it);
        } else {
          ++it;
        }
      }
      now = givenBack_;
    }
    for (const KeptBuffer& k : idle) unmapFrameBuffer(k.buffer, k.bytes);
    return now;
  }

  std::uint64_t givenBack() {
    std::lock_guard<std::mutex> lock(mutex_);
    return givenBack_;
  }

  ~Pool() { release(); }

 private:
  std::mutex mutex_;
  std::deque<KeptBuffer> kept_;  // oldest first
  std::size_t keptBytes_ = 0;
  int notKept_ = 0;           // FrameBuffersNotKept alive
  int keptFrameToFrame_ = 0;  // FrameBuffersKeptFrameToFrame alive
  std::uint64_t givenBack_ = 0;

  bool keeps() const { return notKept_ == 0 || keptFrameToFrame_ > 0; }

  // One of the policies' guards made or gone; where the pool now keeps none, what it kept goes.
  void count(int& guards, bool on) {
    bool releasing;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      guards += on ? 1 : -1;
      releasing = !keeps();
    }
    if (releasing) release();
  }
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

FrameBuffersKeptFrameToFrame::FrameBuffersKeptFrameToFrame() : mark_(pool().givenBack()) {
  pool().keepFrameToFrame(true);
}
FrameBuffersKeptFrameToFrame::~FrameBuffersKeptFrameToFrame() { pool().keepFrameToFrame(false); }
void FrameBuffersKeptFrameToFrame::nextFrame() { mark_ = pool().releaseGivenBackBefore(mark_); }

FrameBuffersFreedAtOnce::FrameBuffersFreedAtOnce() { ++freedAtOnce; }
FrameBuffersFreedAtOnce::~FrameBuffersFreedAtOnce() { --freedAtOnce; }

FrameBuffersNotKept::FrameBuffersNotKept() { pool().keepNone(true); }
FrameBuffersNotKept::~FrameBuffersNotKept() { pool().keepNone(false); }

}  // namespace taa
