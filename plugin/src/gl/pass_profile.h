// Where a run's GL time goes, pass by pass (TAA_GL_PROFILE=1 in the environment; taatool prints
// the table at the end of a run, docs/PERFORMANCE.md "Profiling the GL passes"). While it is on,
// every full-screen draw waits for the GL before and after it, so the passes neither overlap
// each other nor the reads and writes: the figures say how a run's GL work divides, and the
// run itself is slower than without it.
#pragma once

#include <string>
#include <vector>

namespace taa::gl {

// Whether TAA_GL_PROFILE is set (and not "0"), read once per process.
bool passProfileOn();

// Adds one draw of `pass` that took `milliseconds` (thread-safe: a host may run several nodes).
void recordPassTime(const char* pass, double milliseconds);

struct PassTime {
  std::string pass;
  long draws = 0;
  double milliseconds = 0.0;
};

// Every pass drawn so far in this process, in the order of each one's first draw.
std::vector<PassTime> passProfile();

// passProfile() as a table, a line a pass: draws, total and mean milliseconds, share of the
// GL time; empty when nothing was drawn.
std::string passProfileText();

}  // namespace taa::gl
