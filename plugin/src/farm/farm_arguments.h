// taa-farm's command line: a verb, taa-farm's own options, and taatool's arguments (input,
// output, resolve options) passed through unchanged. taa-farm's option names are not taatool's,
// so they may appear anywhere on the line.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace taa::farm {

// History mode's pre-roll when --preroll is not given. History forgets at the blend rate (0.04 a
// frame by default), so a chunk's history started 128 frames before it differs from the
// whole-shot run's by at most 0.00221 in display values (Reinhard x/(1+x)) on the slowest scene
// measured, below one 8-bit step (1/255); 96 frames left 0.012 (README "Render farm",
// taa-preroll-error).
inline constexpr int kDefaultPreroll = 128;

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
