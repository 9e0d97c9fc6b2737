// A host with its own OpenGL context current on the render thread (a viewer, an OpenGL
// compositor) has that context current again after every call into the plugin: the first
// render (which makes the plugin's own context), the following ones, and purge caches (which
// destroys it). Both kinds of context taa knows are tried as the host's: EGL and OSMesa.
#include <dlfcn.h>

#include "gl/context.h"
#include "ofx_host_fixture.h"

namespace taa::ofxtest {
namespace {

// The context current on this thread as the back end's own library reports it.
const void* currentNativeContext(gl::Backend backend) {
  const bool egl = backend == gl::Backend::Egl;
  void* library = dlopen(egl ? "libEGL.so.1" : "libOSMesa.so.8", RTLD_LAZY | RTLD_NOLOAD);
  if (!library) return nullptr;
  auto current = reinterpret_cast<void* (*)()>(
      dlsym(library, egl ? "eglGetCurrentContext" : "OSMesaGetCurrentContext"));
  const void* context = current ? current() : nullptr;
  dlclose(library);
  return context;
}

class OfxHostGlContextTest : public OfxHostTest,
                             public ::testing::WithParamInterface<gl::Backend> {};

TEST_P(OfxHostGlContextTest, HostContextIsCurrentAfterEveryCall) {
  auto effect = instance();
  const std::unique_ptr<gl::Context> hostContext = gl::Context::create(GetParam());  // current
  const void* before = currentNativeContext(GetParam());
  ASSERT_NE(before, nullptr);
  auto stillCurrent = [&](const char* after) {
    EXPECT_EQ(currentNativeContext(GetParam()), before) << "after " << after;
    // GL calls reach a context: with none current, Mesa's dispatch answers NULL.
    EXPECT_NE(hostContext->functions().GetString(GL_RENDERER), nullptr) << "after " << after;
  };
  EXPECT_LE(maxDifference(render(*effect, 1), expected(1)), 1e-5f);
  stillCurrent("the first render");
  EXPECT_LE(maxDifference(render(*effect, 2), expected(2)), 1e-5f);
  stillCurrent("the second render");
  EXPECT_EQ(host_.action(kOfxActionPurgeCaches, effect.get()), kOfxStatOK);
  stillCurrent("purge caches");
  destroy(effect);
  stillCurrent("destroying the instance");
  hostContext->releaseCurrent();
}

INSTANTIATE_TEST_SUITE_P(Backends, OfxHostGlContextTest,
                         ::testing::Values(gl::Backend::Egl, gl::Backend::OsMesa),
                         [](const ::testing::TestParamInfo<gl::Backend>& param) {
                           return std::string(gl::backendName(param.param));
                         });

}  // namespace
}  // namespace taa::ofxtest
