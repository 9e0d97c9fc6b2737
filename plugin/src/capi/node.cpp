#include "capi/node.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "capi/buffer_conversion.h"
#include "capi/status_error.h"
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

void Node::pushFrame(const taa_frame& frame) {
  if (!frame.color) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT, "frame " + std::to_string(frame.frame) +
                                                      " has no color buffer (NULL)");
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
  Image depth, motion;
  if (frame.depth) depth = importDepth(*frame.depth, parameters_.depth, width, height);
  if (frame.motion) motion = importMotion(*frame.motion, parameters_.motion, width, height);

  ResolveInput input;
  input.color = &color;
  input.depth = frame.depth ? &depth : nullptr;
  input.motion = frame.motion ? &motion : nullptr;
  input.jitter = frame.has_jitter ? glm::vec2(frame.jitter[0], frame.jitter[1])
                                  : frameJitter(frame.frame, parameters_.resolve.jitter);
  // Row-major row-vector matrices (EXR) read column-major are GLM's column-vector ones.
  FrameCamera camera;
  if (frame.world_to_camera && frame.world_to_ndc) {
    camera.worldToCamera = glm::dmat4(glm::make_mat4(frame.world_to_camera));
    camera.worldToNdc = glm::dmat4(glm::make_mat4(frame.world_to_ndc));
    input.camera = &camera;
    input.window.displayWidth = width;
    input.window.displayHeight = height;
    input.ndc = parameters_.ndc;
  }
  auto keep = [](const float* matrix) -> std::optional<std::array<float, 16>> {
    if (!matrix) return std::nullopt;
    std::array<float, 16> copy;
    std::copy(matrix, matrix + 16, copy.begin());
    return copy;
  };
  const FrameMatrices matrices{keep(frame.world_to_camera), keep(frame.world_to_ndc)};

  const auto current = bindContext();
  if (windowMode()) {
    windowFrames().push(frame.frame, input, resetRequested_, matrices);
  } else {
    window_.reset();  // switching modes frees the ring
    resolveInHistory(frame.frame, input);
    outputMatrices_ = matrices;
  }
  resetRequested_ = false;
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
