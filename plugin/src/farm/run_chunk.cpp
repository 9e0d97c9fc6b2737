// taa-farm run: what each farm task executes (farm/verbs.h).
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>

#include "cli/input_report.h"
#include "farm/chunk_plan.h"
#include "farm/farm_errors.h"
#include "util/one_line_text.h"
#include "farm/shot.h"
#include "farm/verbs.h"
#include "io/file_presence.h"
#include "io/output_completeness.h"
#include "resolve/window_plan.h"
#include "util/interruption.h"
#include "util/number_text.h"

namespace taa::farm {
namespace {

namespace fs = std::filesystem;

struct Chunk {
  std::vector<int> frames;
  std::string name;  // "task 2" or "chunk 1013-1018", for the log lines
};

Chunk chunkOf(const FarmArguments& args, const Shot& shot) {
  const std::string shotText = cli::frameListText(shot.frames);
  if (args.chunkRange) {
    const auto [first, last] = *args.chunkRange;
    Chunk chunk{framesWithin(shot.frames, first, last),
                "chunk " + std::to_string(first) + "-" + std::to_string(last)};
    if (chunk.frames.empty()) {
      throw UsageError("--chunk " + std::to_string(first) + "-" + std::to_string(last) +
                       " holds no frame of the shot (" + shotText + ")");
    }
    return chunk;
  }
  int task = 0;
  if (args.task) {
    task = *args.task;
  } else {
    const char* env = std::getenv("SLURM_ARRAY_TASK_ID");
    const std::optional<int> id = env ? parseIntText(env) : std::nullopt;
    if (!id || *id < 0) {
      throw UsageError(std::string("--chunk N needs the task's index: SLURM_ARRAY_TASK_ID is ") +
                       (env ? "\"" + std::string(env) + "\"" : "not set") +
                       " (give --task I, or --chunk FIRST-LAST)");
    }
    task = *id;
  }
  const auto chunks = splitIntoChunks(shot.frames, *args.chunkSize);
  if (task >= int(chunks.size())) {
    throw UsageError("task " + std::to_string(task) + " is past the last chunk: the shot (" +
                     shotText + ") makes " + std::to_string(chunks.size()) + " chunk(s) of " +
                     std::to_string(*args.chunkSize) + " (tasks 0-" +
                     std::to_string(chunks.size() - 1) + ")");
  }
  return {chunks[std::size_t(task)], "task " + std::to_string(task)};
}

// Every input file of `frames` exists; else the first missing one is "not ready".
void requireInputs(const SequenceJob& job, const std::vector<int>& frames,
                   const std::string& chunkName) {
  for (int frame : frames) {
    for (const InputFile& input : frameInputFiles(job.layout, frame)) {
      if (const std::string absence = io::fileAbsence(input.path); !absence.empty()) {
        throw InputsNotReady("input frame not ready (" + absence + "), needed by " + chunkName,
                             {input.path, frame, input.aov});
      }
    }
  }
}

// The shot's frames the windows of `outputs` take in once every frame of the shot is on disk.
std::vector<int> windowInputs(const Shot& shot, const std::vector<int>& outputs) {
  const SequenceJob& job = shot.commandLine.job;
  std::set<int> existing(shot.frames.begin(), shot.frames.end());
  existing.insert(job.availableFrames.begin(), job.availableFrames.end());
  const WindowPlan plan = planWindows(outputs, {existing.begin(), existing.end()},
                                      job.resetFrames, job.resolve.window.radius);
  std::vector<int> needed;
  const std::set<int> inShot(shot.frames.begin(), shot.frames.end());
  for (int frame : plan.reads) {
    if (inShot.count(frame)) needed.push_back(frame);
  }
  return needed;
}

}  // namespace

int runChunk(const FarmArguments& args) {
  Shot shot = loadShot(args.taatoolArgs);
  const Chunk chunk = chunkOf(args, shot);
  SequenceJob& job = shot.commandLine.job;
  const bool window = job.resolve.mode == ResolveMode::Window;
  const std::string prefix = "taa-farm run: " + chunk.name + ": ";

  std::vector<int> pending;
  for (int frame : chunk.frames) {
    const std::string path = outputPath(shot, frame);
    const io::OutputCheck check = io::checkOutputComplete(path, shot.expectedOptions);
    if (check.complete) {
      std::cout << prefix << "frame " << frame << " complete, skipped: " << oneLineText(path)
                << "\n";
    } else {
      if (check.reason != "missing") {
        std::cout << prefix << "frame " << frame << " is resolved again (" << check.reason
                  << "): " << oneLineText(path) << "\n";
      }
      pending.push_back(frame);
    }
  }
  if (pending.empty()) {
    std::cout << prefix << "frames " << cli::frameListText(chunk.frames)
              << " already complete\nPROGRESS: 100%" << std::endl;
    return 0;
  }

  const ChunkWork work =
      window ? planWindowChunk(pending)
             : planHistoryChunk(shot.frames, chunk.frames, pending, args.preroll, job.resetFrames);
  requireInputs(job, window ? windowInputs(shot, work.write) : work.resolve, chunk.name);
  job.frames = work.resolve;
  job.prerollFrames = work.preroll;

  std::cout << prefix << "frames " << cli::frameListText(chunk.frames) << " of "
            << cli::frameListText(shot.frames) << ", " << work.write.size() << " to write";
  if (!work.preroll.empty()) {
    std::cout << ", history from " << work.resolve.front() << " (pre-roll and complete frames "
              << cli::frameListText({work.preroll.begin(), work.preroll.end()})
              << " resolved, not written)";
  }
  std::cout << std::endl;

  const StopSignals stopSignals;  // SIGTERM (scancel, a time limit) stops between frames
  cli::InputReport inputReport(shot.commandLine);
  JobCallbacks callbacks;
  const bool quiet = shot.commandLine.verbosity == cli::Verbosity::Quiet;
  callbacks.log = [quiet](const std::string& message) {
    if (!quiet) std::cerr << "taa-farm: " << message << "\n";
  };
  callbacks.frameRead = [&inputReport](const FrameReport& report) {
    inputReport.frameRead(report);
  };
  callbacks.stopRequested = [] { return StopSignals::received() != 0; };
  std::vector<int> written;
  callbacks.frameDone = [&written](const FrameReport& report) {
    std::cout << "PROGRESS: " << 100 * (report.index + 1) / report.count << "% frame "
              << report.frame;
    if (report.preroll) {
      std::cout << " resolved for history, not written";
    } else {
      std::cout << " written: " << oneLineText(report.outputPath);  // one line, whatever the path
      written.push_back(report.frame);
    }
    std::cout << std::endl;  // flushed: a farm manager reads it as it comes
  };
  runSequenceJob(job, callbacks);
  for (const std::string& warning : inputReport.warnings()) {
    std::cerr << "taa-farm WARNING: " << warning << "\n";
  }
  std::cout << prefix << "done: wrote " << cli::frameListText(written) << " ("
            << written.size() << " frame(s)), " << chunk.frames.size() - pending.size()
            << " already complete" << std::endl;
  return 0;
}

}  // namespace taa::farm
