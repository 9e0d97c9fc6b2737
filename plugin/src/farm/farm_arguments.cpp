#include "farm/farm_arguments.h"

#include <functional>
#include <map>
#include <set>

#include "farm/farm_errors.h"
#include "taa/version.h"
#include "util/number_text.h"

namespace taa::farm {
namespace {

int positiveInt(const std::string& option, const std::string& text, int minimum) {
  const std::optional<int> value = parseIntText(text);
  if (!value || *value < minimum) {
    throw UsageError(option + " expects an integer >= " + std::to_string(minimum) + ", got \"" +
                     text + "\"");
  }
  return *value;
}

// "N" (frames per task) or "FIRST-LAST" (a scheduler's range; either may be negative).
void parseChunk(const std::string& text, FarmArguments& args) {
  const std::size_t dash = text.find('-', 1);
  if (dash == std::string::npos) {
    args.chunkSize = positiveInt("--chunk", text, 1);
    return;
  }
  const std::optional<int> first = parseIntText(text.substr(0, dash));
  const std::optional<int> last = parseIntText(text.substr(dash + 1));
  if (!first || !last || *first > *last) {
    throw UsageError("--chunk expects frames per task (20) or FIRST-LAST (1001-1020), got \"" +
                     text + "\"");
  }
  args.chunkRange = std::make_pair(*first, *last);
}

Scheduler parseScheduler(const std::string& text) {
  if (text == "slurm") return Scheduler::Slurm;
  if (text == "opencue") return Scheduler::OpenCue;
  if (text == "deadline") return Scheduler::Deadline;
  throw UsageError("--scheduler expects one of slurm, opencue, deadline, got \"" + text + "\"");
}

}  // namespace

FarmArguments parseFarmArguments(const std::vector<std::string>& argv) {
  FarmArguments args;
  if (argv.empty()) throw UsageError("no verb given: submit, run or status");
  if (argv[0] == "--help" || argv[0] == "-h" || argv[0] == "help") {
    args.help = true;
    return args;
  }
  args.verb = argv[0] == "verify" ? "status" : argv[0];
  if (args.verb != "submit" && args.verb != "run" && args.verb != "status") {
    throw UsageError("unknown verb \"" + argv[0] + "\": submit, run or status");
  }

  std::set<std::string> given;
  using Handler = std::function<void(const std::string&)>;
  const std::map<std::string, Handler> withValue = {
      {"--chunk", [&](const std::string& v) { parseChunk(v, args); }},
      {"--task", [&](const std::string& v) { args.task = positiveInt("--task", v, 0); }},
      {"--preroll",
       [&](const std::string& v) {
         args.preroll = positiveInt("--preroll", v, 0);
         args.prerollGiven = true;
       }},
      {"--scheduler", [&](const std::string& v) { args.scheduler = parseScheduler(v); }},
      {"--partition", [&](const std::string& v) { args.slurm.partition = v; }},
      {"--time", [&](const std::string& v) { args.slurm.time = v; }},
      {"--mem", [&](const std::string& v) { args.slurm.mem = v; }},
      {"--cpus-per-task",
       [&](const std::string& v) {
         args.slurm.cpusPerTask = std::to_string(positiveInt("--cpus-per-task", v, 1));
       }},
      {"--job-name", [&](const std::string& v) { args.slurm.jobName = v; }},
      {"--log-dir", [&](const std::string& v) { args.slurm.logDir = v; }},
      {"--sbatch-arg", [&](const std::string& v) { args.slurm.extra.push_back(v); }},
  };
  const std::map<std::string, std::function<void()>> flags = {
      {"--dry-run", [&] { args.dryRun = true; }},
      {"--help", [&] { args.help = true; }},
      {"-h", [&] { args.help = true; }},
  };
  // Which verb each option belongs to (help belongs to all).
  const std::map<std::string, std::set<std::string>> verbsOf = {
      {"--chunk", {"submit", "run", "status"}},
      {"--task", {"run"}},
      {"--preroll", {"submit", "run"}},
      {"--dry-run", {"submit"}},
      {"--scheduler", {"submit"}},
      {"--partition", {"submit"}},
      {"--time", {"submit"}},
      {"--mem", {"submit"}},
      {"--cpus-per-task", {"submit"}},
      {"--job-name", {"submit"}},
      {"--log-dir", {"submit"}},
      {"--sbatch-arg", {"submit"}},
  };
  for (std::size_t i = 1; i < argv.size(); ++i) {
    std::string arg = argv[i];
    // "--chunk=6" as well as "--chunk 6" for taa-farm's own options; anything else is taatool's.
    std::optional<std::string> attached;
    if (const std::size_t equals = arg.find('=');
        arg.compare(0, 2, "--") == 0 && equals != std::string::npos &&
        withValue.count(arg.substr(0, equals))) {
      attached = arg.substr(equals + 1);
      arg.resize(equals);
    }
    const bool takesValue = withValue.count(arg) > 0;
    if (!takesValue && !flags.count(arg)) {
      args.taatoolArgs.push_back(arg);  // taatool's flags take their values along with them
      continue;
    }
    if (auto verbs = verbsOf.find(arg); verbs != verbsOf.end() && !verbs->second.count(args.verb)) {
      throw UsageError(arg + " is not an option of taa-farm " + args.verb);
    }
    if (arg != "--sbatch-arg" && !given.insert(arg).second) {
      throw UsageError(arg + " given twice");
    }
    if (!takesValue) {
      flags.at(arg)();
    } else if (attached) {
      withValue.at(arg)(*attached);
    } else if (i + 1 >= argv.size()) {
      throw UsageError("option " + arg + " needs a value");
    } else {
      withValue.at(arg)(argv[++i]);
    }
  }
  if (args.help) return args;
  if (args.verb == "submit" && !args.chunkSize) {
    throw UsageError("taa-farm submit needs --chunk N, the frames each task resolves");
  }
  if (args.verb == "run" && !args.chunkSize && !args.chunkRange) {
    throw UsageError("taa-farm run needs --chunk N (with $SLURM_ARRAY_TASK_ID or --task I) or "
                     "--chunk FIRST-LAST");
  }
  if (args.verb == "run" && args.task && args.chunkRange) {
    throw UsageError("--task picks a chunk of --chunk N; --chunk FIRST-LAST names one already");
  }
  if (args.verb == "status" && args.chunkRange) {
    throw UsageError("taa-farm status takes --chunk N (frames per task), not a range");
  }
  if (args.scheduler != Scheduler::Slurm &&
      (!args.slurm.partition.empty() || !args.slurm.time.empty() || !args.slurm.mem.empty() ||
       !args.slurm.cpusPerTask.empty() || !args.slurm.jobName.empty() ||
       !args.slurm.logDir.empty() || !args.slurm.extra.empty())) {
    throw UsageError("sbatch options (--partition, --time, --mem, ...) are for --scheduler slurm");
  }
  return args;
}

}  // namespace taa::farm

namespace taa::farm {

std::string farmHelpText() {
  return R"help(taa-farm -- taa's resolve as a render-farm step (taa )help"
         TAA_VERSION_STRING R"help()

Usage:
  taa-farm submit --chunk N [scheduler options] TAATOOL_ARGUMENTS
  taa-farm run (--chunk N [--task I] | --chunk FIRST-LAST) [--preroll N] TAATOOL_ARGUMENTS
  taa-farm status [--chunk N] TAATOOL_ARGUMENTS          (also: taa-farm verify)

TAATOOL_ARGUMENTS are taatool's: the colour pattern, --depth/--motion or --preset, --frames
(the shot; default: the frames on disk), -o, resolve options. Every verb takes the same ones.

submit: splits the shot into chunks of N frames, one Slurm array task each (sbatch --array),
prints the job id on stdout.
  --chunk N                frames per task
  --preroll N              history mode: frames resolved before each chunk, read-only
                           (default )help" + std::to_string(kDefaultPreroll) + R"help()
  --dry-run                print the batch script instead of submitting it
  --partition P, --time T, --mem M, --cpus-per-task C, --job-name NAME
                           passed to sbatch
  --sbatch-arg OPTION      any other sbatch option, one per flag: --sbatch-arg --qos=high
  --log-dir DIR            tasks' logs, DIR/taa-farm-JOBID_TASK.log (default: this folder)
  --scheduler opencue|deadline
                           print the job for that scheduler (not submitted): the same
                           taa-farm run line with its frame tokens

run: resolves one chunk (what each task executes). Frames whose output is complete (read
whole, resolved with these options) are skipped; the others are written atomically.
  --chunk N                the chunk is task I's of chunks of N: I = --task or
                           $SLURM_ARRAY_TASK_ID (0 = the first chunk)
  --chunk FIRST-LAST       the shot's frames in FIRST-LAST (a scheduler's frame tokens)
  --preroll N              history mode: resolve up to N frames before the chunk first,
                           not written (stops at the shot's start, a gap or a reset frame)
  Prints "PROGRESS: P% frame F ..." once per resolved frame.

status: lists output frames missing or incomplete and a summary line; with --chunk N, the
tasks to run again.

Exit status: 0 done (status: every frame complete); 1 resolve error, message naming file,
frame and channel (status: a frame missing or incomplete; submit: sbatch failed); 2 bad
arguments; 3 inputs not ready (an input frame the task needs is missing); 130/143 stopped by
SIGINT/SIGTERM between frames (frames written are complete).
)help";
}

}  // namespace taa::farm
