// gl::CallerContext: whatever EGL or OSMesa context the calling thread had current is current
// again after taa bound, used and released its own, for every pair of back ends (Mesa's EGL
// and OSMesa share one GL dispatch, so binding one behind the other's back is the hard case).
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <tuple>

#include "gl/caller_context.h"
#include "gl/context.h"

namespace taa::gl {
namespace {

const void* currentNativeContext(Backend backend) {
  const bool egl = backend == Backend::Egl;
  void* library = dlopen(egl ? "libEGL.so.1" : "libOSMesa.so.8", RTLD_LAZY | RTLD_NOLOAD);
  if (!library) return nullptr;
  auto current = reinterpret_cast<void* (*)()>(
      dlsym(library, egl ? "eglGetCurrentContext" : "OSMesaGetCurrentContext"));
  const void* context = current ? current() : nullptr;
  dlclose(library);
  return context;
}

// (the caller's back end, taa's back end)
class CallerContextTest : public ::testing::TestWithParam<std::tuple<Backend, Backend>> {};

TEST_P(CallerContextTest, CallersContextIsCurrentAgain) {
  const auto [callerBackend, taaBackend] = GetParam();
  const std::unique_ptr<Context> caller = Context::create(callerBackend);  // left current
  const void* before = currentNativeContext(callerBackend);
  ASSERT_NE(before, nullptr);
  {
    const CallerContext saved;
    EXPECT_TRUE(saved.hadContext());
    const std::unique_ptr<Context> ours = Context::create(taaBackend);  // binds ours
    EXPECT_NE(ours->functions().GetString(GL_RENDERER), nullptr);
    ours->releaseCurrent();
  }
  EXPECT_EQ(currentNativeContext(callerBackend), before);
  // GL calls reach a context again (with none, Mesa's dispatch answers NULL).
  EXPECT_NE(caller->functions().GetString(GL_RENDERER), nullptr);
  caller->releaseCurrent();
}

TEST(CallerContext, NoCallerContextLeavesNoneCurrent) {
  {
    const CallerContext saved;
    EXPECT_FALSE(saved.hadContext());
    const std::unique_ptr<Context> ours = Context::create(Backend::Egl);
    ours->releaseCurrent();
  }
  EXPECT_EQ(currentNativeContext(Backend::Egl), nullptr);
}

std::string pairName(const ::testing::TestParamInfo<std::tuple<Backend, Backend>>& param) {
  return std::string("caller_") + backendName(std::get<0>(param.param)) + "_taa_" +
         backendName(std::get<1>(param.param));
}

INSTANTIATE_TEST_SUITE_P(Backends, CallerContextTest,
                         ::testing::Combine(::testing::Values(Backend::Egl, Backend::OsMesa),
                                            ::testing::Values(Backend::Egl, Backend::OsMesa)),
                         pairName);

}  // namespace
}  // namespace taa::gl
