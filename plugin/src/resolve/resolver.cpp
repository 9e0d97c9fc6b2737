#include "resolve/resolver.h"

#include <string>
#include <utility>

#include "color/ocio_bracket.h"
#include "color/ocio_gpu_resources.h"
#include "gl/objects.h"
#include "taa/error.h"

namespace taa {
namespace {

// Texture units of the resolve program. OCIO's LUT textures are bound after these.
enum TextureUnit : int { kCurrentUnit = 0, kHistoryUnit, kMotionUnit, kDepthUnit, kFirstOcioUnit };

std::vector<std::string> programDefines(const ResolveOptions& options) {
  return {"#define DILATE_MOTION " + std::to_string(options.dilateMotion ? 1 : 0),
          "#define RECTIFY " + std::to_string(int(options.rectify)),
          "#define BOX_SPACE_YCOCG " + std::to_string(options.boxSpace == BoxSpace::YCoCg ? 1 : 0)};
}

void checkPlane(const Image* plane, const Image& color, int channels, const char* name) {
  if (!plane) return;
  if (plane->width != color.width || plane->height != color.height) {
    throw Error(std::string(name) + " is " + std::to_string(plane->width) + "x" +
                    std::to_string(plane->height) + " but color is " +
                    std::to_string(color.width) + "x" + std::to_string(color.height),
                {"", std::nullopt, name});
  }
  if (plane->channels != channels) {
    throw Error(std::string(name) + " must have " + std::to_string(channels) +
                    " channels, has " + std::to_string(plane->channels),
                {"", std::nullopt, name});
  }
}

void validateOptions(const ResolveOptions& options) {
  if (!(options.blend > 0.0f && options.blend <= 1.0f)) {
    throw Error("blend must be in (0, 1], got " + std::to_string(options.blend));
  }
}

}  // namespace

struct Resolver::Impl {
  gl::Context& context;
  const gl::Functions& gl;
  ResolveOptions options;
  gl::Program program;
  gl::FullscreenTriangle triangle;
  std::string programKey;  // defines + bracket cache ID the program was built from
  color::OcioGpuResources toWorkingLuts, fromWorkingLuts;

  // Per-size resources, rebuilt when the frame size changes.
  int width = 0, height = 0;
  gl::Texture current, motion, depth;
  gl::Texture history[2];  // working space
  gl::Texture output;      // output colorspace
  gl::Framebuffer historyTarget[2];  // attachments: history[i], output
  int latest = 0;  // index of the history texture holding the last output
  bool hasHistory = false;

  Impl(gl::Context& ctx, const ResolveOptions& opts)
      : context(ctx), gl(ctx.functions()), options(opts), triangle(gl) {
    buildProgram(options);
  }

  // Builds the bracket and, when it or the defines changed, the program.
  // Throws (leaving the current program in place) when the new options are unusable.
  void buildProgram(const ResolveOptions& newOptions) {
    const color::OcioBracket bracket(newOptions.color);
    std::vector<std::string> defines = programDefines(newOptions);
    std::string key;
    for (const auto& d : defines) key += d + "\n";
    key += bracket.cacheId();
    if (key == programKey) return;
    defines.push_back(bracket.glsl());
    program = gl::Program(gl, gl::embeddedShaderSource("fullscreen.vert"),
                          gl::embeddedShaderSource("resolve.frag", defines));
    toWorkingLuts = color::OcioGpuResources(gl, bracket.toWorking(), kFirstOcioUnit);
    fromWorkingLuts = color::OcioGpuResources(gl, bracket.fromWorking(),
                                              kFirstOcioUnit + toWorkingLuts.unitCount());
    toWorkingLuts.setUniforms(program);
    fromWorkingLuts.setUniforms(program);
    programKey = key;
  }

  void allocate(int w, int h) {
    width = w;
    height = h;
    current = gl::Texture(gl, w, h, GL_RGBA32F);
    motion = gl::Texture(gl, w, h, GL_RG32F);
    depth = gl::Texture(gl, w, h, GL_R32F);
    output = gl::Texture(gl, w, h, GL_RGBA32F);
    for (int i = 0; i < 2; ++i) {
      history[i] = gl::Texture(gl, w, h, GL_RGBA32F, gl::Texture::Filter::Linear);
      historyTarget[i] = gl::Framebuffer(gl, {&history[i], &output});
    }
    hasHistory = false;
  }

  Image resolve(const ResolveInput& input) {
    if (!input.color || input.color->channels != 4 || input.color->empty()) {
      throw Error("resolve needs an RGBA color image", {"", std::nullopt, "color"});
    }
    const Image& color = *input.color;
    checkPlane(input.depth, color, 1, "depth");
    checkPlane(input.motion, color, 2, "motion");
    if (color.width != width || color.height != height) allocate(color.width, color.height);

    current.upload(color.pixels.data(), 4);
    if (input.motion) motion.upload(input.motion->pixels.data(), 2);
    if (input.depth) depth.upload(input.depth->pixels.data(), 1);

    const int target = 1 - latest;
    historyTarget[target].bind();
    program.use();
    current.bind(kCurrentUnit);
    history[latest].bind(kHistoryUnit);
    motion.bind(kMotionUnit);
    depth.bind(kDepthUnit);
    toWorkingLuts.bind();
    fromWorkingLuts.bind();
    program.set("uCurrent", int(kCurrentUnit));
    program.set("uHistory", int(kHistoryUnit));
    program.set("uMotion", int(kMotionUnit));
    program.set("uDepth", int(kDepthUnit));
    program.set("uJitter", input.jitter.x, input.jitter.y);
    program.set("uBlend", options.blend);
    program.set("uHasHistory", hasHistory ? 1 : 0);
    program.set("uHasMotion", input.motion ? 1 : 0);
    program.set("uHasDepth", input.depth ? 1 : 0);
    triangle.draw();
    gl::checkError(gl, "resolve pass");

    latest = target;
    hasHistory = true;

    Image result(width, height, 4);
    result.pixels = historyTarget[latest].readRGBA(1);
    return result;
  }
};

Resolver::Resolver(gl::Context& context, const ResolveOptions& options) {
  validateOptions(options);
  impl_ = std::make_unique<Impl>(context, options);
}

Resolver::~Resolver() = default;

Image Resolver::resolve(const ResolveInput& input) { return impl_->resolve(input); }

void Resolver::resetHistory() { impl_->hasHistory = false; }

const ResolveOptions& Resolver::options() const { return impl_->options; }

void Resolver::setOptions(const ResolveOptions& options) {
  validateOptions(options);
  impl_->buildProgram(options);  // a no-op unless a [program] option changed
  impl_->options = options;
}

}  // namespace taa
