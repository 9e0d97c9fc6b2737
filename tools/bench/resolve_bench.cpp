// taa-resolve-bench: the GL side of a resolve alone, without file I/O. Reads a few frames once,
// then resolves them over and over (upload, both passes, read-back in the output type) and
// prints wall and CPU milliseconds per frame. CPU time is the whole process's (user + system,
// llvmpipe's threads included): on a shared machine it is the steadier figure.
//   taa-resolve-bench [--repeat N] <taatool arguments: inputs, --frames, resolve options>
// docs/PERFORMANCE.md quotes it for shader changes; whole runs are timed by scripts/benchmark.sh.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "io/frame_reader.h"
#include "resolve/resolver.h"
#include "taa/error.h"

namespace {

double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

int run(std::vector<std::string> args) {
  using namespace taa;
  int repeat = 24;
  if (args.size() >= 2 && args[0] == "--repeat") {
    repeat = std::stoi(args[1]);
    args.erase(args.begin(), args.begin() + 2);
  }
  cli::CommandLine cl = cli::parseCommandLine(args);
  cli::resolveFrameList(cl);
  const SequenceJob& job = cl.job;
  std::vector<io::FrameData> frames;
  for (std::size_t i = 0; i < std::min<std::size_t>(job.frames.size(), 4); ++i) {
    frames.push_back(io::readFrame(job.layout, job.frames[i]));
  }
  auto context = gl::Context::create(job.backend);
  Resolver resolver(*context, job.resolve);
  const SampleType outputType = io::outputSampleType(job.write, frames[0].colorSpec);
  auto resolveFrame = [&](int n) {
    const io::FrameData& data = frames[std::size_t(n) % frames.size()];
    ResolveInput input;
    input.color = &data.color;
    input.depth = data.depth.empty() ? nullptr : &data.depth;
    input.motion = data.motion.empty() ? nullptr : &data.motion;
    input.jitter = {0.25f, -0.25f};
    input.camera = data.camera ? &*data.camera : nullptr;
    input.window = data.window;
    input.ndc = data.ndc;
    resolver.resolve(input, outputType);
  };
  resolveFrame(0);  // compiles the shader variants and allocates
  resolveFrame(1);
  const double cpu0 = cpuSeconds();
  const auto wall0 = std::chrono::steady_clock::now();
  for (int n = 0; n < repeat; ++n) resolveFrame(n);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = cpuSeconds() - cpu0;
  std::printf("%dx%d, %d resolves: %.1f ms wall, %.1f ms CPU per frame\n", frames[0].color.width(),
              frames[0].color.height(), repeat, 1e3 * wall / repeat, 1e3 * cpu / repeat);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "taa-resolve-bench ERROR: " << e.what() << std::endl;
    return 1;
  }
}
