// The OSMesa back end: Mesa's off-screen software renderer (llvmpipe), used where EGL is not
// available. It always has a colour buffer to draw to; taa keeps it tiny and renders into FBOs.
#include "gl/gl_functions.h"  // glcorearb.h first: osmesa.h pulls in the legacy GL/gl.h

#include <GL/osmesa.h>

#include <string>
#include <vector>

#include "gl/context_backends.h"
#include "gl/dynamic_library.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

using CreateContextAttribsFn = OSMesaContext (*)(const int* attributes, OSMesaContext sharelist);
using DestroyContextFn = void (*)(OSMesaContext context);
using MakeCurrentFn = GLboolean (*)(OSMesaContext context, void* buffer, GLenum type,
                                    GLsizei width, GLsizei height);
using GetCurrentContextFn = OSMesaContext (*)();
using GetProcAddressFn = OSMESAproc (*)(const char* name);

struct OsMesaApi {
  CreateContextAttribsFn CreateContextAttribs = nullptr;
  DestroyContextFn DestroyContext = nullptr;
  MakeCurrentFn MakeCurrent = nullptr;
  GetCurrentContextFn GetCurrentContext = nullptr;
  GetProcAddressFn GetProcAddress = nullptr;
};

void* loadGlFunction(const char* name, void* userData) {
  const OsMesaApi& osmesa = *static_cast<const OsMesaApi*>(userData);
  return reinterpret_cast<void*>(osmesa.GetProcAddress(name));
}

// The colour buffer OSMesa insists on; never read. Small, but not 1x1, which some Mesa
// versions handle poorly.
constexpr int kBufferSize = 16;

class OsMesaContext final : public Context {
 public:
  OsMesaContext() : buffer_(kBufferSize * kBufferSize * 4) {
    try {
      library_ = DynamicLibrary::open({"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"});
      osmesa_.CreateContextAttribs =
          library_.function<CreateContextAttribsFn>("OSMesaCreateContextAttribs");
      osmesa_.DestroyContext = library_.function<DestroyContextFn>("OSMesaDestroyContext");
      osmesa_.MakeCurrent = library_.function<MakeCurrentFn>("OSMesaMakeCurrent");
      osmesa_.GetCurrentContext =
          library_.function<GetCurrentContextFn>("OSMesaGetCurrentContext");
      osmesa_.GetProcAddress = library_.function<GetProcAddressFn>("OSMesaGetProcAddress");
    } catch (const Error& error) {
      throw Error("OSMesa: " + error.description());
    }
    // OSMesa reports no error codes: a null context is all we learn.
    for (int minor = 5; minor >= 1 && !context_; --minor) {
      const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                OSMESA_DEPTH_BITS, 0,
                                OSMESA_STENCIL_BITS, 0,
                                OSMESA_ACCUM_BITS, 0,
                                OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                OSMESA_CONTEXT_MINOR_VERSION, minor,
                                0};
      context_ = osmesa_.CreateContextAttribs(attributes, nullptr);
    }
    if (!context_) {
      throw Error("OSMesa: OSMesaCreateContextAttribs failed for OpenGL 4.5 to 4.1 core (" +
                  library_.name() + ")");
    }
    try {
      makeCurrent();
      functions_.load(loadGlFunction, &osmesa_, "OSMesa");
      info_ = queryContextInfo(functions_, Backend::OsMesa, "OSMesa");
    } catch (...) {
      destroy();
      throw;
    }
  }

  ~OsMesaContext() override { destroy(); }

  void makeCurrent() override {
    if (!osmesa_.MakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize,
                             kBufferSize)) {
      throw Error("OSMesa: OSMesaMakeCurrent failed");
    }
  }

  void releaseCurrent() override {
    if (osmesa_.GetCurrentContext() != context_) return;
    if (!osmesa_.MakeCurrent(nullptr, nullptr, 0, 0, 0)) {
      throw Error("OSMesa: OSMesaMakeCurrent (release) failed");
    }
  }

 private:
  void destroy() noexcept {
    if (!context_) return;
    if (osmesa_.GetCurrentContext() == context_) osmesa_.MakeCurrent(nullptr, nullptr, 0, 0, 0);
    osmesa_.DestroyContext(context_);
    context_ = nullptr;
  }

  DynamicLibrary library_;
  OsMesaApi osmesa_;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Context> createOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace taa::gl
