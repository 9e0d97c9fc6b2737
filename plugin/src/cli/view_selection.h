// taatool's --view NAME|all: which views of a multi-view EXR the job resolves (io/views.h).
#pragma once

#include "cli/cli_options.h"

namespace taa::cli {

// Fills commandLine.job.views from the first frame's colour file and --view (all by default):
// every view, or the one named. Nothing for a file that is not multi-view. Throws taa::Error
// for --view on a file without views or a view the file lacks (naming those it has), and for
// what several views cannot share: --out-ch (one name set) and --debug-layers.
void selectViews(CommandLine& commandLine);

}  // namespace taa::cli
