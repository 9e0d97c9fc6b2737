// The C++ side of a taa_node: one Resolver on its own GL context, the parameters set by name,
// and the last output. Calls throw StatusError; c_api.cpp turns them into status codes.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "capi/node_parameters.h"
#include "gl/context.h"
#include "resolve/resolver.h"
#include "taa/taa.h"
#include "util/image.h"

namespace taa::capi {

class Node {
 public:
  // Makes the GL context now unless `deferContext`; throws StatusError(TAA_ERROR_GL).
  Node(gl::Backend backend, bool deferContext);
  ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  // Parameter changes reach the resolver on the next pushFrame.
  void setInt(const std::string& name, int value);
  void setFloat(const std::string& name, float value);
  void setString(const std::string& name, const std::string& value);

  void pushFrame(const taa_frame& frame);
  void readOutput(const taa_buffer& output) const;
  void cameras(float* worldToCamera, float* worldToNdc) const;
  void resetHistory() { resetRequested_ = true; }

 private:
  // Binds the context to the calling thread for one call and releases it after, so the node
  // can be used from another thread next time.
  class CurrentContext;

  void ensureContext();

  gl::Backend backend_;
  std::unique_ptr<gl::Context> context_;
  std::unique_ptr<Resolver> resolver_;
  NodeParameters parameters_;
  bool parametersChanged_ = false;
  bool resetRequested_ = false;
  std::optional<int> lastFrame_;
  TypedImage output_;
  std::optional<std::array<float, 16>> worldToCamera_, worldToNdc_;
};

}  // namespace taa::capi
