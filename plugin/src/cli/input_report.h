// What changed a result without failing the run (issue 17's policy), for taatool and Python's
// resolve_sequence: NaN/Inf colour or motion set to 0, float colour clamped to a half output's
// range, a change of image size (history restarts), frames skipped with --skip-missing, the
// jitter taken out of a projection that carried it. Each is tallied for a warning with counts
// at the end; with --strict each is an error instead, raised before anything of the frame it
// concerns is written. Frames without camera matrices in window mode are warned about with
// what that costs (issue 24), never an error: many shots have no camera to give.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "resolve/sequence_job.h"

namespace taa::cli {

// "1-3, 7, 9-10": ascending frames with runs collapsed.
std::string frameListText(const std::vector<int>& frames);

class InputReport {
 public:
  // For a parsed command line whose frame list is resolved (resolveFrameList). Throws taa::Error
  // naming the first skipped frame's file when --strict meets --skip-missing frames.
  explicit InputReport(const CommandLine& commandLine);

  // JobCallbacks::frameRead: tallies `report`; with --strict throws taa::Error naming the file,
  // frame and channels for anything it changed.
  void frameRead(const FrameReport& report);

  // One line per kind of change, with counts and where it first happened; empty if nothing.
  std::vector<std::string> warnings() const;

 private:
  // One kind of change: how many values (or events), in how many frames, the first of them.
  struct Tally {
    long long values = 0;
    int frames = 0;
    std::string first;  // "frame 7, beauty.0007.exr"
    void add(long long count, const std::string& where);
  };

  bool strict_ = false;
  std::string colorChannels_, motionChannels_;
  std::vector<int> skipped_;
  Tally nonFiniteColor_, nonFiniteMotion_, clampedColor_, sizeChanges_, noCamera_,
      projectionJitter_;
  std::optional<std::pair<int, int>> lastSize_;
};

}  // namespace taa::cli
