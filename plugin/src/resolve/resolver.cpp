#include "resolve/resolver.h"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "color/ocio_bracket.h"
#include "color/ocio_gpu_resources.h"
#include "gl/objects.h"
#include "resolve/reconstruction_filter.h"
#include "resolve/resolve_input.h"
#include "taa/error.h"

namespace taa {
namespace {

// Texture units of the resolve pass. The to-working and output passes use unit 0 for their input
// and kFirstOcioUnit onwards for their bracket's LUTs.
enum TextureUnit : int {
  kCurrentUnit = 0,
  kHistoryUnit,
  kHistoryStateUnit,
  kMotionUnit,
  kDepthUnit,
  kPreviousDepthUnit,
  kFirstOcioUnit
};
constexpr int kResolvedUnit = 0;

// Attachments of the resolve pass (locations in resolve.frag).
enum ResolveAttachment : int {
  kHistoryAttachment = 0,
  kStateAttachment,
  kDebugAttachment,
  kOutputAttachment  // when the output pass is fused into the resolve pass
};

std::string define(const char* name, int value) {
  return std::string("#define ") + name + " " + std::to_string(value);
}

// Without sharpening, which needs the neighbours' results, the resolve pass writes the output
// colour itself: a separate output pass would cost about 45 ms of CPU per 1080p frame on
// llvmpipe, for one texel fetch.
bool fusedOutput(const ResolveOptions& o) { return o.sharpen == 0.0f; }

std::vector<std::string> resolveDefines(const ResolveOptions& o) {
  return {define("FUSED_OUTPUT", fusedOutput(o) ? 1 : 0),
          define("MOTION_DILATION", int(o.motionDilation)),
          define("CAMERA_MOTION", int(o.cameraMotion)),
          define("HISTORY_FILTER", int(o.historyFilter)),
          define("RECTIFY", int(o.rectify)),
          define("BOX_SPACE_YCOCG", o.boxSpace == BoxSpace::YCoCg ? 1 : 0),
          define("NEIGHBOURHOOD", o.neighbourhood == Neighbourhood::Plus5 ? 5 : 9)};
}

void requireRange(float value, float lo, float hi, const char* name) {
  if (!(value >= lo && value <= hi)) {
    throw Error(std::string(name) + " must be in [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "], got " + std::to_string(value));
  }
}

void validateOptions(const ResolveOptions& o) {
  if (!(o.blend > 0.0f && o.blend <= 1.0f)) {
    throw Error("blend must be in (0, 1], got " + std::to_string(o.blend));
  }
  requireRange(o.velocityBlend, 0.0f, 1.0f, "velocity blend");
  requireRange(o.antiFlicker, 0.0f, 1.0f, "anti-flicker");
  requireRange(o.thinFeatureHold, 0.0f, 1.0f, "thin-feature hold");
  requireRange(o.cutDetection, 0.0f, 1.0f, "cut detection");
  requireRange(o.depthTolerance, 0.0f, 1e6f, "depth tolerance");
  requireRange(o.sharpen, 0.0f, 1e6f, "sharpen");
  requireRange(o.cameraAgreement, 0.0f, 1e6f, "camera agreement");
  if (!(o.varianceGamma > 0.0f)) throw Error("variance gamma must be > 0");
  if (!(o.velocityScale > 0.0f)) throw Error("velocity scale must be > 0");
  if (!(o.thinFeatureHoldSpeed > 0.0f)) throw Error("thin-feature hold speed must be > 0");
}

// Fraction of pixels whose debug reason says history was rejected (off-screen, disoccluded).
double rejectedFraction(const FrameVector<float>& debug) {
  std::size_t rejected = 0, count = debug.size() / 4;
  for (std::size_t i = 0; i < count; ++i) {
    if (debug[4 * i + 1] >= float(Rejection::OffScreen)) ++rejected;
  }
  return count ? double(rejected) / double(count) : 0.0;
}

}  // namespace

struct Resolver::Impl {
  gl::Context& context;
  const gl::Functions& gl;
  ResolveOptions options;
  gl::FullscreenTriangle triangle;

  // Programs and the bracket's GL resources, rebuilt when programKey changes.
  std::string programKey;
  gl::Program toWorkingProgram, resolveProgram, outputProgram;
  color::OcioBracket::Range workingRange{};
  color::OcioGpuResources toWorkingLuts, fromWorkingLuts;

  // Per-size resources, rebuilt when the frame size changes. Texture formats: the current
  // colour in its input type (half sampled is exactly half widened); its working-space copy,
  // history, depth, motion and the output stay 32-bit float; sample counts (integers <= 1024)
  // are exact in R16F.
  int width = 0, height = 0;
  SampleType currentType = SampleType::Float;
  gl::Texture current, currentWorking, motion, debug, output;
  gl::Framebuffer toWorkingTarget;
  gl::Texture depth[2];         // this frame's and the previous frame's, alternating
  gl::Texture history[2];       // working space, alternating
  gl::Texture historyState[2];  // sample counts, alternating with history
  gl::Framebuffer resolveTarget[2];
  bool hasDebugTarget = false;       // resolveTarget has the debug attachment
  bool hasOutputAttachment = false;  // resolveTarget writes the output (fusedOutput)
  gl::Framebuffer outputTarget;
  int latest = 0;        // index of the history holding the last result
  int latestDepth = 0;   // index of the depth texture holding the last frame's depth
  bool hasHistory = false;
  bool hasPreviousDepth = false;
  std::optional<FrameCamera> previousCamera;

  bool debugOutput = false;
  Image lastDebug;
  bool lastFrameWasCut = false;

  Impl(gl::Context& ctx, const ResolveOptions& opts)
      : context(ctx), gl(ctx.functions()), options(opts), triangle(gl) {
    buildPrograms(options);
  }

  // Builds the bracket and, when it or the defines changed, the programs. Throws (leaving the
  // current programs in place) when the new options are unusable.
  void buildPrograms(const ResolveOptions& newOptions) {
    const color::OcioBracket bracket(newOptions.color);
    std::vector<std::string> defines = resolveDefines(newOptions);
    std::string key;
    for (const auto& d : defines) key += d + "\n";
    key += bracket.cacheId();
    if (key == programKey) return;
    gl::Program newToWorking(gl, gl::embeddedShaderSource("fullscreen.vert"),
                             gl::embeddedShaderSource("to_working.frag",
                                                      {bracket.toWorking()->getShaderText()}));
    if (fusedOutput(newOptions)) defines.push_back(bracket.fromWorking()->getShaderText());
    gl::Program newResolve(gl, gl::embeddedShaderSource("fullscreen.vert"),
                           gl::embeddedShaderSource("resolve.frag", defines));
    gl::Program newOutput(gl, gl::embeddedShaderSource("fullscreen.vert"),
                          gl::embeddedShaderSource("output.frag",
                                                   {bracket.fromWorking()->getShaderText()}));
    color::OcioGpuResources newToWorkingLuts(gl, bracket.toWorking(), kFirstOcioUnit);
    color::OcioGpuResources newFromWorking(gl, bracket.fromWorking(), kFirstOcioUnit);
    newToWorkingLuts.setUniforms(newToWorking);
    newFromWorking.setUniforms(newOutput);
    if (fusedOutput(newOptions)) newFromWorking.setUniforms(newResolve);
    toWorkingProgram = std::move(newToWorking);
    resolveProgram = std::move(newResolve);
    outputProgram = std::move(newOutput);
    toWorkingLuts = std::move(newToWorkingLuts);
    fromWorkingLuts = std::move(newFromWorking);
    workingRange = bracket.workingRange();
    programKey = key;
  }

  void allocateCurrent(SampleType type) {
    currentType = type;
    current = gl::Texture(gl, width, height, type == SampleType::Half ? GL_RGBA16F : GL_RGBA32F);
  }

  void allocate(int w, int h, SampleType colorType) {
    width = w;
    height = h;
    allocateCurrent(colorType);
    currentWorking = gl::Texture(gl, w, h, GL_RGBA32F);
    toWorkingTarget = gl::Framebuffer(gl, currentWorking);
    motion = gl::Texture(gl, w, h, GL_RG32F);
    output = gl::Texture(gl, w, h, GL_RGBA32F);
    for (int i = 0; i < 2; ++i) {
      depth[i] = gl::Texture(gl, w, h, GL_R32F);
      history[i] = gl::Texture(gl, w, h, GL_RGBA32F, gl::Texture::Filter::Linear);
      historyState[i] = gl::Texture(gl, w, h, GL_R16F);
    }
    buildResolveTargets();
    outputTarget = gl::Framebuffer(gl, output);
    hasHistory = false;
    hasPreviousDepth = false;
  }

  bool needsDebug() const { return debugOutput || options.cutDetection > 0.0f; }

  bool resolveTargetsFit() const {
    return needsDebug() == hasDebugTarget && fusedOutput(options) == hasOutputAttachment;
  }

  // The resolve pass's targets. The debug attachment (float RGBA: 133 MB at 4K) exists only
  // while something reads it; without it GL drops the shader's debug output. The output texture
  // is attached when the resolve pass writes it (fusedOutput).
  void buildResolveTargets() {
    const bool withDebug = needsDebug();
    const bool withOutput = fusedOutput(options);
    debug = withDebug ? gl::Texture(gl, width, height, GL_RGBA32F) : gl::Texture();
    for (int i = 0; i < 2; ++i) {
      std::vector<gl::Attachment> attachments = {&history[i], &historyState[i],
                                                     withDebug ? &debug : nullptr};
      if (withOutput) attachments.push_back(&output);
      resolveTarget[i] = gl::Framebuffer(gl, attachments);
    }
    hasDebugTarget = withDebug;
    hasOutputAttachment = withOutput;
  }

  void setResolveUniforms(const ResolveInput& input, bool useCamera) {
    const gl::Program& p = resolveProgram;
    p.set("uCurrent", int(kCurrentUnit));
    p.set("uHistory", int(kHistoryUnit));
    p.set("uHistoryState", int(kHistoryStateUnit));
    p.set("uMotion", int(kMotionUnit));
    p.set("uDepth", int(kDepthUnit));
    p.set("uPreviousDepth", int(kPreviousDepthUnit));
    const std::array<float, 9> weights =
        reconstructionWeights(options.reconstruction, input.jitter);
    p.setArray("uReconstruction", weights.data(), int(weights.size()));
    p.set("uHasMotion", input.motion ? 1 : 0);
    p.set("uHasDepth", input.depth ? 1 : 0);
    p.set("uHasPreviousDepth", hasPreviousDepth ? 1 : 0);
    p.set("uHasCamera", useCamera ? 1 : 0);
    if (useCamera) {
      const ReprojectionMatrices m =
          reprojectionMatrices(*input.camera, *previousCamera, input.window, input.ndc);
      p.setMatrix4("uRasterToCamera", &m.rasterToCamera[0][0]);
      p.setMatrix4("uCameraToPreviousRaster", &m.cameraToPreviousRaster[0][0]);
      p.setMatrix4("uCameraToPreviousCamera", &m.cameraToPreviousCamera[0][0]);
    }
    p.set("uCameraAgreement", options.cameraAgreement);
    p.set("uBlend", options.blend);
    p.set("uVelocityBlend", options.velocityBlend);
    p.set("uVelocityScale", options.velocityScale);
    p.set("uAntiFlicker", options.antiFlicker);
    p.set("uLumaWeighting", options.lumaWeighting ? 1 : 0);
    p.set("uSampleCount", options.sampleCount ? 1 : 0);
    p.set("uAntiRinging", options.antiRinging ? 1 : 0);
    p.set("uVarianceGamma", options.varianceGamma);
    p.set("uDepthTolerance", options.depthTolerance);
    p.set("uThinHold", options.thinFeatureHold);
    p.set("uThinHoldSpeed", options.thinFeatureHoldSpeed);
    p.set("uWorkingRange", workingRange.lo, workingRange.hi);
  }

  // Whichever pass writes the output clamps it to what `type` can hold (glsl/finite_range.glsl).
  void setOutputLimit(SampleType type) {
    const float limit = type == SampleType::Half ? 65504.0f : std::numeric_limits<float>::max();
    resolveProgram.set("uOutputLimit", limit);
    outputProgram.set("uOutputLimit", limit);
  }

  void toWorkingPass() {
    toWorkingTarget.bind();
    toWorkingProgram.use();
    toWorkingProgram.set("uCurrent", 0);
    current.bind(0);
    toWorkingLuts.bind();
    triangle.draw("to-working pass");
  }

  void resolvePass(int target, int currentDepth) {
    resolveTarget[target].bind();
    resolveProgram.use();
    resolveProgram.set("uHasHistory", hasHistory ? 1 : 0);
    currentWorking.bind(kCurrentUnit);
    history[latest].bind(kHistoryUnit);
    historyState[latest].bind(kHistoryStateUnit);
    motion.bind(kMotionUnit);
    depth[currentDepth].bind(kDepthUnit);
    depth[1 - currentDepth].bind(kPreviousDepthUnit);
    if (fusedOutput(options)) fromWorkingLuts.bind();  // the to-working pass bound its own there
    triangle.draw("resolve pass");
  }

  // The resolve's debug attachment (reasons, weights) into lastDebug.
  void readDebug(int target) {
    lastDebug = Image(width, height, 4);
    resolveTarget[target].readRGBA(lastDebug.pixels.data(), GL_FLOAT, kDebugAttachment);
  }

  void outputPass(int resolved) {
    outputTarget.bind();
    outputProgram.use();
    outputProgram.set("uResolved", kResolvedUnit);
    outputProgram.set("uSharpen", options.sharpen);
    history[resolved].bind(kResolvedUnit);
    fromWorkingLuts.bind();
    triangle.draw("output pass");
  }

  TypedImage resolve(const ResolveInput& input, SampleType outputType) {
    const ImageView& color = input.color;
    if (!color || color.channels != 4) {
      throw Error("resolve needs an RGBA color image", {"", std::nullopt, "color"});
    }
    checkPlane(input.depth, color, 1, "depth");
    checkPlane(input.motion, color, 2, "motion");
    if (color.width != width || color.height != height) {
      allocate(color.width, color.height, color.type);
    } else if (color.type != currentType) {
      allocateCurrent(color.type);
    }
    if (!resolveTargetsFit()) buildResolveTargets();

    const int currentDepth = 1 - latestDepth;
    current.upload(color.data, 4, glType(color.type));
    if (input.motion) motion.upload(input.motion.data, 2, glType(input.motion.type));
    if (input.depth) depth[currentDepth].upload(input.depth.data, 1, glType(input.depth.type));
    const bool useCamera = hasHistory && input.camera && previousCamera;
    setResolveUniforms(input, useCamera);
    setOutputLimit(outputType);

    const int target = 1 - latest;
    toWorkingPass();
    resolvePass(target, currentDepth);
    lastFrameWasCut = false;
    bool debugRead = false;
    if (options.cutDetection > 0.0f && hasHistory) {
      readDebug(target);
      debugRead = true;
      if (rejectedFraction(lastDebug.pixels) > options.cutDetection) {
        hasHistory = false;  // a cut: resolve this frame again from scratch
        resolvePass(target, currentDepth);
        lastFrameWasCut = true;
        debugRead = false;
      }
    }
    if (debugOutput && !debugRead) readDebug(target);
    if (!fusedOutput(options)) outputPass(target);

    latest = target;
    latestDepth = currentDepth;
    hasHistory = true;
    hasPreviousDepth = bool(input.depth);
    previousCamera = input.camera ? std::optional<FrameCamera>(*input.camera) : std::nullopt;

    TypedImage result(width, height, 4, outputType);
    outputTarget.readRGBA(result.data(), glType(outputType));
    return result;
  }
};

Resolver::Resolver(gl::Context& context, const ResolveOptions& options) {
  validateOptions(options);
  impl_ = std::make_unique<Impl>(context, options);
}

Resolver::~Resolver() = default;

Image Resolver::resolve(const ResolveInput& input) {
  return std::move(*impl_->resolve(input, SampleType::Float).floats());
}

TypedImage Resolver::resolve(const ResolveInput& input, SampleType outputType) {
  return impl_->resolve(input, outputType);
}

void Resolver::resetHistory() {
  impl_->hasHistory = false;
  impl_->hasPreviousDepth = false;
  impl_->previousCamera.reset();
}

const ResolveOptions& Resolver::options() const { return impl_->options; }

void Resolver::setOptions(const ResolveOptions& options) {
  validateOptions(options);
  impl_->buildPrograms(options);  // a no-op unless a [program] option changed
  impl_->options = options;
}

void Resolver::setDebugOutput(bool enabled) { impl_->debugOutput = enabled; }

const Image& Resolver::lastDebug() const { return impl_->lastDebug; }

bool Resolver::lastFrameWasCut() const { return impl_->lastFrameWasCut; }

}  // namespace taa
