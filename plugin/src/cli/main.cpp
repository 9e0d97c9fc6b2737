// taatool: resolve a jittered EXR AOV sequence into an anti-aliased one (oiiotool-style CLI).
// All failures end here: "taatool ERROR: ..." on stderr and exit status 1 (128 + the signal's
// number when SIGINT or SIGTERM stopped the run).
#include <unistd.h>

#include <csignal>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/info.h"
#include "cli/input_report.h"
#include "cli/progress_line.h"
#include "fast_zlib/fast_zlib.h"
#include "gl/pass_profile.h"
#include "taa/error.h"
#include "util/frame_memory.h"
#include "util/interruption.h"

namespace {

int run(const std::vector<std::string>& args) {
  using namespace taa;
  cli::CommandLine cl = cli::parseCommandLine(args);
  if (cl.help) {
    std::cout << cli::helpText();
    return 0;
  }
  const bool quiet = cl.verbosity == cli::Verbosity::Quiet;
  const bool verbose = cl.verbosity == cli::Verbosity::Verbose;
  gl::LogSink log = [quiet](const std::string& message) {
    if (!quiet) std::cerr << "taatool: " << message << "\n";
  };
  if (cl.info) {
    const int status = cli::printInfo(cl.job.backend, log, std::cout);
    std::cout << "EXR zlib codec:  " << fast_zlib::description() << "\n";
    return status;
  }
  if (cl.listOptions) {
    std::cout << cli::optionsMarkdownTable();
    return 0;
  }
  if (cl.listBrackets) {
    cli::printBrackets(cl.job.resolve.color.ocioConfig, std::cout);
    return 0;
  }

  const StopSignals stopSignals;  // SIGINT/SIGTERM stop the run between frames
  cli::resolveFrameList(cl);
  // Frames done, rate and time left on stderr: one line rewritten on a terminal, a line per
  // frame in a log; -v puts them on its per-frame lines instead, -q prints none.
  std::optional<cli::ProgressLine> progress;
  if (!quiet) progress.emplace(std::cerr, isatty(STDERR_FILENO) == 1);
  cli::InputReport inputReport(cl);
  JobCallbacks callbacks;
  callbacks.log = log;
  if (verbose) callbacks.detail = log;
  callbacks.frameRead = [&inputReport](const FrameReport& report) {
    inputReport.frameRead(report);
  };
  callbacks.stopRequested = [] { return StopSignals::received() != 0; };
  callbacks.frameDone = [verbose, &progress](const FrameReport& report) {
    if (!progress) return;
    if (!verbose) return progress->frameDone(report.frame, report.index + 1, report.count);
    std::cout << "frame " << report.frame << " (" << progress->textNow(report.index + 1,
                                                                        report.count)
              << "): " << report.inputPath << " -> " << report.outputPath;
    if (report.sizeChanged) {
      std::cout << " [new size " << report.width << "x" << report.height << ": history reset]";
    } else if (report.historyReset) {
      std::cout << " [history reset]";
    }
    if (report.cutDetected) std::cout << " [cut detected: history reset]";
    if (report.nonFiniteColorValues > 0) {
      std::cout << " [" << report.nonFiniteColorValues << " NaN/Inf color values set to 0]";
    }
    if (report.nonFiniteMotionValues > 0) {
      std::cout << " [" << report.nonFiniteMotionValues << " NaN/Inf motion values set to 0]";
    }
    if (report.clampedColorValues > 0) {
      std::cout << " [" << report.clampedColorValues << " color values beyond half's range]";
    }
    std::cout << std::endl;
  };
  runSequenceJob(cl.job, callbacks);
  if (progress) progress->finish();
  // Asked for in the environment, so printed even with -q (the measuring scripts' flag).
  if (gl::passProfileOn()) {
    std::cerr << "taatool: GL passes (TAA_GL_PROFILE):\n" << gl::passProfileText();
  }
  if (!quiet) {
    for (const std::string& warning : inputReport.warnings()) {
      std::cerr << "taatool WARNING: " << warning << "\n";
    }
    std::cout << "taatool: resolved " << cl.job.frames.size() << " frame(s) to "
              << cl.job.outputPattern << std::endl;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  taa::keepFrameBuffersOutOfTheHeap();
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const taa::Stopped& e) {
    const int signal = taa::StopSignals::received();
    std::cerr << "taatool ERROR: interrupted by " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
              << ": " << e.what() << std::endl;
    return 128 + signal;  // the shell's convention for a process ended by that signal
  } catch (const std::exception& e) {
    std::cerr << "taatool ERROR: " << e.what() << std::endl;
    return 1;
  }
}
