#include "resolve/sequence_job.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "io/frame_reader.h"
#include "io/sequence_pattern.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"
#include "taa/error.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

// Every input path of one frame, with the AOV it serves (for error messages).
std::vector<std::pair<std::string, std::string>> inputPaths(const io::AovLayout& layout,
                                                            int frame) {
  const std::string colorPath = io::expandFramePattern(layout.color.pattern, frame);
  std::vector<std::pair<std::string, std::string>> paths = {{colorPath, "color"}};
  auto add = [&](const std::optional<io::AovSource>& aov, const char* name) {
    if (!aov) return;
    paths.emplace_back(aov->pattern.empty() ? colorPath
                                            : io::expandFramePattern(aov->pattern, frame),
                       name);
  };
  add(layout.depth, "depth");
  add(layout.motion, "motion");
  return paths;
}

// Paths compare equal when they name the same file, whether or not it exists yet.
std::string canonical(const std::string& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? path : result.string();
}

// The resolver's diagnostics and the input's NaN/Inf mask as extra output channels.
io::ExtraChannels debugChannels(const Image& debug, const Image& nonFiniteMask) {
  io::ExtraChannels extra;
  extra.names = {"debug.historyWeight", "debug.rejection", "debug.velocity.x", "debug.velocity.y",
                 "debug.nonFinite"};
  extra.image = Image(debug.width, debug.height, 5);
  for (std::size_t i = 0, n = std::size_t(debug.width) * debug.height; i < n; ++i) {
    std::copy_n(&debug.pixels[4 * i], 4, &extra.image.pixels[5 * i]);
    extra.image.pixels[5 * i + 4] = nonFiniteMask.empty() ? 0.0f : nonFiniteMask.pixels[i];
  }
  return extra;
}

}  // namespace

void validateSequenceJob(const SequenceJob& job) {
  if (job.frames.empty()) throw Error("no frames to resolve", {job.layout.color.pattern});
  if (job.outputPattern.empty()) throw Error("no output given (use -o PATTERN)");
  if (job.frames.size() > 1 && !io::hasFramePlaceholder(job.outputPattern)) {
    throw Error("output pattern has no frame number placeholder (#, @ or %0Nd) but " +
                    std::to_string(job.frames.size()) + " frames are resolved",
                {job.outputPattern});
  }
  std::set<std::string> inputs;
  for (int frame : job.frames) {
    for (const auto& [path, aov] : inputPaths(job.layout, frame)) {
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) {
        throw Error("missing input frame", {path, frame, aov});
      }
      inputs.insert(canonical(path));
    }
  }
  for (int frame : job.frames) {
    const std::string output = io::expandFramePattern(job.outputPattern, frame);
    if (inputs.count(canonical(output))) {
      throw Error("output would overwrite an input file", {output, frame});
    }
  }
}

void runSequenceJob(const SequenceJob& job, const JobCallbacks& callbacks) {
  validateSequenceJob(job);
  auto context = gl::Context::create(job.backend, callbacks.log);
  Resolver resolver(*context, job.resolve);
  resolver.setDebugOutput(job.debugLayers);

  const int count = static_cast<int>(job.frames.size());
  for (int index = 0; index < count; ++index) {
    const int frame = job.frames[index];
    FrameReport report;
    report.index = index;
    report.count = count;
    report.frame = frame;
    // Motion vectors point to frame - 1: any other predecessor makes history meaningless.
    report.historyReset =
        index == 0 || job.frames[index - 1] != frame - 1 || job.resetFrames.count(frame) > 0;
    if (report.historyReset) resolver.resetHistory();

    io::FrameData data = io::readFrame(job.layout, frame);
    ResolveInput input;
    input.color = &data.color;
    input.depth = data.depth.empty() ? nullptr : &data.depth;
    input.motion = data.motion.empty() ? nullptr : &data.motion;
    input.jitter = frameJitter(frame, job.resolve.jitter);
    input.camera = data.camera ? &*data.camera : nullptr;
    input.window = data.window;
    input.ndc = job.ndc;
    Image output;
    try {
      output = resolver.resolve(input);
    } catch (const Error& e) {
      throw Error(e.description(), {data.colorPath, frame, e.context().channel});
    }

    report.cutDetected = resolver.lastFrameWasCut();
    report.inputPath = data.colorPath;
    report.outputPath = io::expandFramePattern(job.outputPattern, frame);
    report.nonFiniteColorValues = data.nonFiniteColorValues;
    OIIO::ImageSpec spec = data.colorSpec;
    spec.attribute("taa:version", TAA_VERSION_STRING);
    io::writeExrAtomic(report.outputPath, output, spec, job.write,
                       job.debugLayers ? debugChannels(resolver.lastDebug(), data.nonFiniteMask)
                                       : io::ExtraChannels{});
    if (callbacks.frameDone) callbacks.frameDone(report);
  }
}

}  // namespace taa
