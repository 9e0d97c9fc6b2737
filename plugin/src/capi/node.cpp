#include "capi/node.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "capi/buffer_conversion.h"
#include "capi/status_error.h"
#include "resolve/jitter.h"
#include "taa/error.h"

namespace taa::capi {

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
}

void Node::ensureContext() {
  if (context_) return;
  try {
    context_ = gl::Context::create(backend_);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_GL, e.what());
  }
  context_->releaseCurrent();  // create() leaves it current; each call binds it again
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

  ensureContext();
  std::optional<CurrentContext> current;
  try {
    current.emplace(*context_);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_GL, e.what());
  }
  try {
    if (!resolver_) {
      resolver_ = std::make_unique<Resolver>(*context_, parameters_.resolve);
    } else if (parametersChanged_) {
      resolver_->setOptions(parameters_.resolve);
    }
    parametersChanged_ = false;
    const bool gap = lastFrame_ && parameters_.resetOnGap && *lastFrame_ + 1 != frame.frame;
    if (gap || resetRequested_) resolver_->resetHistory();

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
    // The output buffer's type is only known at taa_node_read_output, so the host says which
    // read-back it wants ("output-type"): float by default, which exportColor narrows into a
    // half buffer exactly as a half read-back would have.
    output_ = resolver_->resolve(input, parameters_.outputType);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_INTERNAL,
                      "frame " + std::to_string(frame.frame) + ": " + e.what());
  }
  resetRequested_ = false;
  lastFrame_ = frame.frame;
  auto keep = [](const float* matrix) -> std::optional<std::array<float, 16>> {
    if (!matrix) return std::nullopt;
    std::array<float, 16> copy;
    std::copy(matrix, matrix + 16, copy.begin());
    return copy;
  };
  worldToCamera_ = keep(frame.world_to_camera);
  worldToNdc_ = keep(frame.world_to_ndc);
}

void Node::readOutput(const taa_buffer& output) const {
  if (output_.empty()) {
    throw StatusError(TAA_ERROR_NO_OUTPUT, "no frame has been resolved yet");
  }
  exportColor(output_, output);
}

void Node::cameras(float* worldToCamera, float* worldToNdc) const {
  if (!lastFrame_) throw StatusError(TAA_ERROR_NO_OUTPUT, "no frame has been resolved yet");
  auto give = [](const std::optional<std::array<float, 16>>& stored, float* out) {
    if (!out) return;
    if (stored) {
      std::copy(stored->begin(), stored->end(), out);
    } else {
      std::fill(out, out + 16, 0.0f);
    }
  };
  give(worldToCamera_, worldToCamera);
  give(worldToNdc_, worldToNdc);
}

}  // namespace taa::capi
