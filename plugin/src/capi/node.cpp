#include "capi/node.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "capi/buffer_conversion.h"
#include "capi/status_error.h"
#include "io/aov_conversion.h"
#include "gl/caller_context.h"
#include "resolve/jitter.h"
#include "taa/error.h"
#include "util/frame_span.h"

namespace taa::capi {

// Binds the node's context for one call, then releases it and gives the calling thread back
// the context it had (a host's own GL context must survive a call into taa).
class Node::CurrentContext {
 public:
  explicit CurrentContext(gl::Context& context) : context_(context) { context_.makeCurrent(); }
  ~CurrentContext() {
    try {
      context_.releaseCurrent();
    } catch (const Error&) {
      // Nothing to undo: the next call binds the context again, which reports real failures.
    }
  }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

 private:
  gl::CallerContext caller_;  // restored after the release above
  gl::Context& context_;
};

Node::Node(gl::Backend backend, bool deferContext) : backend_(backend) {
  if (!deferContext) ensureContext();
}

Node::~Node() {
  if (!context_) return;
  // GL objects must die with their context current.
  CurrentContext current(*context_);
  resolver_.reset();
  window_.reset();
}

void Node::ensureContext() {
  if (context_) return;
  const gl::CallerContext caller;  // create() binds the new context: give the caller theirs back
  try {
    context_ = gl::Context::create(backend_);
    context_->releaseCurrent();  // create() leaves it current; each call binds it again
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_GL, e.what());
  }
}

std::unique_ptr<Node::CurrentContext> Node::bindContext() {
  ensureContext();
  try {
    return std::make_unique<CurrentContext>(*context_);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_GL, e.what());
  }
}

void Node::setInt(const std::string& name, int value) {
  setIntParameter(parameters_, name, value);
  parametersChanged_ = true;
}

void Node::setFloat(const std::string& name, float value) {
  setFloatParameter(parameters_, name, value);
  parametersChanged_ = true;
}

void Node::setString(const std::string& name, const std::string& value) {
  setStringParameter(parameters_, name, value);
  parametersChanged_ = true;
}

void Node::pushFrame(const taa_frame& frame, const std::vector<taa_pass>& passes) {
  if (!frame.color) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "frame " + std::to_string(frame.frame) +
                                                      " has no color buffer (NULL)");
  }
  if (!passes.empty() && !windowMode()) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                      "frame " + std::to_string(frame.frame) +
                          ": passes are resolved in window mode only (parameter \"mode\" = "
                          "\"window\"); history mode has no per-sample weights to give them");
  }
  // Convert every input before touching the resolver, so a bad buffer leaves history intact.
  // Half colour stays half: the resolver uploads it as is.
  if (frame.has_jitter) {
    try {
      checkedJitter(glm::vec2(frame.jitter[0], frame.jitter[1]), "the host",
                    {"", frame.frame, ""});
    } catch (const Error& e) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT, e.what());
    }
  }
  for (const float* matrix : {frame.world_to_camera, frame.world_to_ndc}) {
    if (matrix && !std::all_of(matrix, matrix + 16, [](float v) { return std::isfinite(v); })) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        "frame " + std::to_string(frame.frame) + ": " +
                            (matrix == frame.world_to_camera ? "world_to_camera" : "world_to_ndc") +
                            " holds NaN or Inf");
    }
  }
  const TypedImage color = importColor(*frame.color);
  const int width = color.width(), height = color.height();

  // The camera sidecar's entry serves what the host did not give (taatool's rule: the host's
  // matrices and jitter, like explicit flags, win).
  const bool hostCamera = frame.world_to_camera && frame.world_to_ndc;
  const io::SidecarFrame* entry = nullptr;
  if (parameters_.cameraSidecar && (!hostCamera || !frame.has_jitter)) {
    try {
      entry = &parameters_.cameraSidecar->frame(frame.frame);
    } catch (const Error& e) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT, e.what());
    }
  }
  ResolveInput input;
  const RasterWindow whole{0, 0, width, height};  // a host buffer is the whole image
  input.jitter = frame.has_jitter                ? glm::vec2(frame.jitter[0], frame.jitter[1])
                 : entry && entry->jitter        ? *entry->jitter
                                                 : frameJitter(frame.frame, parameters_.resolve.jitter);
  // Row-major row-vector matrices (EXR) read column-major are GLM's column-vector ones.
  FrameCamera camera;
  auto keep = [](const float* matrix) -> std::optional<std::array<float, 16>> {
    if (!matrix) return std::nullopt;
    std::array<float, 16> copy;
    std::copy(matrix, matrix + 16, copy.begin());
    return copy;
  };
  // What taa_node_get_camera gives back: the host's matrices as given, or the sidecar's in
  // the same row-major layout.
  std::optional<std::array<float, 16>> toCamera = keep(frame.world_to_camera);
  std::optional<std::array<float, 16>> toNdc = keep(frame.world_to_ndc);
  if (hostCamera) {
    camera.worldToCamera = glm::dmat4(glm::make_mat4(frame.world_to_camera));
    camera.worldToNdc = glm::dmat4(glm::make_mat4(frame.world_to_ndc));
    input.camera = &camera;
    input.ndc = parameters_.ndc;
  } else if (entry && entry->camera) {
    camera = *entry->camera;
    input.camera = &camera;
    input.ndc = io::CameraSidecar::kNdc;
    toCamera.emplace();
    toNdc.emplace();
    const glm::mat4 c(camera.worldToCamera), n(camera.worldToNdc);
    std::copy_n(glm::value_ptr(c), 16, toCamera->begin());
    std::copy_n(glm::value_ptr(n), 16, toNdc->begin());
  }
  if (input.camera) input.window = whole;
  const FrameMatrices matrices{toCamera, toNdc};

  Image depth, motion;
  if (frame.depth) {
    std::optional<io::PixelRay> ray;
    if (input.camera) {
      ray = io::cameraPixelRay(camera, whole, input.ndc);
    } else if (parameters_.depth.horizontalFovDegrees) {
      ray = io::pinholePixelRay(*parameters_.depth.horizontalFovDegrees, whole);
    }
    depth = importDepth(*frame.depth, parameters_.depth, width, height, ray ? &*ray : nullptr);
  }
  if (frame.motion) motion = importMotion(*frame.motion, parameters_.motion, width, height);
  input.color = &color;
  input.depth = frame.depth ? &depth : nullptr;
  input.motion = frame.motion ? &motion : nullptr;
  const std::optional<FramePasses> framePasses =
      passes.empty() ? std::nullopt
                     : std::optional<FramePasses>(
                           importFramePasses(frame.frame, passes, width, height));

  const auto current = bindContext();
  if (windowMode()) {
    windowFrames().push(frame.frame, input, resetRequested_, matrices,
                        framePasses ? &*framePasses : nullptr);
  } else {
    window_.reset();  // switching modes frees the ring
    resolveInHistory(frame.frame, input);
    passesOutput_ = Image();
    passesOutputNames_.clear();
    outputMatrices_ = matrices;
  }
  resetRequested_ = false;
}

FramePasses Node::importFramePasses(int frame, const std::vector<taa_pass>& passes, int width,
                                    int height) const {
  const std::string which = "frame " + std::to_string(frame) + "'s passes";
  FramePasses imported;
  std::set<std::string> seen;
  std::vector<PassChannel> channels;
  for (std::size_t c = 0; c < passes.size(); ++c) {
    const taa_pass& pass = passes[c];
    if (!pass.name || !*pass.name) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        which + ": channel " + std::to_string(c) + " has no name");
    }
    if (!seen.insert(pass.name).second) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        which + ": channel \"" + std::string(pass.name) + "\" given twice");
    }
    if (!pass.buffer) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        which + ": channel \"" + std::string(pass.name) + "\" has no buffer");
    }
    imported.names.push_back(pass.name);
    channels.push_back({pass.buffer, pass.channel, pass.name});
  }
  imported.values = importPasses(channels, width, height, imported.types);
  imported.rules = parameters_.passRules;
  return imported;
}

void Node::resolveInHistory(int frame, const ResolveInput& input) {
  try {
    if (!resolver_) {
      resolver_ = std::make_unique<Resolver>(*context_, parameters_.resolve);
    } else if (parametersChanged_) {
      resolver_->setOptions(parameters_.resolve);
    }
    parametersChanged_ = false;
    const bool gap = lastFrame_ && parameters_.resetOnGap && !isNextFrame(*lastFrame_, frame);
    if (gap || resetRequested_) resolver_->resetHistory();
    // The output buffer's type is only known at taa_node_read_output, so the host says which
    // read-back it wants ("output-type"): float by default, which exportColor narrows into a
    // half buffer exactly as a half read-back would have.
    output_ = resolver_->resolve(input, parameters_.outputType);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_INTERNAL, "frame " + std::to_string(frame) + ": " + e.what());
  }
  lastFrame_ = frame;
}

WindowFrames& Node::windowFrames() {
  // Switching modes frees the history (the context is current: GL objects die with it).
  resolver_.reset();
  lastFrame_.reset();
  try {
    if (!window_) {
      window_ = std::make_unique<WindowFrames>(*context_, parameters_.resolve);
    } else {
      window_->setOptions(parameters_.resolve);
    }
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_INTERNAL, e.what());
  }
  parametersChanged_ = false;
  return *window_;
}

void Node::requireWindowMode(const char* function) const {
  if (!windowMode()) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                      std::string(function) +
                          " needs parameter \"mode\" = \"window\" (in history mode "
                          "taa_node_push_frame resolves each frame)");
  }
}

void Node::resolveFrame(int frame) {
  requireWindowMode("taa_node_resolve_frame");
  const auto current = bindContext();
  WindowFrames& window = windowFrames();
  output_ = window.resolve(frame, parameters_.outputType);
  passesOutput_ = window.takeResolvedPasses();
  passesOutputNames_ = window.passNames();
  outputMatrices_ = window.matrices(frame);
}

void Node::dropFrame(int frame) {
  requireWindowMode("taa_node_drop_frame");
  if (!window_) return;  // nothing pushed yet
  const auto current = bindContext();
  window_->drop(frame);
}

void Node::readOutput(const taa_buffer& output) const {
  if (output_.empty()) {
    throw StatusError(TAA_ERROR_NO_OUTPUT, "no frame has been resolved yet");
  }
  exportColor(output_, output);
}

void Node::readPasses(const std::vector<taa_pass>& passes) const {
  if (passesOutput_.empty()) {
    throw StatusError(TAA_ERROR_NO_OUTPUT, output_.empty()
                                               ? "no frame has been resolved yet"
                                               : "the last resolved frame had no passes "
                                                 "(taa_node_push_frame_passes)");
  }
  std::vector<PassChannel> channels;
  std::vector<int> sources;
  for (const taa_pass& pass : passes) {
    const std::string name = pass.name ? pass.name : "";
    const auto found = std::find(passesOutputNames_.begin(), passesOutputNames_.end(), name);
    if (found == passesOutputNames_.end()) {
      std::string held;
      for (const std::string& n : passesOutputNames_) held += (held.empty() ? "" : ", ") + n;
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                        "the last resolved frame has no pass \"" + name + "\" (it has " + held +
                            ")");
    }
    if (!pass.buffer) {
      throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "pass \"" + name + "\" has no buffer");
    }
    channels.push_back({pass.buffer, pass.channel, name});
    sources.push_back(int(found - passesOutputNames_.begin()));
  }
  exportPasses(passesOutput_, sources, channels);
}

void Node::cameras(float* worldToCamera, float* worldToNdc) const {
  if (!outputMatrices_) {
    throw StatusError(TAA_ERROR_NO_OUTPUT, "no frame has been resolved yet");
  }
  auto give = [](const std::optional<std::array<float, 16>>& stored, float* out) {
    if (!out) return;
    if (stored) {
      std::copy(stored->begin(), stored->end(), out);
    } else {
      std::fill(out, out + 16, 0.0f);
    }
  };
  give(outputMatrices_->worldToCamera, worldToCamera);
  give(outputMatrices_->worldToNdc, worldToNdc);
}

}  // namespace taa::capi
