#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/self_test.h"
#include "gl_test_support.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;

class ContextTest : public ::testing::TestWithParam<Backend> {};

TEST_P(ContextTest, CreatesA41CoreContextAndDescribesIt) {
  std::unique_ptr<Context> context = Context::create(GetParam());
  ASSERT_NE(context, nullptr);
  const ContextInfo& info = context->info();
  EXPECT_EQ(info.backend, GetParam());
  EXPECT_FALSE(info.vendor.empty());
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_FALSE(info.version.empty());
  EXPECT_FALSE(info.glslVersion.empty());
  if (GetParam() == Backend::Egl) {
    EXPECT_THAT(info.platform, AnyOf("EGL device", "EGL surfaceless"));
  } else {
    EXPECT_EQ(info.platform, "OSMesa");
  }
  GLint major = 0, minor = 0, profile = 0;
  context->functions().GetIntegerv(GL_MAJOR_VERSION, &major);
  context->functions().GetIntegerv(GL_MINOR_VERSION, &minor);
  context->functions().GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 41) << info.version;
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << info.version;
  std::cout << "[ info     ] " << backendName(info.backend) << " (" << info.platform
            << "): " << info.vendor << " | " << info.renderer << " | " << info.version
            << " | GLSL " << info.glslVersion << "\n";
}

TEST_P(ContextTest, SelfTestReadsTheKnownPatternBackExactly) {
  std::unique_ptr<Context> context = Context::create(GetParam());
  const SelfTestResult result = runSelfTest(*context);
  EXPECT_TRUE(result.passed) << result.detail;
  // Odd and tiny sizes too: row order or viewport mistakes show up as mismatches.
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{1, 1}, {3, 64}, {64, 3}}) {
    const SelfTestResult sized = runSelfTest(*context, width, height);
    EXPECT_TRUE(sized.passed) << width << "x" << height << ": " << sized.detail;
  }
}

TEST_P(ContextTest, SelfTestReportsGlFailuresInsteadOfThrowing) {
  std::unique_ptr<Context> context = Context::create(GetParam());
  const SelfTestResult result = runSelfTest(*context, 0, 5);
  EXPECT_FALSE(result.passed);
  EXPECT_THAT(result.detail, HasSubstr("not positive"));
}

INSTANTIATE_TEST_SUITE_P(Backends, ContextTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         test::backendParamName);

TEST(ContextAuto, PrefersEglAndExplainsAnyFallback) {
  std::vector<std::string> messages;
  std::unique_ptr<Context> context =
      Context::create(Backend::Auto, [&](const std::string& line) { messages.push_back(line); });
  ASSERT_NE(context, nullptr);
  EXPECT_NE(context->info().backend, Backend::Auto);
  if (context->info().backend == Backend::Egl) {
    EXPECT_TRUE(messages.empty());
  } else {
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_THAT(messages[0], HasSubstr("falling back to OSMesa"));
  }
  EXPECT_TRUE(runSelfTest(*context).passed);
}

// Runs in a fresh process (threadsafe death-test style re-executes the binary), so that glvnd
// reads the vendor list from the environment we set: with no vendor, EGL must fail cleanly.
TEST(ContextAutoDeathTest, FallsBackToOsMesaWhenEglIsUnusable) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/taa_no_vendor.json", 1);
        bool eglThrew = false;
        try {
          Context::create(Backend::Egl);
        } catch (const Error& error) {
          eglThrew = std::string(error.what()).rfind("EGL: ", 0) == 0;
        }
        std::string log;
        std::unique_ptr<Context> context =
            Context::create(Backend::Auto, [&](const std::string& line) { log += line; });
        const bool fellBack = context->info().backend == Backend::OsMesa;
        const bool rendered = runSelfTest(*context).passed;
        std::fprintf(stderr, "%s\n", log.c_str());
        std::_Exit(eglThrew && fellBack && rendered ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "falling back to OSMesa: EGL: ");
}

}  // namespace
}  // namespace taa::gl
