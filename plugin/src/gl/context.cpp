#include "gl/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "gl/context_backends.h"
#include "taa/error.h"

namespace taa::gl {

Backend parseBackend(std::string_view name) {
  if (name == "auto") return Backend::Auto;
  if (name == "egl") return Backend::Egl;
  if (name == "osmesa") return Backend::OsMesa;
  throw Error("unknown GL back end \"" + std::string(name) + "\" (expected auto, egl or osmesa)");
}

const char* backendName(Backend backend) {
  switch (backend) {
    case Backend::Auto: return "auto";
    case Backend::Egl: return "egl";
    case Backend::OsMesa: return "osmesa";
  }
  return "unknown";
}

std::unique_ptr<Context> Context::create(Backend backend, const LogSink& log) {
  switch (backend) {
    case Backend::Egl: return createEglContext();
    case Backend::OsMesa: return createOsMesaContext();
    case Backend::Auto: break;
  }
  std::string eglFailure;
  try {
    return createEglContext();
  } catch (const Error& error) {
    eglFailure = error.description();
  }
  if (log) log("EGL unavailable, falling back to OSMesa: " + eglFailure);
  try {
    return createOsMesaContext();
  } catch (const Error& error) {
    throw Error("no OpenGL context could be created; " + eglFailure + "; " +
                error.description());
  }
}

bool hasExtension(const char* extensions, const char* name) {
  if (!extensions || !name || !*name) return false;
  const size_t length = std::strlen(name);
  for (const char* p = extensions; (p = std::strstr(p, name)) != nullptr; p += length) {
    const bool startsWord = p == extensions || p[-1] == ' ';
    const bool endsWord = p[length] == ' ' || p[length] == '\0';
    if (startsWord && endsWord) return true;
  }
  return false;
}

namespace {

std::string glString(const Functions& gl, GLenum name) {
  const GLubyte* text = gl.GetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

ContextInfo queryContextInfo(const Functions& gl, Backend backend, const std::string& platform) {
  ContextInfo info;
  info.backend = backend;
  info.platform = platform;
  info.vendor = glString(gl, GL_VENDOR);
  info.renderer = glString(gl, GL_RENDERER);
  info.version = glString(gl, GL_VERSION);
  info.glslVersion = glString(gl, GL_SHADING_LANGUAGE_VERSION);

  GLint major = 0, minor = 0, profile = 0;
  gl.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl.GetIntegerv(GL_MINOR_VERSION, &minor);
  gl.GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  const std::string where = std::string(backendName(backend)) + " (" + platform + ")";
  if (major * 10 + minor < 41) {
    throw Error(where + ": got OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                " (\"" + info.version + "\"), taa needs 4.1 or newer");
  }
  if (!(profile & GL_CONTEXT_CORE_PROFILE_BIT)) {
    throw Error(where + ": got a compatibility-profile context, taa needs the core profile");
  }
  gl.GetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &info.fragmentTextureUnits);
  const char* imageStores = std::getenv("TAA_GL_IMAGE_STORES");
  const bool imagesWanted = !(imageStores && std::string(imageStores) == "0");
  if (imagesWanted && major * 10 + minor >= 42 && gl.BindImageTexture && gl.MemoryBarrier) {
    GLint fragmentImages = 0, units = 0;
    gl.GetIntegerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &fragmentImages);
    gl.GetIntegerv(GL_MAX_IMAGE_UNITS, &units);
    info.fragmentImageUnits = std::min(fragmentImages, units);
  }
  return info;
}

}  // namespace taa::gl
