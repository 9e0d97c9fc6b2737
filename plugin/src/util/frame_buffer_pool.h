// Frame-sized buffers kept for the next frame (docs/PERFORMANCE.md, "Page faults").
// A sequence allocates and frees the same few buffers of tens of MB for every frame (a frame's
// AOVs as read, the resolved frame as read back). Served fresh each time, every 4 KiB page of
// them faults on first touch: about 30,000 faults a 1080p frame, which cost more than a third
// of the history mode's wall time on a virtual machine where faults are slow. The pool keeps
// a few freed buffers and hands them back to a request of the same size, so a long run
// touches its pages once; it stays bounded, so memory stays flat.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace taa {

void* takeFrameBuffer(std::size_t bytes);
void giveBackFrameBuffer(void* buffer, std::size_t bytes);

// Frees what the pool keeps (the end of a job, a node's destruction): a host gets its memory
// back once taa is done.
void releaseFrameBuffers();

// Bytes the pool keeps now (freed, not yet handed out again).
std::size_t keptFrameBufferBytes();

// While one lives, the pool keeps no freed buffer (those it keeps are freed at once): for a run
// whose peak memory is its bar, where idle buffers cost more than their page faults (a window
// resolve with every pass: docs/PERFORMANCE.md, "Every pass and the pool"). Nested ones count.
class FrameBuffersNotKept {
 public:
  FrameBuffersNotKept();
  ~FrameBuffersNotKept();
  FrameBuffersNotKept(const FrameBuffersNotKept&) = delete;
  FrameBuffersNotKept& operator=(const FrameBuffersNotKept&) = delete;
};

// For a run whose peak memory is its bar and whose frames take the same buffers each (a window
// resolve with every pass in taatool: docs/PERFORMANCE.md, "Every pass reusing its buffers"):
// while one lives the pool keeps freed buffers even where a FrameBuffersNotKept says none,
// so each frame's reuse the last's pages instead of faulting new ones in; nextFrame(), called
// once a frame, frees those kept through a whole frame without being taken (what the frames no
// longer need, such as the buffers of a window's lead-in frames), so idle buffers stay few.
class FrameBuffersKeptFrameToFrame {
 public:
  FrameBuffersKeptFrameToFrame();
  ~FrameBuffersKeptFrameToFrame();
  FrameBuffersKeptFrameToFrame(const FrameBuffersKeptFrameToFrame&) = delete;
  FrameBuffersKeptFrameToFrame& operator=(const FrameBuffersKeptFrameToFrame&) = delete;
  void nextFrame();

 private:
  std::uint64_t mark_;  // the pool's count of buffers given back at the last nextFrame()
};

// While one lives, the buffers its thread frees are unmapped at once, not kept: for buffers
// freed to make room at a run's peak (resolve/pass_band_stream's idle bands).
class FrameBuffersFreedAtOnce {
 public:
  FrameBuffersFreedAtOnce();
  ~FrameBuffersFreedAtOnce();
  FrameBuffersFreedAtOnce(const FrameBuffersFreedAtOnce&) = delete;
  FrameBuffersFreedAtOnce& operator=(const FrameBuffersFreedAtOnce&) = delete;
};

// The pool as a standard allocator, for the vectors that hold frames (util/image.h).
template <typename T>
struct FrameBufferAllocator {
  using value_type = T;
  FrameBufferAllocator() = default;
  template <typename U>
  FrameBufferAllocator(const FrameBufferAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(takeFrameBuffer(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) { giveBackFrameBuffer(p, n * sizeof(T)); }
  template <typename U>
  bool operator==(const FrameBufferAllocator<U>&) const { return true; }
  template <typename U>
  bool operator!=(const FrameBufferAllocator<U>&) const { return false; }
};

// A frame's samples, or any buffer of a frame's size: kept for the next frame when freed.
template <typename T>
using FrameVector = std::vector<T, FrameBufferAllocator<T>>;

}  // namespace taa
