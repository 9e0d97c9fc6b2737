// The C++ side of a taa_node: on its own GL context, a Resolver (history mode) or the window
// mode's ring (capi/window_frames), the parameters set by name, and the last output. Calls
// throw StatusError; c_api.cpp turns them into status codes.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "capi/node_parameters.h"
#include "capi/window_frames.h"
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

  // History mode: resolves the frame. Window mode: puts it into the ring, with its passes if
  // any (window mode only).
  void pushFrame(const taa_frame& frame, const std::vector<taa_pass>& passes);
  // Window mode only (TAA_ERROR_INVALID_ARGUMENT otherwise).
  void resolveFrame(int frame);
  void dropFrame(int frame);
  void readOutput(const taa_buffer& output) const;
  void readPasses(const std::vector<taa_pass>& passes) const;
  void cameras(float* worldToCamera, float* worldToNdc) const;
  // History mode: the next frame starts a new history. Window mode: it starts a new shot.
  void resetHistory() { resetRequested_ = true; }

 private:
  // Binds the context to the calling thread for one call and releases it after, so the node
  // can be used from another thread next time.
  class CurrentContext;

  void ensureContext();
  // The context made and bound for one call; GL failures become TAA_ERROR_GL.
  std::unique_ptr<CurrentContext> bindContext();
  bool windowMode() const { return parameters_.resolve.mode == ResolveMode::Window; }
  void requireWindowMode(const char* function) const;
  void resolveInHistory(int frame, const ResolveInput& input);
  // The host's passes of `frame` checked and read (the colour's `width` x `height`).
  FramePasses importFramePasses(int frame, const std::vector<taa_pass>& passes, int width,
                                int height) const;
  // The window ring with the current parameters, made on first use (history freed).
  WindowFrames& windowFrames();

  gl::Backend backend_;
  std::unique_ptr<gl::Context> context_;
  std::unique_ptr<Resolver> resolver_;
  std::unique_ptr<WindowFrames> window_;
  NodeParameters parameters_;
  bool parametersChanged_ = false;
  bool resetRequested_ = false;
  std::optional<int> lastFrame_;  // history mode: the last frame resolved
  TypedImage output_;
  Image passesOutput_;  // the passes of the frame output_ is, if it had any
  std::vector<std::string> passesOutputNames_;  // and their names, in passesOutput_'s order
  std::optional<FrameMatrices> outputMatrices_;  // the matrices of the frame output_ is
};

}  // namespace taa::capi
