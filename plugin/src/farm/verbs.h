// taa-farm's verbs. Each prints to stdout and stderr and returns the exit status, or throws:
// UsageError (2), InputsNotReady (3), Stopped (128 + signal), any other taa::Error (1); main
// maps them (farm/main.cpp).
#pragma once

#include "farm/farm_arguments.h"

namespace taa::farm {

// Splits the shot into chunks and submits a Slurm array job (prints its id), or with --dry-run
// prints the batch script; --scheduler opencue|deadline prints their job's command instead.
int submitShot(const FarmArguments& args);

// Resolves one chunk: skips complete frames, writes the others atomically, one PROGRESS line
// per resolved frame.
int runChunk(const FarmArguments& args);

// Which output frames are complete, which are missing or incomplete; 0 when all are complete.
int reportStatus(const FarmArguments& args);

}  // namespace taa::farm
