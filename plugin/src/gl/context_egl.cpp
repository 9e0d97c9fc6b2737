// The EGL back end: a surfaceless OpenGL core context on the EGL device platform when a
// hardware device is present, otherwise on Mesa's surfaceless platform (llvmpipe).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "gl/context_backends.h"
#include "gl/dynamic_library.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

struct EglApi {
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLGETERRORPROC GetError = nullptr;
  PFNEGLQUERYSTRINGPROC QueryString = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLTERMINATEPROC Terminate = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCHOOSECONFIGPROC ChooseConfig = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLGETCURRENTCONTEXTPROC GetCurrentContext = nullptr;
  // Extensions: null when the implementation lacks them.
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT = nullptr;
  PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceStringEXT = nullptr;
};

const char* eglErrorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
  }
  return "unknown EGL error";
}

[[noreturn]] void fail(const EglApi& egl, const std::string& step) {
  throw Error("EGL: " + step + " failed (" + eglErrorName(egl.GetError()) + ")");
}

// eglInitialize is not reference counted, and eglGetPlatformDisplayEXT returns the same handle
// for the same device, so contexts share displays: terminate only when the last one goes, and
// never a display someone else in the process initialized before us.
class DisplayUsers {
 public:
  static void acquire(const EglApi& egl, EGLDisplay display) {
    std::lock_guard<std::mutex> lock(mutex());
    Entry& entry = entries()[display];
    if (entry.users == 0) {
      entry.ownedByUs = egl.QueryString(display, EGL_VENDOR) == nullptr;
      egl.GetError();  // the probe sets EGL_NOT_INITIALIZED; that is the expected answer
      EGLint major = 0, minor = 0;
      if (entry.ownedByUs && !egl.Initialize(display, &major, &minor)) {
        entries().erase(display);
        fail(egl, "eglInitialize");
      }
    }
    ++entry.users;
  }

  static void release(const EglApi& egl, EGLDisplay display) noexcept {
    std::lock_guard<std::mutex> lock(mutex());
    auto found = entries().find(display);
    if (found == entries().end() || --found->second.users > 0) return;
    if (found->second.ownedByUs) egl.Terminate(display);
    entries().erase(found);
  }

 private:
  struct Entry {
    int users = 0;
    bool ownedByUs = false;
  };
  static std::mutex& mutex() {
    static std::mutex instance;
    return instance;
  }
  static std::map<EGLDisplay, Entry>& entries() {
    static std::map<EGLDisplay, Entry> instance;
    return instance;
  }
};

// The display use and context of one attempt; releases whatever was made, in reverse order.
struct EglResources {
  const EglApi* egl = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;

  ~EglResources() { reset(); }
  void reset() noexcept {
    if (context != EGL_NO_CONTEXT) {
      egl->BindAPI(EGL_OPENGL_API);
      if (egl->GetCurrentContext() == context) {
        egl->MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      }
      egl->DestroyContext(display, context);
      context = EGL_NO_CONTEXT;
    }
    if (display != EGL_NO_DISPLAY) DisplayUsers::release(*egl, display);
    display = EGL_NO_DISPLAY;
  }
};

void* loadGlFunction(const char* name, void* userData) {
  const EglApi& egl = *static_cast<const EglApi*>(userData);
  return reinterpret_cast<void*>(egl.GetProcAddress(name));
}

class EglContext final : public Context {
 public:
  EglContext() {
    try {
      library_ = DynamicLibrary::open({"libEGL.so.1", "libEGL.so"});
      loadApi();
    } catch (const Error& error) {
      throw Error("EGL: " + error.description());
    }
    resources_.egl = &egl_;
    const char* clientExtensions = egl_.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!egl_.GetPlatformDisplayEXT || !hasExtension(clientExtensions, "EGL_EXT_platform_base")) {
      throw Error("EGL: EGL_EXT_platform_base is not supported");
    }
    std::string deviceFailure = tryHardwareDevices(clientExtensions);
    if (resources_.context != EGL_NO_CONTEXT) return;
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
      throw Error("EGL: no usable hardware device" +
                  (deviceFailure.empty() ? std::string() : " (" + deviceFailure + ")") +
                  " and the surfaceless platform (EGL_MESA_platform_surfaceless) is missing");
    }
    EGLDisplay display =
        egl_.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    try {
      open(display, "EGL surfaceless");
    } catch (const Error& error) {
      if (deviceFailure.empty()) throw;
      throw Error(error.description() + "; before that, " + deviceFailure);
    }
  }

  void makeCurrent() override {
    egl_.BindAPI(EGL_OPENGL_API);  // the bound API is per thread; a new thread starts with ES
    // Mesa skips a make-current of the context EGL believes is current, but another library
    // (OSMesa, which shares Mesa's GL dispatch) may have bound its own context on this thread
    // since: unbind first so that the bind below really happens.
    if (egl_.GetCurrentContext() == resources_.context) {
      egl_.MakeCurrent(resources_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (!egl_.MakeCurrent(resources_.display, EGL_NO_SURFACE, EGL_NO_SURFACE,
                          resources_.context)) {
      fail(egl_, "eglMakeCurrent");
    }
  }

  void releaseCurrent() override {
    egl_.BindAPI(EGL_OPENGL_API);
    if (egl_.GetCurrentContext() != resources_.context) return;
    if (!egl_.MakeCurrent(resources_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT)) {
      fail(egl_, "eglMakeCurrent (release)");
    }
  }

 private:
  template <typename FunctionPointer>
  void load(FunctionPointer& target, const char* name) {
    target = library_.function<FunctionPointer>(name);
  }

  void loadApi() {
    load(egl_.GetProcAddress, "eglGetProcAddress");
    load(egl_.GetError, "eglGetError");
    load(egl_.QueryString, "eglQueryString");
    load(egl_.Initialize, "eglInitialize");
    load(egl_.Terminate, "eglTerminate");
    load(egl_.BindAPI, "eglBindAPI");
    load(egl_.ChooseConfig, "eglChooseConfig");
    load(egl_.CreateContext, "eglCreateContext");
    load(egl_.DestroyContext, "eglDestroyContext");
    load(egl_.MakeCurrent, "eglMakeCurrent");
    load(egl_.GetCurrentContext, "eglGetCurrentContext");
    egl_.GetPlatformDisplayEXT = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        egl_.GetProcAddress("eglGetPlatformDisplayEXT"));
    egl_.QueryDevicesEXT =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl_.GetProcAddress("eglQueryDevicesEXT"));
    egl_.QueryDeviceStringEXT = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        egl_.GetProcAddress("eglQueryDeviceStringEXT"));
  }

  // Opens the first hardware (not EGL_MESA_device_software) device that gives a context.
  // Returns why the devices could not be used, empty when there were none to try.
  std::string tryHardwareDevices(const char* clientExtensions) {
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_device") ||
        !hasExtension(clientExtensions, "EGL_EXT_device_enumeration") || !egl_.QueryDevicesEXT ||
        !egl_.QueryDeviceStringEXT) {
      return {};
    }
    EGLint count = 0;
    if (!egl_.QueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    if (!egl_.QueryDevicesEXT(count, devices.data(), &count)) return {};
    std::string failures;
    for (EGLint i = 0; i < count; ++i) {
      const char* extensions = egl_.QueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
      if (hasExtension(extensions, "EGL_MESA_device_software")) continue;
      try {
        open(egl_.GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
             "EGL device");
        return {};
      } catch (const Error& error) {
        resources_.reset();
        failures += (failures.empty() ? "device " : "; device ") + std::to_string(i) + ": " +
                    error.description();
      }
    }
    return failures;
  }

  // Initializes `display` and makes a current core-profile context on it.
  void open(EGLDisplay display, const std::string& platform) {
    const std::string where = platform + ": ";
    if (display == EGL_NO_DISPLAY) fail(egl_, where + "eglGetPlatformDisplayEXT");
    DisplayUsers::acquire(egl_, display);
    resources_.display = display;

    const char* extensions = egl_.QueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
      throw Error("EGL: " + where + "EGL_KHR_surfaceless_context is not supported");
    }
    if (!egl_.BindAPI(EGL_OPENGL_API)) fail(egl_, where + "eglBindAPI(EGL_OPENGL_API)");

    EGLConfig config = chooseConfig(display, extensions, where);
    EGLint lastError = EGL_SUCCESS;
    for (int minor = 5; minor >= 1 && resources_.context == EGL_NO_CONTEXT; --minor) {
      const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                   EGL_CONTEXT_MINOR_VERSION, minor,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
      resources_.context = egl_.CreateContext(display, config, EGL_NO_CONTEXT, attributes);
      if (resources_.context == EGL_NO_CONTEXT) lastError = egl_.GetError();
    }
    if (resources_.context == EGL_NO_CONTEXT) {
      throw Error("EGL: " + where + "eglCreateContext for OpenGL 4.5 to 4.1 core failed (" +
                  eglErrorName(lastError) + ")");
    }
    if (!egl_.MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, resources_.context)) {
      fail(egl_, where + "eglMakeCurrent");
    }
    functions_.load(loadGlFunction, &egl_, "EGL");
    info_ = queryContextInfo(functions_, Backend::Egl, platform);
  }

  EGLConfig chooseConfig(EGLDisplay display, const char* extensions, const std::string& where) {
    // Rendering goes to framebuffer objects, so any config will do, or none at all.
    if (hasExtension(extensions, "EGL_KHR_no_config_context")) return EGL_NO_CONFIG_KHR;
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                 EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!egl_.ChooseConfig(display, attributes, &config, 1, &count)) {
      fail(egl_, where + "eglChooseConfig");
    }
    if (count < 1) throw Error("EGL: " + where + "no config supports desktop OpenGL");
    return config;
  }

  DynamicLibrary library_;
  EglApi egl_;
  EglResources resources_;  // declared last: released before the library and API go
};

}  // namespace

std::unique_ptr<Context> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace taa::gl
