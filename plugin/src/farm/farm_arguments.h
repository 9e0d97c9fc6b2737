// taa-farm's command line: a verb, taa-farm's own options, and taatool's arguments (input,
// output, resolve options) passed through unchanged. taa-farm's option names are not taatool's,
// so they may appear anywhere on the line.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace taa::farm {

// History mode's pre-roll when --preroll is not given: chosen from the measured difference to a
// whole-shot run (README "Render farm").
inline constexpr int kDefaultPreroll = 16;

enum class Scheduler { Slurm, OpenCue, Deadline };

// sbatch settings of `taa-farm submit`, each empty unless given.
struct SlurmOptions {
  std::string partition, time, mem, cpusPerTask, jobName;
  std::string logDir;               // folder of the tasks' logs (default: the working folder)
  std::vector<std::string> extra;   // --sbatch-arg, each one sbatch option ("--qos=high")
};

struct FarmArguments {
  std::string verb;                  // submit, run, status (verify is status)
  bool help = false;
  std::optional<int> chunkSize;      // --chunk N
  std::optional<std::pair<int, int>> chunkRange;  // --chunk FIRST-LAST (run)
  std::optional<int> task;           // --task I (run; default $SLURM_ARRAY_TASK_ID)
  int preroll = kDefaultPreroll;     // --preroll N (history mode)
  bool prerollGiven = false;
  bool dryRun = false;               // --dry-run (submit)
  Scheduler scheduler = Scheduler::Slurm;  // --scheduler (submit)
  SlurmOptions slurm;
  std::vector<std::string> taatoolArgs;
};

// Parses argv[1..]. Throws UsageError naming the offending argument, including options that
// belong to another verb.
FarmArguments parseFarmArguments(const std::vector<std::string>& args);

std::string farmHelpText();

}  // namespace taa::farm
