// taatool: resolve a jittered EXR AOV sequence into an anti-aliased one (oiiotool-style CLI).
// All failures end here: "taatool ERROR: ..." on stderr and exit status 1.
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/info.h"
#include "fast_zlib/fast_zlib.h"
#include "taa/error.h"

namespace {

int run(const std::vector<std::string>& args) {
  using namespace taa;
  cli::CommandLine cl = cli::parseCommandLine(args);
  cli::useOcioEnvironmentUnlessGiven(cl, args);
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

  cli::resolveFrameList(cl);
  JobCallbacks callbacks;
  callbacks.log = log;
  callbacks.frameDone = [verbose](const FrameReport& report) {
    if (!verbose) return;
    std::cout << "frame " << report.frame << " (" << report.index + 1 << "/" << report.count
              << "): " << report.inputPath << " -> " << report.outputPath;
    if (report.historyReset) std::cout << " [history reset]";
    if (report.cutDetected) std::cout << " [cut detected: history reset]";
    if (report.nonFiniteColorValues > 0) {
      std::cout << " [" << report.nonFiniteColorValues << " NaN/Inf color values set to 0]";
    }
    std::cout << std::endl;
  };
  runSequenceJob(cl.job, callbacks);
  if (!quiet) {
    std::cout << "taatool: resolved " << cl.job.frames.size() << " frame(s) to "
              << cl.job.outputPattern << std::endl;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "taatool ERROR: " << e.what() << std::endl;
    return 1;
  }
}
