// The benchmark tools' clocks: the whole process's CPU time (user + system, every thread's:
// llvmpipe's and OpenEXR's included), the steadier figure on a shared machine, and wall time.
#pragma once

#include <sys/resource.h>

#include <chrono>

namespace taa::bench {

inline double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

inline double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace taa::bench
