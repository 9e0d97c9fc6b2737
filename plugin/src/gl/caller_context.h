// The OpenGL context the calling thread had current before taa bound its own, put back after.
// Hosts (compositors, OpenFX hosts, viewers) often keep their own context current on the thread
// that calls taa; binding taa's context unbinds theirs, so every entry point that binds one
// keeps a CallerContext for the duration. EGL (any client API) and OSMesa are covered; only
// libraries already loaded in the process are looked at, so nothing is loaded for this.
#pragma once

#include <memory>

namespace taa::gl {

class CallerContext {
 public:
  // Records what is current on this thread now.
  CallerContext();
  // Makes it current again (after taa released its own). Never throws.
  ~CallerContext();
  CallerContext(const CallerContext&) = delete;
  CallerContext& operator=(const CallerContext&) = delete;

  // Whether the thread had any EGL or OSMesa context current when this was made.
  bool hadContext() const;

 private:
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

}  // namespace taa::gl
