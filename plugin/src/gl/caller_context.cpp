#include "gl/caller_context.h"

#include <EGL/egl.h>
#include <dlfcn.h>

#include "gl/gl_functions.h"  // glcorearb.h first: osmesa.h pulls in the legacy GL/gl.h

#include <GL/osmesa.h>

#include <vector>

namespace taa::gl {
namespace {

// A library the process has already loaded (never loads one), closed again on destruction.
class LoadedLibrary {
 public:
  explicit LoadedLibrary(std::initializer_list<const char*> names) {
    for (const char* name : names) {
      handle_ = dlopen(name, RTLD_LAZY | RTLD_NOLOAD);
      if (handle_) return;
    }
  }
  ~LoadedLibrary() {
    if (handle_) dlclose(handle_);
  }
  LoadedLibrary(const LoadedLibrary&) = delete;
  LoadedLibrary& operator=(const LoadedLibrary&) = delete;

  explicit operator bool() const { return handle_ != nullptr; }
  template <typename Function>
  Function function(const char* name) const {
    return handle_ ? reinterpret_cast<Function>(dlsym(handle_, name)) : nullptr;
  }

 private:
  void* handle_ = nullptr;
};

struct EglCalls {
  EGLenum (*QueryAPI)() = nullptr;
  EGLBoolean (*BindAPI)(EGLenum) = nullptr;
  EGLContext (*GetCurrentContext)() = nullptr;
  EGLDisplay (*GetCurrentDisplay)() = nullptr;
  EGLSurface (*GetCurrentSurface)(EGLint) = nullptr;
  EGLBoolean (*MakeCurrent)(EGLDisplay, EGLSurface, EGLSurface, EGLContext) = nullptr;
  EGLBoolean (*QueryContext)(EGLDisplay, EGLContext, EGLint, EGLint*) = nullptr;

  explicit EglCalls(const LoadedLibrary& egl) {
    QueryAPI = egl.function<decltype(QueryAPI)>("eglQueryAPI");
    BindAPI = egl.function<decltype(BindAPI)>("eglBindAPI");
    GetCurrentContext = egl.function<decltype(GetCurrentContext)>("eglGetCurrentContext");
    GetCurrentDisplay = egl.function<decltype(GetCurrentDisplay)>("eglGetCurrentDisplay");
    GetCurrentSurface = egl.function<decltype(GetCurrentSurface)>("eglGetCurrentSurface");
    MakeCurrent = egl.function<decltype(MakeCurrent)>("eglMakeCurrent");
    QueryContext = egl.function<decltype(QueryContext)>("eglQueryContext");
  }
  bool complete() const {
    return QueryAPI && BindAPI && GetCurrentContext && GetCurrentDisplay && GetCurrentSurface &&
           MakeCurrent && QueryContext;
  }
};

struct EglCurrent {
  EGLenum api = EGL_OPENGL_API;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLSurface draw = EGL_NO_SURFACE, read = EGL_NO_SURFACE;
  EGLContext context = EGL_NO_CONTEXT;
};

struct OsMesaCalls {
  OSMesaContext (*GetCurrentContext)() = nullptr;
  GLboolean (*GetColorBuffer)(OSMesaContext, GLint*, GLint*, GLint*, void**) = nullptr;
  void (*GetIntegerv)(GLint, GLint*) = nullptr;
  GLboolean (*MakeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  void (*PixelStore)(GLint, GLint) = nullptr;

  explicit OsMesaCalls(const LoadedLibrary& osmesa) {
    GetCurrentContext = osmesa.function<decltype(GetCurrentContext)>("OSMesaGetCurrentContext");
    GetColorBuffer = osmesa.function<decltype(GetColorBuffer)>("OSMesaGetColorBuffer");
    GetIntegerv = osmesa.function<decltype(GetIntegerv)>("OSMesaGetIntegerv");
    MakeCurrent = osmesa.function<decltype(MakeCurrent)>("OSMesaMakeCurrent");
    PixelStore = osmesa.function<decltype(PixelStore)>("OSMesaPixelStore");
  }
  bool complete() const {
    return GetCurrentContext && GetColorBuffer && GetIntegerv && MakeCurrent && PixelStore;
  }
};

struct OsMesaCurrent {
  OSMesaContext context = nullptr;
  void* buffer = nullptr;
  GLint type = GL_UNSIGNED_BYTE, width = 0, height = 0, rowLength = 0, yUp = 1;
};

}  // namespace

struct CallerContext::Saved {
  LoadedLibrary eglLibrary{"libEGL.so.1", "libEGL.so"};
  LoadedLibrary osmesaLibrary{"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
  bool eglQueried = false;
  EGLenum boundApi = EGL_OPENGL_ES_API;  // EGL's per-thread default; taa binds OpenGL
  std::vector<EglCurrent> egl;
  OsMesaCurrent osmesa;

  void saveEgl(const EglCalls& calls) {
    eglQueried = true;
    boundApi = calls.QueryAPI();
    for (EGLenum api : {boundApi, EGLenum(EGL_OPENGL_API), EGLenum(EGL_OPENGL_ES_API)}) {
      if (!calls.BindAPI(api)) continue;
      EglCurrent current;
      current.context = calls.GetCurrentContext();
      if (current.context == EGL_NO_CONTEXT) continue;
      bool known = false;
      for (const EglCurrent& saved : egl) known = known || saved.context == current.context;
      if (known) continue;
      current.display = calls.GetCurrentDisplay();
      current.draw = calls.GetCurrentSurface(EGL_DRAW);
      current.read = calls.GetCurrentSurface(EGL_READ);
      // The context's own API (some EGLs report one current context whatever API is bound).
      EGLint type = 0;
      current.api = calls.QueryContext(current.display, current.context,
                                       EGL_CONTEXT_CLIENT_TYPE, &type)
                        ? EGLenum(type)
                        : api;
      egl.push_back(current);
    }
    calls.BindAPI(boundApi);
  }

  void restoreEgl(const EglCalls& calls) const {
    for (const EglCurrent& saved : egl) {
      calls.BindAPI(saved.api);
      // EGL skips binding the context it believes current, though OSMesa (sharing Mesa's GL
      // dispatch) may have replaced it since: unbind it first so that the bind is real.
      if (calls.GetCurrentContext() == saved.context) {
        calls.MakeCurrent(saved.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      }
      calls.MakeCurrent(saved.display, saved.draw, saved.read, saved.context);
    }
    calls.BindAPI(boundApi);
  }

  void saveOsMesa(const OsMesaCalls& calls) {
    OSMesaContext context = calls.GetCurrentContext();
    if (!context) return;
    GLint format = 0;
    if (!calls.GetColorBuffer(context, &osmesa.width, &osmesa.height, &format, &osmesa.buffer)) {
      return;
    }
    calls.GetIntegerv(OSMESA_TYPE, &osmesa.type);
    calls.GetIntegerv(OSMESA_ROW_LENGTH, &osmesa.rowLength);
    calls.GetIntegerv(OSMESA_Y_UP, &osmesa.yUp);
    osmesa.context = context;
  }

  void restoreOsMesa(const OsMesaCalls& calls) const {
    if (!osmesa.context) return;
    if (!calls.MakeCurrent(osmesa.context, osmesa.buffer, GLenum(osmesa.type), osmesa.width,
                           osmesa.height)) {
      return;
    }
    calls.PixelStore(OSMESA_ROW_LENGTH, osmesa.rowLength);
    calls.PixelStore(OSMESA_Y_UP, osmesa.yUp);
  }
};

CallerContext::CallerContext() : saved_(std::make_unique<Saved>()) {
  if (saved_->eglLibrary) {
    const EglCalls calls(saved_->eglLibrary);
    if (calls.complete()) saved_->saveEgl(calls);
  }
  // OSMesa answers from Mesa's shared GL dispatch, so with an EGL (or GLX) context current its
  // "current context" is not an OSMesa context: ask it only when EGL has none.
  if (saved_->egl.empty() && saved_->osmesaLibrary) {
    const OsMesaCalls calls(saved_->osmesaLibrary);
    if (calls.complete()) saved_->saveOsMesa(calls);
  }
}

CallerContext::~CallerContext() {
  if (saved_->eglQueried) saved_->restoreEgl(EglCalls(saved_->eglLibrary));
  if (saved_->osmesa.context) saved_->restoreOsMesa(OsMesaCalls(saved_->osmesaLibrary));
}

bool CallerContext::hadContext() const {
  return !saved_->egl.empty() || saved_->osmesa.context != nullptr;
}

}  // namespace taa::gl
