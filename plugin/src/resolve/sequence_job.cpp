#include "resolve/sequence_job.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <future>
#include <optional>
#include <set>

#include "io/camera_sidecar.h"
#include "io/frame_reader.h"
#include "io/sequence_pattern.h"
#include "io/stale_temp_files.h"
#include "resolve/jitter.h"
#include "resolve/option_registry.h"
#include "resolve/resolver.h"
#include "taa/error.h"
#include "util/interruption.h"

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

// Pass-through channels minus those the resolved color is written as (the resolve wins).
io::ExtraChannels passthroughWithout(const io::ExtraChannels& all,
                                     const std::vector<std::string>& colorNames) {
  io::ExtraChannels kept;
  std::vector<std::size_t> keep;
  for (std::size_t c = 0; c < all.names.size(); ++c) {
    if (std::find(colorNames.begin(), colorNames.end(), all.names[c]) == colorNames.end()) {
      keep.push_back(c);
    }
  }
  if (keep.empty()) return kept;
  kept.image = Image(all.image.width, all.image.height, int(keep.size()));
  for (std::size_t c : keep) {
    kept.names.push_back(all.names[c]);
    kept.formats.push_back(all.formats[c]);
  }
  for (std::size_t i = 0, n = std::size_t(kept.image.width) * kept.image.height; i < n; ++i) {
    for (std::size_t k = 0; k < keep.size(); ++k) {
      kept.image.pixels[i * keep.size() + k] = all.image.pixels[i * all.names.size() + keep[k]];
    }
  }
  return kept;
}

// The frame's jitter from the job's source.
glm::vec2 jitterOf(const SequenceJob& job, const io::FrameData& data,
                   const io::CameraSidecar* sidecar) {
  switch (job.jitterSource) {
    case JobJitterSource::Options: return frameJitter(data.frame, job.resolve.jitter);
    case JobJitterSource::Sidecar: return sidecar->jitter(data.frame);
    case JobJitterSource::HeaderAttribute: break;
  }
  const OIIO::ParamValue* value = data.colorSpec.find_attribute(job.jitterAttribute);
  if (!value || value->type().basetype != OIIO::TypeDesc::FLOAT ||
      value->type().numelements() * value->type().aggregate != 2) {
    throw Error("the color header has no jitter attribute " + job.jitterAttribute +
                    " of two floats (v2f, pixels, y down)",
                {data.colorPath, data.frame, ""});
  }
  const float* xy = static_cast<const float*>(value->data());
  return checkedJitter(glm::vec2(xy[0], xy[1]), "the header attribute " + job.jitterAttribute,
                       {data.colorPath, data.frame, ""});
}

// "name=value; ..." for every resolve option, plus the jitter source when not the options'.
std::string optionsAttribute(const SequenceJob& job) {
  std::string text;
  for (const OptionInfo& option : resolveOptionList()) {
    text += (text.empty() ? "" : "; ") + option.name + "=" +
            resolveOptionValue(job.resolve, option.name);
  }
  if (job.jitterSource == JobJitterSource::HeaderAttribute) {
    text += "; jitter-source=header:" + job.jitterAttribute;
  } else if (job.jitterSource == JobJitterSource::Sidecar) {
    text += "; jitter-source=sidecar";
  }
  return text;
}

}  // namespace

std::vector<std::string> outputChannelNames(const SequenceJob& job) {
  if (!job.outputChannels.empty()) return job.outputChannels;
  std::vector<std::string> names = job.layout.color.channels;
  if (names.size() == 3) {
    // "ViewLayer.Combined.R" -> "ViewLayer.Combined.A"; "R" -> "A".
    const std::string& red = names[0];
    const std::size_t dot = red.rfind('.');
    names.push_back(dot == std::string::npos ? "A" : red.substr(0, dot + 1) + "A");
  }
  return names;
}

void validateSequenceJob(const SequenceJob& job) {
  if (job.frames.empty()) throw Error("no frames to resolve", {job.layout.color.pattern});
  for (std::size_t i = 1; i < job.frames.size(); ++i) {
    if (job.frames[i] <= job.frames[i - 1]) {  // e.g. --frames 5-1: history needs frame - 1 first
      throw Error("frames must ascend: " + std::to_string(job.frames[i]) + " follows " +
                      std::to_string(job.frames[i - 1]) +
                      " (history is built forward in time; list the frames in ascending order)",
                  {job.layout.color.pattern, job.frames[i], ""});
    }
  }
  if (job.ioThreads < 0 || job.ioThreads > kMaxIoThreads) {
    throw Error("threads must be 0 to " + std::to_string(kMaxIoThreads) + ", got " +
                std::to_string(job.ioThreads));
  }
  if (job.outputPattern.empty()) throw Error("no output given (use -o PATTERN)");
  if (job.frames.size() > 1 && !io::hasFramePlaceholder(job.outputPattern)) {
    throw Error("output pattern has no frame number placeholder (#, @ or %0Nd) but " +
                    std::to_string(job.frames.size()) + " frames are resolved",
                {job.outputPattern});
  }
  if (job.jitterSource == JobJitterSource::Sidecar && job.cameraSidecar.empty()) {
    throw Error("jitter from the sidecar needs a camera sidecar (--camera-sidecar FILE)");
  }
  if (outputChannelNames(job).size() != 4) {
    throw Error("the output needs 4 color channel names (--out-ch R,G,B,A)");
  }
  if (!job.cameraSidecar.empty()) {
    // Every frame must have its entry before any frame is written.
    const io::CameraSidecar sidecar = io::CameraSidecar::load(job.cameraSidecar);
    for (int frame : job.frames) {
      if (job.jitterSource == JobJitterSource::Sidecar) sidecar.jitter(frame);
      sidecar.frame(frame);
    }
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
  const io::StaleTemporaries stale = io::removeStaleTemporaries(job.outputPattern);
  if (callbacks.log) {
    for (const auto& path : stale.removed) callbacks.log("removed a dead run's temporary " + path);
    for (const auto& why : stale.failed) callbacks.log("cannot remove a dead run's file " + why);
  }
  std::optional<io::CameraSidecar> sidecar;
  if (!job.cameraSidecar.empty()) sidecar = io::CameraSidecar::load(job.cameraSidecar);
  io::CameraInputs cameras{job.ndc, sidecar ? &*sidecar : nullptr};
  io::WriteOptions write = job.write;
  write.rgbaNames = outputChannelNames(job);
  const std::string options = optionsAttribute(job);
  auto context = gl::Context::create(job.backend, callbacks.log);
  Resolver resolver(*context, job.resolve);
  resolver.setDebugOutput(job.debugLayers);

  // Frames are read ahead and written behind on worker threads while the GL thread resolves, so
  // decoding and encoding overlap the resolve. The resolve itself runs in frame order on this
  // thread, so the output cannot depend on timing. With ioThreads 0 the same code runs serially
  // (deferred tasks run when their result is taken). Queues are bounded: memory stays constant.
  const int count = static_cast<int>(job.frames.size());
  const int inFlight = std::max(0, job.ioThreads);
  const std::launch policy = inFlight > 0 ? std::launch::async : std::launch::deferred;
  std::deque<std::future<io::FrameData>> reads;
  int nextRead = 0;
  std::deque<std::pair<std::future<void>, FrameReport>> writes;
  auto finishOldestWrite = [&] {
    writes.front().first.get();
    if (callbacks.frameDone) callbacks.frameDone(writes.front().second);
    writes.pop_front();
  };

  int lastWidth = 0, lastHeight = 0;
  for (int index = 0; index < count; ++index) {
    if (callbacks.stopRequested && callbacks.stopRequested()) {
      while (!writes.empty()) finishOldestWrite();  // frames in flight end complete
      throw Stopped("stopped after " + std::to_string(index) + " of " + std::to_string(count) +
                    " frames; those are written completely and nothing partial is left");
    }
    for (; nextRead < count && nextRead <= index + inFlight; ++nextRead) {
      const int frame = job.frames[nextRead];
      reads.push_back(std::async(policy, [&job, frame, cameras] {
        return io::readFrame(job.layout, frame, cameras);
      }));
    }
    const int frame = job.frames[index];
    FrameReport report;
    report.index = index;
    report.count = count;
    report.frame = frame;
    // Motion vectors point to frame - 1: any other predecessor makes history meaningless.
    report.historyReset =
        index == 0 || job.frames[index - 1] != frame - 1 || job.resetFrames.count(frame) > 0;
    if (report.historyReset) resolver.resetHistory();

    io::FrameData data = reads.front().get();
    reads.pop_front();
    // The resolver restarts history at a new size; say so (FrameReport::sizeChanged).
    report.width = data.color.width();
    report.height = data.color.height();
    report.sizeChanged = index > 0 && (report.width != lastWidth || report.height != lastHeight);
    report.historyReset = report.historyReset || report.sizeChanged;
    lastWidth = report.width;
    lastHeight = report.height;
    report.inputPath = data.colorPath;
    report.outputPath = io::expandFramePattern(job.outputPattern, frame);
    report.motionPath = data.motionPath;
    report.nonFiniteColorValues = data.nonFiniteColorValues;
    report.nonFiniteMotionValues = data.nonFiniteMotionValues;
    const SampleType outputType = io::outputSampleType(write, data.colorSpec);
    report.clampedColorValues = outputType == SampleType::Half ? data.colorValuesBeyondHalf : 0;
    if (callbacks.frameRead) callbacks.frameRead(report);
    ResolveInput input;
    input.color = &data.color;
    input.depth = data.depth.empty() ? nullptr : &data.depth;
    input.motion = data.motion.empty() ? nullptr : &data.motion;
    input.jitter = jitterOf(job, data, sidecar ? &*sidecar : nullptr);
    input.camera = data.camera ? &*data.camera : nullptr;
    input.window = data.window;
    input.ndc = data.ndc;
    OIIO::ImageSpec spec = data.colorSpec;
    // Read back in the type the file gets: a half output goes from GL to the encoder as is.
    TypedImage output = [&] {
      try {
        return resolver.resolve(input, outputType);
      } catch (const Error& e) {
        throw Error(e.description(), {data.colorPath, frame, e.context().channel});
      }
    }();

    report.cutDetected = resolver.lastFrameWasCut();
    spec.attribute("taa:version", TAA_VERSION_STRING);
    spec.attribute("taa:options", options);
    io::ExtraChannels extra = passthroughWithout(data.passthrough, write.rgbaNames);
    if (job.debugLayers) {
      io::appendExtraChannels(extra, debugChannels(resolver.lastDebug(), data.nonFiniteMask));
    }
    writes.emplace_back(
        std::async(policy,
                   [path = report.outputPath, output = std::move(output), spec = std::move(spec),
                    &write, extra = std::move(extra), frame] {
                     try {
                       io::writeExrAtomic(path, output, spec, write, extra);
                     } catch (const Error& e) {  // the writer knows the path, not the frame
                       throw Error(e.description(), {e.context().file, frame, e.context().channel});
                     }
                   }),
        report);
    while (int(writes.size()) > inFlight) finishOldestWrite();
  }
  while (!writes.empty()) finishOldestWrite();
}

}  // namespace taa
