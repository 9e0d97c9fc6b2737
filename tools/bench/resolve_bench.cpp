// taa-resolve-bench: taatool's three stages timed apart, one after another on one thread: reading
// a few frames, resolving them over and over on the GL side (upload, passes, read-back in the
// output type), and writing the last results. In window mode (--mode window) it reads the 2K+1
// frames of one window (--frames must name at least that many) and times adding a frame to
// the ring (upload, conversion, classification) and resolving the centre frame apart. Prints CPU and wall milliseconds per frame for
// each. CPU time is the whole process's (user + system; llvmpipe's and OpenEXR's threads
// included): on a shared machine it is the steadier figure.
//   taa-resolve-bench [--repeat N] <taatool arguments: inputs, --frames, -o, resolve options>
// The outputs go to -o's pattern. Linked with taatool's ZIP codec (fast_zlib), as taatool is.
// docs/PERFORMANCE.md quotes it; whole runs, with the stages overlapped, are timed by
// scripts/benchmark.sh.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "gl/pass_profile.h"
#include "io/camera_sidecar.h"
#include "io/exr_writer.h"
#include "io/frame_reader.h"
#include "io/sequence_pattern.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"
#include "resolve/window_resolver.h"
#include "taa/error.h"
#include "process_time.h"

namespace {

using taa::bench::cpuSeconds;

// "<cpu> ms CPU (<wall> ms wall)" per run of `work`, run `count` times.
std::string timePerRun(int count, const std::function<void(int)>& work) {
  const double cpu0 = cpuSeconds();
  const auto wall0 = std::chrono::steady_clock::now();
  for (int n = 0; n < count; ++n) work(n);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = cpuSeconds() - cpu0;
  char text[64];
  std::snprintf(text, sizeof text, "%.1f ms CPU (%.1f ms wall)", 1e3 * cpu / count,
                1e3 * wall / count);
  return text;
}

taa::ResolveInput inputOf(const taa::io::FrameData& data) {
  taa::ResolveInput input;
  input.color = &data.color;
  input.depth = data.depth.empty() ? nullptr : &data.depth;
  input.motion = data.motion.empty() ? nullptr : &data.motion;
  input.jitter = taa::frameJitter(data.frame, taa::JitterOptions{});
  input.camera = data.camera ? &*data.camera : nullptr;
  input.window = data.window;
  input.ndc = data.ndc;
  return input;
}

// Window mode: one window's frames read, added to the ring, and its centre resolved.
int runWindow(const taa::SequenceJob& job, int repeat, const taa::io::CameraInputs& cameras) {
  using namespace taa;
  const int size = 2 * job.resolve.window.radius + 1;
  if (int(job.frames.size()) < size) {
    throw Error("window mode needs --frames to name at least 2K+1 = " + std::to_string(size) +
                " frames");
  }
  std::vector<io::FrameData> frames(static_cast<std::size_t>(size));
  const std::string read = timePerRun(size, [&](int n) {
    frames[std::size_t(n)] = io::readFrame(job.layout, job.frames[std::size_t(n)], cameras);
  });
  auto context = gl::Context::create(job.backend);
  WindowResolver resolver(*context, job.resolve);
  const int first = frames.front().frame, last = frames.back().frame;
  const int centre = frames[std::size_t(size / 2)].frame;
  auto fill = [&] {
    for (const io::FrameData& data : frames) resolver.addFrame(data.frame, inputOf(data));
  };
  fill();  // compiles the programs and allocates the ring
  resolver.resolve(centre, first, last, SampleType::Float);
  resolver.clear();
  const std::string add = timePerRun(size, [&](int n) {
    resolver.addFrame(frames[std::size_t(n)].frame, inputOf(frames[std::size_t(n)]));
  });
  io::WriteOptions write = job.write;
  write.rgbaNames = outputChannelNames(job);
  const SampleType outputType = io::outputSampleType(write, frames[0].colorSpec);
  // The first resolve of a window classifies its frames; the repeats time the gather alone,
  // as taatool's steady state is (one new frame classified per output).
  resolver.resolve(centre, first, last, outputType);
  const std::string resolve = timePerRun(repeat, [&](int) {
    resolver.resolve(centre, first, last, outputType);
  });
  std::printf("%dx%d, window K=%d: read %s per frame; add to the ring %s per frame; resolve %s "
              "over %d resolves\n",
              frames[0].color.width(), frames[0].color.height(), job.resolve.window.radius,
              read.c_str(), add.c_str(), resolve.c_str(), repeat);
  return 0;
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
  // Cameras as taatool takes them: the sidecar's, else the headers'.
  std::optional<io::CameraSidecar> sidecar;
  if (!job.cameraSidecar.empty()) sidecar = io::CameraSidecar::load(job.cameraSidecar);
  const io::CameraInputs cameras{job.ndc, sidecar ? &*sidecar : nullptr};
  if (job.resolve.mode == ResolveMode::Window) return runWindow(job, repeat, cameras);
  const int count = int(std::min<std::size_t>(job.frames.size(), 4));
  std::vector<io::FrameData> frames(static_cast<std::size_t>(count));
  const std::string read = timePerRun(count, [&](int n) {
    frames[std::size_t(n)] = io::readFrame(job.layout, job.frames[std::size_t(n)], cameras);
  });

  auto context = gl::Context::create(job.backend);
  Resolver resolver(*context, job.resolve);
  io::WriteOptions write = job.write;
  write.rgbaNames = outputChannelNames(job);
  const SampleType outputType = io::outputSampleType(write, frames[0].colorSpec);
  auto resolveFrame = [&](int n) {
    const io::FrameData& data = frames[std::size_t(n % count)];
    ResolveInput input;
    input.color = &data.color;
    input.depth = data.depth.empty() ? nullptr : &data.depth;
    input.motion = data.motion.empty() ? nullptr : &data.motion;
    input.jitter = {0.25f, -0.25f};
    input.camera = data.camera ? &*data.camera : nullptr;
    input.window = data.window;
    input.ndc = data.ndc;
    return resolver.resolve(input, outputType);
  };
  resolveFrame(0);  // compiles the shader variants and allocates
  resolveFrame(1);
  // Each result is dropped at once, as taatool's writer drops it, so its memory is reused.
  const std::string resolve = timePerRun(repeat, [&](int n) { resolveFrame(n); });

  std::vector<TypedImage> outputs;
  for (int n = 0; n < count; ++n) outputs.push_back(resolveFrame(n));

  const std::string written = timePerRun(count, [&](int n) {
    const std::string path = io::expandFramePattern(job.outputPattern, job.frames[std::size_t(n)]);
    io::writeExrAtomic(path, outputs[std::size_t(n)], frames[std::size_t(n)].colorSpec, write);
  });
  std::printf("%dx%d, per frame: read %s; resolve %s over %d resolves; write %s\n",
              frames[0].color.width(), frames[0].color.height(), read.c_str(), resolve.c_str(),
              repeat, written.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const int status = run(std::vector<std::string>(argv + 1, argv + argc));
    if (taa::gl::passProfileOn()) {
      std::cerr << "GL passes (TAA_GL_PROFILE):\n" << taa::gl::passProfileText();
    }
    return status;
  } catch (const std::exception& e) {
    std::cerr << "taa-resolve-bench ERROR: " << e.what() << std::endl;
    return 1;
  }
}
