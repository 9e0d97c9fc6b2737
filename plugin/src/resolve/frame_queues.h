// The frame pipeline's two queues: frames read ahead and written behind on worker threads
// while the GL thread resolves (DESIGN.md section 4, "sequence orchestration"). Both keep
// order, so the output cannot depend on timing; both are bounded, so memory does not grow
// with the sequence. With depth 0 the same code runs on the calling thread, step by step.
#pragma once

#include <deque>
#include <functional>
#include <future>
#include <vector>

#include "io/frame_reader.h"

namespace taa {

class ReadAhead {
 public:
  // Reads `frames` in order with `read`, up to `depth` frames ahead of the one taken last.
  // `read` is told whether the caller waits for it (depth 0: the read runs on the calling
  // thread while nothing else does, so it may use every core).
  using Read = std::function<io::FrameData(int frame, bool callerWaits)>;
  ReadAhead(std::vector<int> frames, int depth, Read read);
  ~ReadAhead();
  ReadAhead(const ReadAhead&) = delete;
  ReadAhead& operator=(const ReadAhead&) = delete;

  bool done() const { return taken_ >= frames_.size(); }
  // The frame `next()` will return.
  int peek() const { return frames_[taken_]; }
  // The next frame in order; a failed read throws here, when its turn comes.
  io::FrameData next();
  // Reads started from now on go up to `depth` ahead.
  void setDepth(int depth);

 private:
  void fill();
  std::vector<int> frames_;
  std::size_t taken_ = 0, started_ = 0;
  int depth_;
  Read read_;
  std::deque<std::future<io::FrameData>> pending_;
};

class WriteBehind {
 public:
  // Up to `depth` writes run while more frames are resolved; `done` is called after each
  // write, in order, on the calling thread: at the latest when the next frame is pushed.
  WriteBehind(int depth, std::function<void(int index)> done);
  ~WriteBehind();
  WriteBehind(const WriteBehind&) = delete;
  WriteBehind& operator=(const WriteBehind&) = delete;

  void push(std::function<void()> write, int index);
  // Writes pushed from now on: up to `depth` running.
  void setDepth(int depth);
  // Waits for every write; the first failure throws.
  void finish();

 private:
  void finishOldest();
  int depth_;
  std::function<void(int)> done_;
  std::deque<std::pair<std::future<void>, int>> pending_;
};

}  // namespace taa
