#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "gl/context.h"
#include "gl/objects.h"
#include "gl/self_test.h"
#include "gl_test_support.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

// One context's own texture + framebuffer filled with a value only it holds, so that reading
// it back proves which context is really current.
class MarkedTarget {
 public:
  MarkedTarget(const Functions& gl, float marker)
      : marker_(marker), texture_(gl, 5, 3, GL_RGBA32F), framebuffer_(gl, texture_) {
    const std::vector<float> data(5 * 3 * 4, marker);
    texture_.upload(data.data(), 4);
  }
  // Number of values that differ from the marker.
  int mismatches() const {
    int count = 0;
    for (float value : framebuffer_.readRGBA()) count += value != marker_;
    return count;
  }

 private:
  float marker_;
  Texture texture_;
  Framebuffer framebuffer_;
};

TEST(MultiContext, EglAndOsMesaAliveAtOnceEachRenderTheirOwnObjects) {
  std::unique_ptr<Context> egl = Context::create(Backend::Egl);
  auto eglTarget = std::make_unique<MarkedTarget>(egl->functions(), 1.5f);
  std::unique_ptr<Context> osmesa = Context::create(Backend::OsMesa);
  auto osmesaTarget = std::make_unique<MarkedTarget>(osmesa->functions(), -2.5f);

  // Switch back and forth on one thread: the object names (1, 2, ...) are the same in both
  // contexts, so a switch that did not really happen reads the other context's marker.
  for (int round = 0; round < 3; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    egl->makeCurrent();
    EXPECT_EQ(eglTarget->mismatches(), 0) << "EGL context read another context's objects";
    SelfTestResult eglResult = runSelfTest(*egl, 9 + round, 4);
    EXPECT_TRUE(eglResult.passed) << eglResult.detail;

    osmesa->makeCurrent();
    EXPECT_EQ(osmesaTarget->mismatches(), 0) << "OSMesa context read another context's objects";
    SelfTestResult osmesaResult = runSelfTest(*osmesa, 4, 9 + round);
    EXPECT_TRUE(osmesaResult.passed) << osmesaResult.detail;
  }
  osmesa->makeCurrent();
  osmesaTarget.reset();
  egl->makeCurrent();
  eglTarget.reset();
}

TEST(MultiContext, TwoEglContextsShareTheDisplaySafely) {
  std::unique_ptr<Context> first = Context::create(Backend::Egl);
  std::unique_ptr<Context> second = Context::create(Backend::Egl);
  first.reset();  // must not terminate the display the second still uses
  EXPECT_TRUE(runSelfTest(*second).passed);
  std::unique_ptr<Context> third = Context::create(Backend::Egl);
  EXPECT_TRUE(runSelfTest(*third).passed);
}

// Each thread creates its own context and renders repeatedly while the other does the same.
void renderInThread(Backend backend, int seed, std::string* failure) {
  try {
    std::unique_ptr<Context> context = Context::create(backend);
    for (int i = 0; i < 6; ++i) {
      const SelfTestResult result = runSelfTest(*context, 17 + seed + i, 11 + i);
      if (!result.passed) {
        *failure = result.detail;
        return;
      }
      MarkedTarget target(context->functions(), static_cast<float>(seed * 100 + i));
      if (target.mismatches() != 0) {
        *failure = "texture read back wrong values";
        return;
      }
    }
  } catch (const Error& error) {
    *failure = error.what();
  }
}

std::string pairName(const ::testing::TestParamInfo<std::pair<Backend, Backend>>& param) {
  return std::string(backendName(param.param.first)) + "_" + backendName(param.param.second);
}

class ParallelContexts : public ::testing::TestWithParam<std::pair<Backend, Backend>> {};

TEST_P(ParallelContexts, RenderCorrectlyInTwoThreadsAtOnce) {
  std::string firstFailure, secondFailure;
  std::thread first(renderInThread, GetParam().first, 1, &firstFailure);
  std::thread second(renderInThread, GetParam().second, 2, &secondFailure);
  first.join();
  second.join();
  EXPECT_EQ(firstFailure, "") << backendName(GetParam().first);
  EXPECT_EQ(secondFailure, "") << backendName(GetParam().second);
}

INSTANTIATE_TEST_SUITE_P(
    Pairs, ParallelContexts,
    ::testing::Values(std::make_pair(Backend::Egl, Backend::Egl),
                      std::make_pair(Backend::OsMesa, Backend::OsMesa),
                      std::make_pair(Backend::Egl, Backend::OsMesa)),
    pairName);

class HandOff : public ::testing::TestWithParam<Backend> {};

TEST_P(HandOff, AContextMovesBetweenThreadsOneAtATime) {
  std::unique_ptr<Context> context = Context::create(GetParam());
  MarkedTarget target(context->functions(), 42.0f);
  context->releaseCurrent();
  std::string failure;
  std::thread worker([&] {
    try {
      context->makeCurrent();
      const SelfTestResult result = runSelfTest(*context);
      if (!result.passed) failure = result.detail;
      if (target.mismatches() != 0) failure += " marker texture lost";
      context->releaseCurrent();
    } catch (const Error& error) {
      failure = error.what();
    }
  });
  worker.join();
  EXPECT_EQ(failure, "");
  context->makeCurrent();
  EXPECT_EQ(target.mismatches(), 0);
  EXPECT_TRUE(runSelfTest(*context).passed);
}

INSTANTIATE_TEST_SUITE_P(Backends, HandOff, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         test::backendParamName);

}  // namespace
}  // namespace taa::gl
