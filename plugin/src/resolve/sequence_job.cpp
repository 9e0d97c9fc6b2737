#include "resolve/sequence_job.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "color/ocio_bracket.h"
#include "io/camera_sidecar.h"
#include "io/file_presence.h"
#include "io/frame_reader.h"
#include "io/nearest_files.h"
#include "io/sequence_pattern.h"
#include "io/sequence_scan.h"
#include "io/stale_temp_files.h"
#include "io/views.h"
#include "resolve/jitter.h"
#include "resolve/option_registry.h"
#include "resolve/pass_band_stream.h"
#include "resolve/pass_plan.h"
#include "resolve/projection_jitter.h"
#include "resolve/frame_queues.h"
#include "resolve/resolver.h"
#include "resolve/window_budget.h"
#include "resolve/window_plan.h"
#include "resolve/window_resolver.h"
#include "taa/error.h"
#include "util/frame_buffer_pool.h"
#include "util/frame_span.h"
#include "util/interruption.h"
#include "util/usable_cores.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

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
    case JobJitterSource::Auto:
      if (sidecar && sidecar->frame(data.frame).jitter) return *sidecar->frame(data.frame).jitter;
      return data.noteJitter ? *data.noteJitter : frameJitter(data.frame, job.resolve.jitter);
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

// Where a frame's camera and jitter came from, for verbose output.
std::string cameraSourceText(const SequenceJob& job, const io::FrameData& data,
                             const io::CameraSidecar* sidecar) {
  std::string camera;
  switch (data.cameraOrigin) {
    case io::CameraOrigin::Sidecar: camera = "the camera sidecar"; break;
    case io::CameraOrigin::Note: camera = "the color header's camera note (Note)"; break;
    case io::CameraOrigin::HeaderMatrices: camera = "the color header's worldToCamera/worldToNDC";
      break;
    case io::CameraOrigin::None: camera = "nowhere (no matrices: motion vectors only)"; break;
  }
  std::string jitter;
  const bool halton = job.resolve.jitter.source == JitterSource::Halton;
  switch (job.jitterSource) {
    case JobJitterSource::Auto:
      if (sidecar && sidecar->frame(data.frame).jitter) {
        jitter = "the camera sidecar";
      } else {
        jitter = data.noteJitter ? "the color header's camera note"
                 : halton        ? "Halton(2,3) (no camera note or sidecar jitter)"
                                 : "none (no camera note or sidecar jitter)";
      }
      break;
    case JobJitterSource::Options: jitter = halton ? "Halton(2,3)" : "none"; break;
    case JobJitterSource::HeaderAttribute: jitter = "the header attribute " + job.jitterAttribute;
      break;
    case JobJitterSource::Sidecar: jitter = "the camera sidecar"; break;
  }
  return "camera from " + camera + ", jitter from " + jitter;
}

}  // namespace

std::string outputOptionsAttribute(const SequenceJob& job) {
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
  // Passes: whether they are resolved, and by which rules (a resumed run must not take a frame
  // of the colour alone for one with its passes).
  if (job.layout.passes && job.resolve.mode == ResolveMode::Window) {
    text += "; passes=";
    const std::vector<io::ChannelKindRule> rules = io::passRulesOf(job.layout);
    if (rules.empty()) text += "by-name";
    for (std::size_t r = 0; r < rules.size(); ++r) {
      text += (r ? "," : "") + rules[r].pattern + "=" + io::kindName(rules[r].kind);
    }
  }
  // The views resolved: a file of one view is not a complete frame of a run over both.
  for (std::size_t v = 0; v < job.views.size(); ++v) {
    text += (v == 0 ? "; views=" : ",") + job.views[v].name;
  }
  return text;
}

std::vector<InputFile> frameInputFiles(const io::AovLayout& layout, int frame) {
  const std::string colorPath = io::expandFramePattern(layout.color.pattern, frame);
  std::vector<InputFile> files = {{colorPath, "color"}};
  auto add = [&](const std::optional<io::AovSource>& aov, const char* name) {
    if (!aov) return;
    files.push_back({aov->pattern.empty() ? colorPath : io::expandFramePattern(aov->pattern, frame),
                     name});
  };
  add(layout.depth, "depth");
  add(layout.motion, "motion");
  return files;
}

namespace {

// `names` of a view's channels as the output names them: with the view in them for a view of
// a file of one part per view but the first (io::AovLayout::partView), as they are otherwise.
std::vector<std::string> outputNamesOfView(std::vector<std::string> names,
                                           const io::AovLayout& layout) {
  if (layout.partView.empty()) return names;
  for (std::string& name : names) name = io::viewChannelName(name, layout.partView);
  return names;
}

// The colour's names in the layout's part, alpha included (a view's, or the job's): --out-ch,
// else the input's.
std::vector<std::string> colourNamesOf(const SequenceJob& job, const io::AovLayout& layout) {
  if (!job.outputChannels.empty()) return job.outputChannels;
  std::vector<std::string> names = layout.color.channels;
  if (names.size() == 3) {
    // "ViewLayer.Combined.R" -> "ViewLayer.Combined.A"; "R" -> "A".
    const std::string& red = names[0];
    const std::size_t dot = red.rfind('.');
    names.push_back(dot == std::string::npos ? "A" : red.substr(0, dot + 1) + "A");
  }
  return names;
}

// The output's colour names for one layout (a view's, or the job's).
std::vector<std::string> outputChannelNamesOf(const SequenceJob& job, const io::AovLayout& layout) {
  return outputNamesOfView(colourNamesOf(job, layout), layout);
}

}  // namespace

std::vector<std::string> outputChannelNames(const SequenceJob& job) {
  return outputChannelNamesOf(job, job.views.empty() ? job.layout : job.views.front().layout);
}

std::vector<int> availableInputFrames(const io::AovLayout& layout) {
  std::vector<int> frames;
  for (int frame : io::scanExistingFrames(layout.color.pattern)) {
    bool complete = true;
    for (const InputFile& input : frameInputFiles(layout, frame)) {
      std::error_code ec;
      complete = complete && fs::is_regular_file(input.path, ec);
    }
    if (complete) frames.push_back(frame);
  }
  return frames;
}

void validateSequenceJob(const SequenceJob& job) {
  if (job.frames.empty()) throw Error("no frames to resolve", {job.layout.color.pattern});
  if (job.outputPattern.empty()) throw Error("no output given (use -o PATTERN)");
  for (std::size_t i = 1; i < job.frames.size(); ++i) {
    if (job.frames[i] <= job.frames[i - 1]) {  // e.g. --frames 5-1: history needs frame - 1 first
      throw Error("frames must ascend: " + std::to_string(job.frames[i]) + " follows " +
                      std::to_string(job.frames[i - 1]) +
                      " (history is built forward in time; list the frames in ascending order)",
                  {job.layout.color.pattern, job.frames[i], ""});
    }
  }
  if (job.resolve.mode == ResolveMode::Window && job.resolve.cutDetection > 0.0f) {
    // Detection judges a frame by how much of the history it rejects; a window has no history.
    throw Error("--cut-detection is a history-mode stage: in window mode give the shot's cuts "
                "with --reset-frames (a window never crosses them)");
  }
  for (int frame : job.prerollFrames) {
    if (job.resolve.mode == ResolveMode::Window) {
      throw Error("pre-roll frames are for the history resolve: a window frame needs none",
                  {job.layout.color.pattern, frame, ""});
    }
    if (std::find(job.frames.begin(), job.frames.end(), frame) == job.frames.end()) {
      throw Error("pre-roll frame " + std::to_string(frame) + " is not among the frames resolved",
                  {job.layout.color.pattern, frame, ""});
    }
  }
  if ((job.ioThreads < 0 && job.ioThreads != kAutoIoThreads) || job.ioThreads > kMaxIoThreads) {
    throw Error("threads must be 0 to " + std::to_string(kMaxIoThreads) + ", got " +
                std::to_string(job.ioThreads));
  }
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
    for (const InputFile& input : frameInputFiles(job.layout, frame)) {
      if (const std::string absence = io::fileAbsence(input.path); !absence.empty()) {
        throw Error(absence == "missing" ? "missing input frame: " + io::patternMissText(input.path)
                                         : "input frame is " + absence,
                    {input.path, frame, input.aov});
      }
      inputs.insert(canonical(input.path));
    }
  }
  for (int frame : job.frames) {
    if (job.prerollFrames.count(frame)) continue;  // never written
    const std::string output = io::expandFramePattern(job.outputPattern, frame);
    if (inputs.count(canonical(output))) {
      throw Error("output would overwrite an input file", {output, frame});
    }
  }
}

namespace {

// Threads a read the resolve waits for decodes on, at most: a 1080p band is 32 rows, so more
// threads would share too few bands (and a node's cores are the farm's).
constexpr int kMaxDecodeThreads = 8;

// What both strategies share while running a job: inputs, outputs, the writer.
struct JobRun {
  const SequenceJob& job;
  const JobCallbacks& callbacks;
  std::optional<io::CameraSidecar> sidecar;
  io::CameraInputs cameras;
  io::WriteOptions write;
  std::string options;
  color::OutputColorspace colorspace;  // the output's, said in its header
  // What the job reads: each view's layout (a multi-view job), or the job's own; and each
  // view's output colour names (the first view's are write.rgbaNames).
  std::vector<const io::AovLayout*> layouts;
  std::vector<std::vector<std::string>> viewNames;

  JobRun(const SequenceJob& j, const JobCallbacks& c)
      : job(j), callbacks(c), colorspace(color::outputColorspace(j.resolve.color)) {
    if (!job.cameraSidecar.empty()) sidecar = io::CameraSidecar::load(job.cameraSidecar);
    // The note is read unless both the camera and the jitter are given explicitly.
    const bool jitterGiven = job.jitterSource != JobJitterSource::Auto;
    cameras = {job.ndc, sidecar ? &*sidecar : nullptr, !(sidecar && jitterGiven)};
    write = job.write;
    for (const JobView& view : job.views) {
      layouts.push_back(&view.layout);
      write.views.push_back(view.name);
    }
    if (layouts.empty()) layouts.push_back(&job.layout);
    for (const io::AovLayout* layout : layouts) {
      viewNames.push_back(outputChannelNamesOf(job, *layout));
    }
    write.rgbaNames = viewNames.front();
    options = outputOptionsAttribute(job);
  }

  // View `v` of a frame read by read().
  static const io::FrameData& view(const io::FrameData& data, std::size_t v) {
    return v == 0 ? data : data.otherViews[v - 1];
  }
  // The type view `v` is resolved into and written as (its colour's type in its part).
  SampleType outputTypeOf(const io::FrameData& data, std::size_t v) const {
    io::WriteOptions viewWrite = write;
    viewWrite.rgbaNames = colourNamesOf(job, *layouts[v]);
    return io::outputSampleType(viewWrite, view(data, v).colorSpec);
  }

  // Reads a frame, every view of it; a projection that carries the frame's jitter gets it
  // taken out. A read the resolve waits for (no frames read ahead: a window run with passes,
  // or --threads 0) decodes on every core it may use; one beside the GL's work on one.
  io::FrameData read(int frame, bool callerWaits) const {
    const int decodeThreads = callerWaits ? std::min(usableCores(), kMaxDecodeThreads) : 1;
    io::FrameData data = readView(*layouts[0], frame, decodeThreads);
    for (std::size_t v = 1; v < layouts.size(); ++v) {
      data.otherViews.push_back(readView(*layouts[v], frame, decodeThreads));
    }
    if (layouts.size() > 1) requireCamerasOfTheirOwn(data);
    return data;
  }

  io::FrameData readView(const io::AovLayout& layout, int frame, int decodeThreads) const {
    // The window resolve packs the passes for its ring as they are decoded, band by band, on
    // the reader's thread: the frame's pass channels are never held whole as float (590 MB
    // for a 1080p Cycles render with every pass), and the frame waits for the ring holding
    // its packed values (about half that).
    PassPlan plan;
    PackedPasses packed;
    io::PassBandReceiver passBands;
    if (job.resolve.mode == ResolveMode::Window) {
      passBands = [&](const io::ExtraChannels& passes, int width, int height) {
        plan = planPasses(io::passPlanNames(passes.names, layout), passes.formats,
                          io::passRulesOf(layout));
        packed = newPackedPasses(plan, width, height);
        return [&](std::size_t firstPixel, std::size_t count, const float* values) {
          packPassRows(values, firstPixel, count, plan, packed);
        };
      };
    }
    io::FrameData data = io::readFrame(layout, frame, cameras, passBands, decodeThreads);
    if (!data.passes.names.empty() && passBands) {
      data.passGroups = std::move(packed.groups);
      data.passCryptomatte = std::move(packed.cryptomatte);
      data.passes.image = std::move(packed.kept);
    }
    if (data.camera) {
      const glm::vec2 jitter = jitterOf(job, data, sidecar ? &*sidecar : nullptr);
      if (auto corrected = withoutJitterInProjection(*data.camera, jitter, data.window, data.ndc)) {
        data.camera = *corrected;
        data.jitterTakenOutOfProjection = true;
      }
    }
    return data;
  }

  // Each eye has a camera of its own: one camera the views share (a sidecar entry, the header
  // of the one part they live in) fits one of them at most, silently. Resolving one view at a
  // time, each with its own camera, is the way.
  void requireCamerasOfTheirOwn(const io::FrameData& data) const {
    for (std::size_t v = 0; v < layouts.size(); ++v) {
      const io::FrameData& d = view(data, v);
      if (!d.camera) continue;
      bool shared = d.cameraOrigin == io::CameraOrigin::Sidecar;
      for (std::size_t w = 0; w < layouts.size(); ++w) {
        const io::FrameData& other = view(data, w);
        shared = shared || (w != v && other.colorPath == d.colorPath &&
                            other.colorPart == d.colorPart);
      }
      if (!shared) continue;
      std::string views;
      for (const std::string& name : write.views) views += (views.empty() ? "" : ", ") + name;
      throw Error("the views " + views + " would share one camera (" +
                      cameraSourceText(job, d, sidecar ? &*sidecar : nullptr) +
                      "), and each eye has its own: resolve one view at a time (--view NAME), "
                      "each with its own camera",
                  {d.colorPath, d.frame, ""});
    }
  }

  ResolveInput inputOf(const io::FrameData& data, bool tell = true) const {
    if (tell) tellCameraSource(data);
    ResolveInput input;
    input.color = &data.color;
    input.depth = data.depth.empty() ? nullptr : &data.depth;
    input.motion = data.motion.empty() ? nullptr : &data.motion;
    input.jitter = jitterOf(job, data, sidecar ? &*sidecar : nullptr);
    input.camera = data.camera ? &*data.camera : nullptr;
    input.window = data.window;
    input.ndc = data.ndc;
    return input;
  }

  // Verbose output says where the camera and jitter came from: for the first frame, then for
  // each frame where that changes. Called in frame order, on the GL thread.
  mutable std::string lastCameraSource;
  void tellCameraSource(const io::FrameData& data) const {
    if (!callbacks.detail) return;
    std::string source = cameraSourceText(job, data, sidecar ? &*sidecar : nullptr);
    if (data.jitterTakenOutOfProjection) source += " (the jitter taken out of the projection)";
    if (source == lastCameraSource) return;
    callbacks.detail("frame " + std::to_string(data.frame) + ": " + source);
    lastCameraSource = std::move(source);
  }

  // Errors of the resolve name the frame's colour file, but for one `namedElsewhere` holds by
  // then: an earlier frame's failed write met during this resolve, which names its own file.
  template <typename F>
  auto resolveNaming(const io::FrameData& data, F resolve,
                     const std::exception_ptr* namedElsewhere = nullptr) const {
    try {
      return resolve();
    } catch (const Error& e) {
      if (namedElsewhere && *namedElsewhere) std::rethrow_exception(*namedElsewhere);
      throw Error(e.description(), {data.colorPath, data.frame, e.context().channel});
    }
  }

  // The output file of a frame: the input's header plus taa's attributes, pass-through
  // channels, then the diagnostics.
  std::function<void()> writeOf(const io::FrameData& data, TypedImage output,
                                io::ExtraChannels debug,
                                const std::vector<TypedImage>& otherViews = {},
                                std::vector<io::ExtraChannels> passes = {}) const {
    OIIO::ImageSpec spec = data.colorSpec;
    spec.attribute("taa:version", TAA_VERSION_STRING);
    spec.attribute("taa:options", options);
    spec.attribute("taa:colorspace", colorspace.colorspace);
    spec.attribute("taa:ocioConfig", colorspace.config);
    // The other views' colour after the first's, each in its own type; the resolve's names win
    // over pass-through channels of the same name.
    io::ExtraChannels extra;
    std::vector<std::string> colorNames = write.rgbaNames;
    for (std::size_t v = 1; v < viewNames.size(); ++v) {
      const TypedImage& image = otherViews.at(v - 1);
      io::ExtraChannels viewChannels;
      viewChannels.names = viewNames[v];
      viewChannels.image = image.toFloat();  // half widens exactly and is written as half
      viewChannels.formats.assign(4, image.type() == SampleType::Half ? OIIO::TypeHalf
                                                                      : OIIO::TypeFloat);
      io::appendExtraChannels(extra, viewChannels);
      colorNames.insert(colorNames.end(), viewNames[v].begin(), viewNames[v].end());
    }
    io::appendExtraChannels(extra, passthroughWithout(data.passthrough, colorNames));
    for (io::ExtraChannels& viewPasses : passes) {
      io::appendExtraChannels(extra, std::move(viewPasses));
    }
    if (!debug.names.empty()) io::appendExtraChannels(extra, debug);
    return [path = io::expandFramePattern(job.outputPattern, data.frame),
            output = std::move(output), spec = std::move(spec), this, extra = std::move(extra),
            frame = data.frame] {
      try {
        io::writeExrAtomic(path, output, spec, write, extra);
      } catch (const Error& e) {  // the writer knows the path, not the frame
        throw Error(e.description(), {e.context().file, frame, e.context().channel});
      }
    };
  }

  FrameReport reportOf(const io::FrameData& data, int index) const {
    FrameReport report;
    report.index = index;
    report.count = int(job.frames.size());
    report.frame = data.frame;
    report.inputPath = data.colorPath;
    report.preroll = job.prerollFrames.count(data.frame) > 0;
    if (!report.preroll) report.outputPath = io::expandFramePattern(job.outputPattern, data.frame);
    report.motionPath = data.motionPath;
    report.width = data.color.width();
    report.height = data.color.height();
    for (std::size_t v = 0; v < layouts.size(); ++v) {  // every view's
      report.nonFiniteColorValues += view(data, v).nonFiniteColorValues;
      report.nonFiniteMotionValues += view(data, v).nonFiniteMotionValues;
    }
    report.jitterTakenOutOfProjection = data.jitterTakenOutOfProjection;
    report.noCamera = job.resolve.mode == ResolveMode::Window && !data.camera;
    const SampleType outputType = io::outputSampleType(write, data.colorSpec);
    report.clampedColorValues = outputType == SampleType::Half ? data.colorValuesBeyondHalf : 0;
    return report;
  }

  // Before each frame: a stop asked for (SIGINT/SIGTERM in taatool) ends the job here, once the
  // frames in flight are written.
  void stopIfAsked(WriteBehind& writes, int done) const {
    if (!callbacks.stopRequested || !callbacks.stopRequested()) return;
    writes.finish();
    throw Stopped("stopped after " + std::to_string(done) + " of " +
                  std::to_string(job.frames.size()) +
                  " frames; those are written completely and nothing partial is left");
  }
};

// The recursive history resolve: frames in order, each blended into the last one's history.
void runHistory(JobRun& run, gl::Context& context) {
  const SequenceJob& job = run.job;
  // One history per view: each view is resolved as if alone.
  std::vector<std::unique_ptr<Resolver>> resolvers;
  for (std::size_t v = 0; v < run.layouts.size(); ++v) {
    resolvers.push_back(std::make_unique<Resolver>(context, job.resolve));
    resolvers.back()->setDebugOutput(job.debugLayers);
  }
  Resolver& resolver = *resolvers.front();
  std::vector<FrameReport> reports(job.frames.size());
  ReadAhead reads(job.frames, ioDepthOf(job, false),
                  [&run](int frame, bool callerWaits) { return run.read(frame, callerWaits); });
  WriteBehind writes(ioDepthOf(job, false), [&](int index) {
    if (run.callbacks.frameDone) run.callbacks.frameDone(reports[std::size_t(index)]);
  });
  int lastWidth = 0, lastHeight = 0;
  for (int index = 0; index < int(job.frames.size()); ++index) {
    run.stopIfAsked(writes, index);
    const int frame = job.frames[std::size_t(index)];
    const io::FrameData data = reads.next();
    FrameReport& report = reports[std::size_t(index)] = run.reportOf(data, index);
    // Motion vectors point to frame - 1: any other predecessor makes history meaningless. The
    // resolver restarts history at a new size too; the report says so.
    report.sizeChanged = index > 0 && (report.width != lastWidth || report.height != lastHeight);
    report.historyReset = index == 0 || !isNextFrame(job.frames[std::size_t(index) - 1], frame) ||
                          job.resetFrames.count(frame) > 0 || report.sizeChanged;
    lastWidth = report.width;
    lastHeight = report.height;
    if (report.historyReset) {
      for (auto& r : resolvers) r->resetHistory();
    }
    if (run.callbacks.frameRead) run.callbacks.frameRead(report);
    // Read back in the type the file gets: a half output goes from GL to the encoder as is.
    std::vector<TypedImage> outputs;
    for (std::size_t v = 0; v < resolvers.size(); ++v) {
      const io::FrameData& viewData = JobRun::view(data, v);
      const ResolveInput input = run.inputOf(viewData, v == 0);
      outputs.push_back(run.resolveNaming(viewData, [&] {
        return resolvers[v]->resolve(input, run.outputTypeOf(data, v));
      }));
    }
    TypedImage output = std::move(outputs.front());
    outputs.erase(outputs.begin());
    report.cutDetected = resolver.lastFrameWasCut();
    if (report.preroll) {  // history only; a no-op in the queue keeps frameDone in order
      writes.push([] {}, index);
      continue;
    }
    io::ExtraChannels debug;
    if (job.debugLayers) debug = debugChannels(resolver.lastDebug(), data.nonFiniteMask);
    writes.push(run.writeOf(data, std::move(output), std::move(debug), outputs), index);
  }
  writes.finish();
}

// The window resolve's diagnostics and the input's NaN/Inf mask as extra output channels.
io::ExtraChannels windowDebugChannels(const Image& debug, const Image& nonFiniteMask) {
  io::ExtraChannels extra;
  extra.names = {"debug.sampleWeight", "debug.rejectedFraction", "debug.candidates",
                 "debug.nonFinite"};
  extra.image = Image(debug.width, debug.height, 4);
  for (std::size_t i = 0, n = std::size_t(debug.width) * debug.height; i < n; ++i) {
    std::copy_n(&debug.pixels[kWindowDebugChannels * i], kWindowDebugChannels,
                &extra.image.pixels[4 * i]);
    extra.image.pixels[4 * i + 3] = nonFiniteMask.empty() ? 0.0f : nonFiniteMask.pixels[i];
  }
  return extra;
}

// One line a kind for -v, the channels (as the file names them) in file order: a render's
// every pass is 70 names.
void describePassKinds(const PassPlan& plan, const std::vector<std::string>& names,
                       const gl::LogSink& detail) {
  std::map<std::string, std::string> byKind;
  for (std::size_t c = 0; c < plan.names.size(); ++c) {
    std::string& list = byKind[io::kindName(plan.kinds[c])];
    list += (list.empty() ? "" : ", ") + names[c];
  }
  for (const auto& [kind, list] : byKind) {
    detail("passes resolved beside the colour, " + kind + ": " + list);
  }
}

// The window's options for a run over `outputs`: the options asked for, or, where the rings
// with the passes would not fit (resolve/window_budget), the longest window that does, colour
// included so that the passes still add up to it; and never longer than the ring the GL can make
// (windowRadiusTheGlHolds). Decided from the first output's header (every frame of a run holds
// the same channels), so every chunk of a shot on one kind of machine decides alike.
ResolveOptions windowOptionsOf(const JobRun& run, gl::Context& context,
                               const std::vector<int>& outputs) {
  ResolveOptions options = run.job.resolve;
  if (outputs.empty()) return options;
  int width = 0, height = 0;
  // Every view's rings, at the size of the views with passes (a header is read only for those;
  // the views of a file share one size).
  double bytesPerPixel = 0.0, pixels = 0.0;
  bool passes = false;
  for (const io::AovLayout* layout : run.layouts) {
    const io::PassHeader header = io::readPassHeader(*layout, outputs.front());
    width = std::max(width, header.width);
    height = std::max(height, header.height);
    std::optional<PassPlan> plan;
    if (!header.channels.names.empty()) {
      passes = true;
      plan = planPasses(io::passPlanNames(header.channels.names, *layout),
                        header.channels.formats, io::passRulesOf(*layout));
      pixels = std::max(pixels, double(header.width) * double(header.height));
    }
    bytesPerPixel += ringBytesPerPixel(plan ? &*plan : nullptr);
  }
  const double frameBytes = bytesPerPixel * pixels;
  const int asked = options.window.radius;
  const int k = windowRadiusWithinBudget(asked, options.window.nearRadius, frameBytes, passes);
  if (k != asked && run.callbacks.detail) {
    run.callbacks.detail("window resolve: the rings of K " + std::to_string(asked) +
                         " with the passes would take " +
                         std::to_string(int(windowRingBytes(asked, frameBytes) / 1e6)) +
                         " MB: K " + std::to_string(k) + " instead (" +
                         std::to_string(int(windowRingBytes(k, frameBytes) / 1e6)) +
                         " MB), colour included");
  }
  // And as long as the GL can make the rings at all (llvmpipe: K 23 at 1080p, K 5 at 4K).
  const int held = windowRadiusTheGlHolds(context, k, width, height);
  if (held != k && run.callbacks.log) {
    run.callbacks.log("window resolve: the GL cannot make the ring of K " + std::to_string(k) +
                      " at " + std::to_string(width) + "x" + std::to_string(height) +
                      " (2K+2 frames in one texture, larger than its largest): K " +
                      std::to_string(held) + " instead");
  }
  options.window.radius = held;
  return options;
}

// Bands of pass sums read back and not yet packed by the writer: one, which the writer packs
// while the GL draws the next band into its own images.
constexpr int kStreamedPassBands = 1;

// One window-mode run: frames enter the views' rings as they are read (once each, in order)
// and leave when no later window needs them; each output frame is resolved from its window
// alone, its passes finished from the sums as the writer packs them.
class WindowRun {
 public:
  WindowRun(JobRun& run, gl::Context& context, std::vector<int> outputs)
      : run_(run),
        job_(run.job),
        outputs_(std::move(outputs)),
        options_(windowOptionsOf(run, context, outputs_)),
        plan_(planWindows(outputs_, job_.availableFrames, job_.resetFrames,
                          options_.window.radius)),
        reports_(outputs_.size()),
        // Whether the frames carry passes is known once the first is read: until then, one
        // read, unless --threads said how many.
        reads_(plan_.reads, firstIoDepth(job_),
               [&run](int frame, bool callerWaits) { return run.read(frame, callerWaits); }),
        writes_(firstIoDepth(job_), [this](int index) {
          if (run_.callbacks.frameDone) run_.callbacks.frameDone(reports_[std::size_t(index)]);
        }),
        passPlans_(run.layouts.size()) {
    // One ring per view: each view is resolved as if alone.
    for (std::size_t v = 0; v < run.layouts.size(); ++v) {
      resolvers_.push_back(std::make_unique<WindowResolver>(context, options_));
      resolvers_.back()->setDebugOutput(job_.debugLayers);
    }
  }

  void resolveAll() {
    for (int index = 0; index < int(outputs_.size()); ++index) {
      run_.stopIfAsked(writes_, index);
      const int frame = outputs_[std::size_t(index)];
      const FrameWindow window = plan_.windows.at(frame);
      dropFramesBefore(window.first);
      auto readsDue = [&] { return !reads_.done() && reads_.peek() <= window.last; };
      if (passBands_ && readsDue()) {
        // A frame with every pass read while the last is still written would pass the 4 GiB
        // bar at 1080p (docs/PERFORMANCE.md, "The passes streamed to the writer"): the write
        // runs beside the pass draws, the read after it.
        writes_.finish();
        passBands_->releaseIdle();
      }
      if (keptFrameToFrame_ && readsDue()) keptFrameToFrame_->nextFrame();
      while (readsDue()) addToRings(reads_.next());
      resolveAndWrite(index, window);
    }
    writes_.finish();
  }

 private:
  static int firstIoDepth(const SequenceJob& job) {
    return job.ioThreads == kAutoIoThreads ? 0 : job.ioThreads;
  }

  bool hasPasses() const {
    return std::any_of(passPlans_.begin(), passPlans_.end(),
                       [](const std::optional<PassPlan>& p) { return p && !p->empty(); });
  }

  void dropFramesBefore(int first) {
    for (auto it = inRing_.begin(); it != inRing_.end();) {
      if (*it < first) {
        for (auto& r : resolvers_) r->dropFrame(*it);
        it = inRing_.erase(it);
      } else {
        ++it;
      }
    }
  }

  // The passes (issue 21): planned from the first frame read, every frame the same channels;
  // each view its own (a multi-view file's views each resolve their passes with their own
  // weights). The reads' and writes' depth follows from them.
  void planOrCheckPasses(const io::FrameData& data) {
    for (std::size_t v = 0; v < resolvers_.size(); ++v) {
      const io::ExtraChannels& passes = JobRun::view(data, v).passes;
      const std::vector<std::string> names = io::passPlanNames(passes.names, *run_.layouts[v]);
      std::optional<PassPlan>& passPlan = passPlans_[v];
      if (!passPlan) {
        passPlan = planPasses(names, passes.formats, io::passRulesOf(*run_.layouts[v]));
        passFile_ = data.colorPath;
        resolvers_[v]->setPasses(passPlan->halfGroups, int(passPlan->cryptomatte.size()));
        if (run_.callbacks.detail) {
          describePassKinds(*passPlan, passes.names, run_.callbacks.detail);
        }
      } else if (names != passPlan->names) {
        throw Error("the frame's pass channels differ from those of " + passFile_ +
                        " (every frame of a run must hold the same channels)",
                    {data.colorPath, data.frame, ""});
      }
    }
    if (!ioDepthSet_) {
      const int depth = ioDepthOf(job_, hasPasses());
      reads_.setDepth(depth);
      // The passes streamed to the writer need the write on its own thread: one frame's, beside
      // the GL's pass draws (the frame-sized sums it saves pay for it).
      const bool streamable = resolvers_.size() == 1 && hasPasses() &&
                              passPlans_.front()->halfOrFloat && !job_.debugLayers &&
                              resolvers_.front()->canStreamPasses();
      const int writeDepth = streamable && job_.ioThreads == kAutoIoThreads ? 1 : depth;
      if (streamable && writeDepth > 0) {
        passBands_ = std::make_shared<PassBandStream>(kStreamedPassBands);
        if (run_.callbacks.detail) {
          run_.callbacks.detail("window resolve: the passes go to the writer band by band as "
                                "they are drawn, each frame written beside its pass draws");
        }
      }
      writes_.setDepth(writeDepth);
      // Each frame's buffers reuse the last's pages (the resolver keeps none with passes, for
      // its other faces); those a frame leaves idle are freed before the next read, the peak.
      if (hasPasses()) keptFrameToFrame_.emplace();
      ioDepthSet_ = true;
    }
  }

  // A frame read into every view's ring; an output frame waits for its turn without the
  // pixels the rings hold (only its headers, pass-through and kept pass channels stay).
  void addToRings(io::FrameData data) {
    const int f = data.frame;
    if (!data.camera && !toldVectorsOnly_ && run_.callbacks.detail) {
      run_.callbacks.detail("window resolve: frame " + std::to_string(f) +
                            " has no camera matrices (header or sidecar): its samples follow "
                            "their motion vectors only");
      toldVectorsOnly_ = true;
    }
    planOrCheckPasses(data);
    for (std::size_t v = 0; v < resolvers_.size(); ++v) {
      const io::FrameData& viewData = JobRun::view(data, v);
      ResolveInput input = run_.inputOf(viewData, v == 0);
      for (const TypedImage& group : viewData.passGroups) input.passGroups.emplace_back(&group);
      for (const Image& set : viewData.passCryptomatte) input.cryptomatte.emplace_back(&set);
      try {
        resolvers_[v]->addFrame(f, input);
      } catch (const Error& e) {
        throw Error(e.description(), {data.colorPath, f, e.context().channel});
      }
    }
    inRing_.push_back(f);
    if (!plan_.windows.count(f)) return;
    auto dropUploaded = [](io::FrameData& view) {
      view.passGroups.clear();
      view.passCryptomatte.clear();
      view.color = TypedImage();
      view.depth = Image();
      view.motion = Image();
    };
    dropUploaded(data);
    for (io::FrameData& other : data.otherViews) dropUploaded(other);
    waiting_.emplace(f, std::move(data));
  }

  // View `v`'s passes of the frame just resolved, in the file's order and types: finished from
  // the sums band by band as the writer packs them.
  io::ExtraChannels finishedPasses(io::FrameData& data, std::size_t v) {
    io::FrameData& viewData = v == 0 ? data : data.otherViews[v - 1];
    io::ExtraChannels passes = std::move(viewData.passes);
    passes.names = outputNamesOfView(std::move(passes.names), *run_.layouts[v]);
    const std::optional<PassPlan>& passPlan = passPlans_[v];
    if (!passPlan || passPlan->empty()) return passes;
    if (passPlan->halfOrFloat) {
      passes.packed = finishPassesPacked(resolvers_[v]->takePassSums(), std::move(passes.image),
                                         *passPlan);
      passes.image = Image();
    } else {
      passes.image = finishPasses(resolvers_[v]->takePassSums(), passes.image, *passPlan);
    }
    return passes;
  }

  void resolveAndWrite(int index, const FrameWindow& window) {
    const int frame = outputs_[std::size_t(index)];
    io::FrameData data = std::move(waiting_.at(frame));
    waiting_.erase(frame);
    FrameReport& report = reports_[std::size_t(index)] = run_.reportOf(data, index);
    report.historyReset = plan_.shotStarts.count(frame) > 0;
    if (run_.callbacks.frameRead) run_.callbacks.frameRead(report);
    // Pass-through channels would be joined with the passes, which unpacks them whole first.
    if (passBands_ && data.passthrough.names.empty()) {
      return resolveStreamingAndWrite(index, window, std::move(data));
    }
    std::vector<TypedImage> views;
    std::vector<io::ExtraChannels> passes;
    for (std::size_t v = 0; v < resolvers_.size(); ++v) {
      views.push_back(run_.resolveNaming(JobRun::view(data, v), [&] {
        return resolvers_[v]->resolve(frame, window.first, window.last,
                                      run_.outputTypeOf(data, v));
      }));
      passes.push_back(finishedPasses(data, v));
    }
    TypedImage output = std::move(views.front());
    views.erase(views.begin());
    io::ExtraChannels debug;
    if (job_.debugLayers) {
      debug = windowDebugChannels(resolvers_.front()->lastDebug(), data.nonFiniteMask);
    }
    writes_.push(run_.writeOf(data, std::move(output), std::move(debug), views, std::move(passes)),
                 index);
  }

  // One view's frame whose write starts once its colour is drawn, its passes packed as the
  // GL's pass bands come (resolve/pass_band_stream).
  void resolveStreamingAndWrite(int index, const FrameWindow& window, io::FrameData data) {
    const int frame = outputs_[std::size_t(index)];
    io::ExtraChannels passes = std::move(data.passes);
    passes.names = outputNamesOfView(std::move(passes.names), *run_.layouts.front());
    passes.packed = finishPassesStreamed(passBands_, frame, std::move(passes.image),
                                         *passPlans_.front(), data.colorSpec.width,
                                         data.colorSpec.height);
    passes.image = Image();
    // A failed write of an earlier frame comes out of the push: it names its own file and frame.
    std::exception_ptr writeFailed;
    const auto startWrite = [&](TypedImage colour) {
      std::vector<io::ExtraChannels> views(1);
      views.front() = std::move(passes);
      std::function<void()> write = run_.writeOf(data, std::move(colour), {}, {}, std::move(views));
      try {
        writes_.push(
            [write = std::move(write), bands = passBands_, frame] {
              // However the write ends, the GL thread is not left waiting for it to take a band.
              struct Finished {
                PassBandStream& bands;
                int frame;
                ~Finished() { bands.finished(frame); }
              } finished{*bands, frame};
              write();
            },
            index);
      } catch (...) {
        writeFailed = std::current_exception();
        throw;
      }
    };
    try {
      run_.resolveNaming(
          data,
          [&] {
            resolvers_.front()->resolveStreaming(frame, window.first, window.last,
                                                 run_.outputTypeOf(data, 0), startWrite,
                                                 *passBands_);
          },
          &writeFailed);
    } catch (...) {
      passBands_->abandon(frame);  // a write started waits for bands that will not come
      throw;
    }
  }

  JobRun& run_;
  const SequenceJob& job_;
  const std::vector<int> outputs_;  // in order
  const ResolveOptions options_;
  const WindowPlan plan_;
  std::vector<FrameReport> reports_;
  ReadAhead reads_;
  WriteBehind writes_;
  std::vector<std::unique_ptr<WindowResolver>> resolvers_;
  std::vector<std::optional<PassPlan>> passPlans_;
  std::string passFile_;  // the file the plans came from, for the message when one differs
  bool ioDepthSet_ = false;
  std::shared_ptr<PassBandStream> passBands_;  // where the passes are streamed to the writer
  std::optional<FrameBuffersKeptFrameToFrame> keptFrameToFrame_;  // with passes
  std::vector<int> inRing_;
  std::map<int, io::FrameData> waiting_;  // read output frames, pixels dropped once uploaded
  bool toldVectorsOnly_ = false;
};

void runWindow(JobRun& run, gl::Context& context) {
  std::vector<int> outputs = run.job.frames;
  std::sort(outputs.begin(), outputs.end());
  WindowRun(run, context, std::move(outputs)).resolveAll();
}

}  // namespace

int ioDepthOf(const SequenceJob& job, bool passes) {
  if (job.ioThreads != kAutoIoThreads) return job.ioThreads;
  return passes && job.resolve.mode == ResolveMode::Window ? 0 : 2;
}

void runSequenceJob(const SequenceJob& job, const JobCallbacks& callbacks) {
  // Declared first, destroyed last: the job's frame buffers go back to the system (or to the
  // host taa runs in) once every queue holding them is gone, however the job ends.
  struct FrameBuffersReleased {
    ~FrameBuffersReleased() { releaseFrameBuffers(); }
  } released;
  validateSequenceJob(job);
  const io::StaleTemporaries stale = io::removeStaleTemporaries(job.outputPattern);
  if (callbacks.log) {
    for (const auto& path : stale.removed) callbacks.log("removed a dead run's temporary " + path);
    for (const auto& why : stale.failed) callbacks.log("cannot remove a dead run's file " + why);
  }
  JobRun run(job, callbacks);
  auto context = gl::Context::create(job.backend, callbacks.log);
  if (job.resolve.mode == ResolveMode::Window) {
    runWindow(run, *context);
  } else {
    runHistory(run, *context);
  }
}

}  // namespace taa
