// taatool's command line: parsing into a SequenceJob, and the grouped --help text.
#pragma once

#include <string>
#include <vector>

#include "resolve/sequence_job.h"

namespace taa::cli {

enum class Verbosity { Quiet, Normal, Verbose };

struct CommandLine {
  bool help = false;
  bool info = false;
  bool listBrackets = false;
  bool listOptions = false;
  Verbosity verbosity = Verbosity::Normal;
  std::string framesText;  // --frames as given; empty = every frame found on disk
  std::string viewText;    // --view as given; empty = all (a multi-view file's every view)
  bool skipMissing = false;  // --skip-missing: resolve around frames missing from the sequence
  bool strict = false;       // --strict: what would change the result silently is an error
  std::vector<int> missingFrames;  // gaps in the frames found on disk (resolveFrameList)
  SequenceJob job;         // everything else, ready to run once frames are known
};

// Parses argv[1..]. Throws taa::Error with a message naming the offending argument.
CommandLine parseCommandLine(const std::vector<std::string>& args);

// True for an option that takes no value ("--strict", "-v"): Python's resolve_sequence checks
// that a keyword given False names one, which it then leaves out.
bool isSwitchOption(const std::string& option);

// Fills job.frames from --frames or, without it, from the color files found on disk. Frames
// missing between the first and last found are an error naming the first missing file, unless
// --skip-missing is given (they are kept in missingFrames for the report). With --frames and
// --skip-missing, frames asked for whose colour file is missing are skipped the same way.
// Then the views of a multi-view file (cli/view_selection.h, --view).
void resolveFrameList(CommandLine& commandLine);

std::string helpText();

// The resolve options as a Markdown table (option, values, default, what it trades): the README's
// table is this output (`taatool --list-options`), and a test keeps the two equal.
std::string optionsMarkdownTable();

}  // namespace taa::cli
