#include "farm/task_commands.h"

#include <algorithm>

#include "cli/input_report.h"
#include "farm/farm_errors.h"
#include "farm/sbatch_directives.h"
#include "util/one_line_text.h"

namespace taa::farm {
namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + word;
  return line;
}

// The arguments after `taa-farm run`, unquoted, with `chunk` as the --chunk value.
std::vector<std::string> runArguments(const TaskCommand& task, const std::string& chunk) {
  std::vector<std::string> args = {"run", "--chunk", chunk};
  if (task.history) args.insert(args.end(), {"--preroll", std::to_string(task.preroll)});
  args.insert(args.end(), task.taatoolArgs.begin(), task.taatoolArgs.end());
  return args;
}

// Deadline splits its arguments string at spaces outside double quotes, which <QUOTE> stands for;
// it has no way to write a double quote or a line break inside one.
std::string deadlineQuoted(const std::string& text) {
  if (text.find_first_of("\"\r\n") != std::string::npos) {
    throw UsageError("Deadline's job arguments cannot carry a double quote or a line break: \"" +
                     oneLineText(text) + "\"");
  }
  const bool plain = !text.empty() && text.find_first_of(" \t\"") == std::string::npos;
  return plain ? text : "<QUOTE>" + text + "<QUOTE>";
}

}  // namespace

std::string shellQuoted(const std::string& text) {
  const bool safe = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || std::string("@%+=:,./_-#").find(char(c)) != std::string::npos;
  });
  // '#' starts a comment only at the start of a word.
  if (safe && text[0] != '#') return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

TaskCommand taskCommandOf(const FarmArguments& args, const Shot& shot,
                          const std::string& farmPath, const std::string& workingFolder) {
  TaskCommand task;
  task.farmPath = farmPath;
  task.workingFolder = workingFolder;
  task.taatoolArgs = args.taatoolArgs;
  std::string frames = cli::frameListText(shot.frames);
  frames.erase(std::remove(frames.begin(), frames.end(), ' '), frames.end());
  task.framesText = frames;
  // Every task must see the same shot: the frames found on disk at submission, if not given.
  if (shot.commandLine.framesText.empty()) {
    task.taatoolArgs.insert(task.taatoolArgs.end(), {"--frames", frames});
  }
  task.chunkSize = *args.chunkSize;
  task.chunkCount = int((shot.frames.size() + std::size_t(task.chunkSize) - 1) /
                        std::size_t(task.chunkSize));
  task.history = shot.commandLine.job.resolve.mode == ResolveMode::History;
  task.preroll = args.preroll;
  return task;
}

std::string runCommandLine(const TaskCommand& task, const std::string& chunk) {
  std::vector<std::string> words = {shellQuoted(task.farmPath)};
  for (const std::string& arg : runArguments(task, chunk)) words.push_back(shellQuoted(arg));
  return joined(words);
}

std::string slurmArrayScript(const TaskCommand& task, const SlurmOptions& slurm) {
  std::string script = "#!/bin/sh\n";
  script += "# taa-farm: frames " + task.framesText + " in " + std::to_string(task.chunkCount) +
            " chunk(s) of " + std::to_string(task.chunkSize) +
            ", one array task each; `taa-farm run` takes its chunk from SLURM_ARRAY_TASK_ID.\n";
  // Every value goes through sbatchLine, which quotes it for sbatch's own parser. The working
  // folder is not among them: sbatch runs the job where it was started (submit starts it in
  // the working folder), and the logs' default path is relative to it.
  script += sbatchLine("--job-name", slurm.jobName.empty() ? "taa-farm" : slurm.jobName,
                       "--job-name");
  script += sbatchLine("--array", "0-" + std::to_string(task.chunkCount - 1), "--chunk");
  const std::string logName = "taa-farm-%A_%a.log";
  if (slurm.logDir.find('%') != std::string::npos) {
    throw UsageError("--log-dir holds '%', which Slurm would expand in the log's path: \"" +
                     oneLineText(slurm.logDir) + "\"");
  }
  script += sbatchLine("--output", slurm.logDir.empty() ? logName : slurm.logDir + "/" + logName,
                       "--log-dir");
  script += sbatchLine("--open-mode", "append", "--open-mode");  // a requeued run adds to its log
  script += "#SBATCH --requeue\n";
  const std::pair<const char*, const std::string*> given[] = {
      {"--partition", &slurm.partition},
      {"--time", &slurm.time},
      {"--mem", &slurm.mem},
      {"--cpus-per-task", &slurm.cpusPerTask}};
  for (const auto& [name, value] : given) {
    if (!value->empty()) script += sbatchLine(name, *value, name);
  }
  for (const std::string& extra : slurm.extra) script += sbatchLineOf(extra);
  // The shell runs the rest: every word shell-quoted. A folder the node cannot enter fails the
  // task here instead of running it elsewhere (slurmd falls back to /tmp).
  script += "cd -- " + shellQuoted(task.workingFolder) + " || exit 1\n";
  // exec: signals Slurm sends the task (scancel, time limit) reach taa-farm itself.
  script += "exec " + runCommandLine(task, std::to_string(task.chunkSize)) + "\n";
  return script;
}

std::string openCueLayerText(const TaskCommand& task) {
  return "# OpenCue (printed, not submitted): one layer, frame range " + task.framesText +
         ", chunk size " + std::to_string(task.chunkSize) + ", working folder " +
         oneLineText(task.workingFolder) + ", command:\n" +
         runCommandLine(task, "#FRAME_START#-#FRAME_END#") + "\n";
}

std::string deadlineJobText(const TaskCommand& task) {
  std::vector<std::string> arguments;
  for (const std::string& arg : runArguments(task, "<STARTFRAME>-<ENDFRAME>")) {
    arguments.push_back(deadlineQuoted(arg));
  }
  return "# Deadline (printed, not submitted): a command-line job, one task per chunk:\n"
         "deadlinecommand -SubmitCommandLineJob -executable " + shellQuoted(task.farmPath) +
         " -frames " + shellQuoted(task.framesText) + " -chunksize " +
         std::to_string(task.chunkSize) + " -startupdirectory " +
         shellQuoted(task.workingFolder) + " -arguments " + shellQuoted(joined(arguments)) + "\n";
}

}  // namespace taa::farm
