// Headless OpenGL contexts: one interface, two back ends (EGL and OSMesa), both loaded at run
// time with dlopen so that a missing library is an error for that back end only.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "gl/gl_functions.h"

namespace taa::gl {

enum class Backend { Auto, Egl, OsMesa };

// "auto" | "egl" | "osmesa"; anything else throws taa::Error naming the value and the choices.
Backend parseBackend(std::string_view name);
const char* backendName(Backend backend);

struct ContextInfo {
  Backend backend = Backend::Auto;  // the back end actually in use (never Auto)
  std::string platform;             // e.g. "EGL device", "EGL surfaceless", "OSMesa"
  std::string vendor, renderer, version, glslVersion;
  // Images a fragment shader may write (OpenGL 4.2's image stores), 0 without them (a 4.1
  // context) or with TAA_GL_IMAGE_STORES=0 in the environment (to compare the two ways of the
  // window gather's pass outputs); and the texture units a fragment shader may read.
  int fragmentImageUnits = 0;
  int fragmentTextureUnits = 0;
};

// Receives informational messages, such as why "auto" fell back from EGL to OSMesa.
using LogSink = std::function<void(const std::string&)>;

// An offscreen OpenGL 4.1+ core-profile context. It owns no default framebuffer worth drawing
// to: render into Framebuffer objects. Not thread-safe; make it current on the thread using it.
class Context {
 public:
  // Creates a context on the requested back end. Auto tries EGL (device platform when a GPU
  // device is present, else surfaceless) and falls back to OSMesa, reporting the reason to log.
  // Throws taa::Error naming the back end and the EGL/OSMesa error when no context can be made.
  static std::unique_ptr<Context> create(Backend backend, const LogSink& log = {});

  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Binds the context to the calling thread (the constructor leaves it current already).
  virtual void makeCurrent() = 0;
  // Unbinds the context from the calling thread, so that another thread may make it current.
  virtual void releaseCurrent() = 0;

  const Functions& functions() const { return functions_; }
  const ContextInfo& info() const { return info_; }

 protected:
  Context() = default;
  Functions functions_;
  ContextInfo info_;
};

}  // namespace taa::gl
