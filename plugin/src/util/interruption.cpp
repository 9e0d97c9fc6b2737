#include "util/interruption.h"

#include <signal.h>

namespace taa {
namespace {

// Written by the handler only: a lock-free atomic type is async-signal-safe.
volatile sig_atomic_t firstSignal = 0;
struct sigaction previousInt, previousTerm;

extern "C" void recordSignal(int signal) {
  if (firstSignal == 0) {
    firstSignal = signal;
    return;
  }
  // Asked twice: stop now (what this leaves behind, the next run cleans up).
  struct sigaction defaultAction {};
  defaultAction.sa_handler = SIG_DFL;
  sigemptyset(&defaultAction.sa_mask);
  sigaction(signal, &defaultAction, nullptr);
  raise(signal);
}

}  // namespace

StopSignals::StopSignals() {
  firstSignal = 0;
  struct sigaction action {};
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // I/O in progress goes on; the job polls between frames
  sigaction(SIGINT, &action, &previousInt);
  sigaction(SIGTERM, &action, &previousTerm);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previousInt, nullptr);
  sigaction(SIGTERM, &previousTerm, nullptr);
}

int StopSignals::received() { return firstSignal; }

}  // namespace taa
