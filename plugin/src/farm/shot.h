// The shot a farm job resolves: taatool's arguments parsed as taatool parses them, and the frames
// one taatool run over them would resolve. Every verb of taa-farm starts here, so a task, the
// status check and taatool agree on the frames, the options and the output names.
#pragma once

#include <string>
#include <vector>

#include "cli/cli_options.h"

namespace taa::farm {

struct Shot {
  cli::CommandLine commandLine;  // taatool's; job.frames and job.availableFrames filled
  std::vector<int> frames;       // the shot, in taatool's order
  std::string expectedOptions;   // the outputs' taa:options (resolve/sequence_job.h)
};

// Throws UsageError for arguments taatool would refuse (or that are not a resolve: --help,
// --info, ...), InputsNotReady when no --frames is given and no input frame is on disk yet.
Shot loadShot(const std::vector<std::string>& taatoolArgs);

// The output file of `frame`.
std::string outputPath(const Shot& shot, int frame);

}  // namespace taa::farm
