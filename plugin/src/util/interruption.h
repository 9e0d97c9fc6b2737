// Stopping a long job cleanly (issue 17). A face decides when: taatool on SIGINT or SIGTERM,
// Python on KeyboardInterrupt. It says so through JobCallbacks::stopRequested; the sequence job
// checks between frames, lets the frames in flight be written (complete files) and throws
// Stopped. SIGKILL cannot be caught: the temporaries it leaves, io/stale_temp_files.h removes on
// the next run over the same output.
#pragma once

#include "taa/error.h"

namespace taa {

// The job stopped on request between frames; every frame written is complete.
class Stopped : public Error {
 public:
  using Error::Error;
};

// Records SIGINT and SIGTERM while it lives; the previous handlers come back after. A second
// signal ends the process at once with the default action, for a user who will not wait for the
// frame in flight. For executables only: a library must not take over its host's signals.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The first signal received (SIGINT or SIGTERM), 0 while none has been.
  static int received();
};

}  // namespace taa
