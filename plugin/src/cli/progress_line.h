// taatool's progress (issue 24: a 24-frame run printed nothing until it ended): frames done of
// the total, frames per second and the time left. On a terminal one line on stderr, rewritten
// in place after each frame; elsewhere (a log file, a pipe) one plain line per frame. taa-farm
// keeps its own PROGRESS: lines, which farm managers parse.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace taa::cli {

// "12/24 frames, 1.85 frames/s, 0:06 left" after `done` of `total` frames in `elapsed`
// seconds: the rate over the whole run so far, the time left at that rate (m:ss, or h:mm:ss
// from an hour). Before the first frame is done: "0/24 frames".
std::string progressText(int done, int total, double elapsedSeconds);

class ProgressLine {
 public:
  // `terminal`: rewrite one line in place ('\r', then erase to the end of the line); else
  // write a line per frame. The clock starts now.
  ProgressLine(std::ostream& out, bool terminal);
  // Ends a line left open on a terminal, so that what follows (an error) starts a line.
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // After frame `frame`, the `done`-th of `total`, is written.
  void frameDone(int frame, int done, int total);
  // "6/24, 1.85 frames/s, 0:10 left" now (for -v's per-frame lines).
  std::string textNow(int done, int total) const;
  // Ends the line on a terminal; later calls of frameDone start a new one.
  void finish();

 private:
  std::string elapsedText(int done, int total) const;

  std::ostream& out_;
  bool terminal_;
  bool lineOpen_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace taa::cli
