// taa-farm status (verify): the shot's outputs on disk, each read whole (farm/verbs.h).
#include <iostream>
#include <map>

#include "cli/input_report.h"
#include "farm/chunk_plan.h"
#include "farm/shot.h"
#include "farm/verbs.h"
#include "io/output_completeness.h"

namespace taa::farm {

int reportStatus(const FarmArguments& args) {
  const Shot shot = loadShot(args.taatoolArgs);
  std::vector<int> complete, missing, incomplete;
  for (int frame : shot.frames) {
    const std::string path = outputPath(shot, frame);
    const io::OutputCheck check = io::checkOutputComplete(path, shot.expectedOptions);
    if (check.complete) {
      complete.push_back(frame);
    } else if (check.reason == "missing") {
      missing.push_back(frame);
    } else {
      incomplete.push_back(frame);
      std::cout << "frame " << frame << ": incomplete (" << check.reason << "): " << path << "\n";
    }
  }
  if (!missing.empty()) std::cout << "missing: " << cli::frameListText(missing) << "\n";
  if (args.chunkSize && complete.size() < shot.frames.size()) {
    // Which tasks of `taa-farm submit --chunk N` to requeue.
    const std::set<int> done(complete.begin(), complete.end());
    const auto chunks = splitIntoChunks(shot.frames, *args.chunkSize);
    std::string tasks;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
      for (int frame : chunks[i]) {
        if (done.count(frame)) continue;
        tasks += (tasks.empty() ? "" : ",") + std::to_string(i);
        break;
      }
    }
    std::cout << "tasks to run again: " << tasks << "\n";
  }
  std::cout << "taa-farm status: " << complete.size() << " of " << shot.frames.size()
            << " frames complete";
  if (!missing.empty()) std::cout << ", missing " << cli::frameListText(missing);
  if (!incomplete.empty()) std::cout << ", incomplete " << cli::frameListText(incomplete);
  std::cout << " (" << shot.commandLine.job.outputPattern << ")" << std::endl;
  return complete.size() == shot.frames.size() ? 0 : 1;
}

}  // namespace taa::farm
