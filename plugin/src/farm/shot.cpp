#include "farm/shot.h"

#include "farm/farm_errors.h"
#include "io/sequence_pattern.h"

namespace taa::farm {

Shot loadShot(const std::vector<std::string>& taatoolArgs) {
  Shot shot;
  try {
    shot.commandLine = cli::parseCommandLine(taatoolArgs);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.description(), e.context());
  }
  cli::CommandLine& cl = shot.commandLine;
  if (cl.help || cl.info || cl.listBrackets || cl.listOptions) {
    throw UsageError("taatool's --help, --info, --list-brackets and --list-options are not farm "
                     "work: run taatool for them");
  }
  if (cl.job.outputPattern.empty()) throw UsageError("no output given (use -o PATTERN)");
  if (!io::hasFramePlaceholder(cl.job.layout.color.pattern) ||
      !io::hasFramePlaceholder(cl.job.outputPattern)) {
    throw UsageError("a farm job resolves a sequence: the input and -o patterns need a frame "
                     "placeholder (#, @ or %0Nd)");
  }
  try {
    cli::resolveFrameList(cl);
  } catch (const Error& e) {
    // Without --frames, the frames on disk are the shot: none yet, or a gap, is not ready.
    if (cl.framesText.empty()) throw InputsNotReady(e.description(), e.context());
    throw UsageError(e.description(), e.context());
  }
  shot.frames = cl.job.frames;
  for (std::size_t i = 1; i < shot.frames.size(); ++i) {
    if (shot.frames[i] <= shot.frames[i - 1]) {
      throw UsageError("frames must ascend: " + std::to_string(shot.frames[i]) + " follows " +
                       std::to_string(shot.frames[i - 1]) + " (--frames " + cl.framesText + ")");
    }
  }
  shot.expectedOptions = outputOptionsAttribute(cl.job);
  return shot;
}

std::string outputPath(const Shot& shot, int frame) {
  return io::expandFramePattern(shot.commandLine.job.outputPattern, frame);
}

}  // namespace taa::farm
