// What taa-farm submit hands a scheduler: the `taa-farm run` command of every task, as a Slurm
// array job script, or as the command of an OpenCue layer or a Deadline command-line job with
// their frame tokens. Every form runs the same `taa-farm run` with the same taatool arguments.
#pragma once

#include <string>
#include <vector>

#include "farm/farm_arguments.h"
#include "farm/shot.h"

namespace taa::farm {

// `text` as one POSIX shell word: bare when it is made of safe characters, else single-quoted.
std::string shellQuoted(const std::string& text);

// Everything a task's command is made of.
struct TaskCommand {
  std::string farmPath;          // the taa-farm executable, absolute
  std::string workingFolder;     // where relative paths in the arguments are meant from
  std::vector<std::string> taatoolArgs;  // as given to submit, plus --frames when it had none
  std::string framesText;        // the shot's frames ("1001-1240")
  int chunkSize = 1;
  int chunkCount = 1;
  bool history = true;           // history mode: --preroll is passed
  int preroll = kDefaultPreroll;
};

TaskCommand taskCommandOf(const FarmArguments& args, const Shot& shot,
                          const std::string& farmPath, const std::string& workingFolder);

// `taa-farm run` with `chunk` as its --chunk value, shell-quoted.
std::string runCommandLine(const TaskCommand& task, const std::string& chunk);

// A Slurm batch script: an array of chunkCount tasks (ids 0..n-1), each running
// `taa-farm run --chunk SIZE`, which takes its chunk from $SLURM_ARRAY_TASK_ID. Requeueable, logs
// appended (a requeued task adds to its log), the sbatch options given.
std::string slurmArrayScript(const TaskCommand& task, const SlurmOptions& slurm);

// The command of an OpenCue layer over the shot's frames with the chunk size: OpenCue replaces
// #FRAME_START# and #FRAME_END# with each chunk's first and last frame.
std::string openCueLayerText(const TaskCommand& task);

// A deadlinecommand line submitting a command-line job: Deadline replaces <STARTFRAME> and
// <ENDFRAME> in the arguments with each task's first and last frame, <QUOTE> with '"'.
std::string deadlineJobText(const TaskCommand& task);

}  // namespace taa::farm
