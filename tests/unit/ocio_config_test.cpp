#include <gtest/gtest.h>

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>

namespace OCIO = OCIO_NAMESPACE;

namespace {

OCIO::ConstConfigRcPtr shippedConfig() {
  return OCIO::Config::CreateFromFile(TAA_SOURCE_DIR "/ocio/config.ocio");
}

TEST(ShippedOcioConfig, LoadsAndValidates) {
  OCIO::ConstConfigRcPtr config = shippedConfig();
  ASSERT_TRUE(config);
  EXPECT_NO_THROW(config->validate());
  EXPECT_STREQ(config->getColorSpace("scene_linear")->getName(), "linear");
  EXPECT_TRUE(config->getColorSpace("taa_log2"));
}

TEST(ShippedOcioConfig, Log2WorkingSpaceRoundTripsOverHalfRange) {
  OCIO::ConstConfigRcPtr config = shippedConfig();
  auto forward = config->getProcessor("linear", "taa_log2")->getDefaultCPUProcessor();
  auto inverse = config->getProcessor("taa_log2", "linear")->getDefaultCPUProcessor();
  float pixel[3];
  for (float value : {0.0f, 1e-4f, 0.0078125f, 0.18f, 1.0f, 10.0f, 1000.0f, 65504.0f}) {
    pixel[0] = pixel[1] = pixel[2] = value;
    forward->applyRGB(pixel);
    if (value == 1.0f) {
      EXPECT_NEAR(pixel[0], 7.0f / 24.0f, 1e-6f);  // 1.0 sits 7 stops up
    }
    inverse->applyRGB(pixel);
    EXPECT_NEAR(pixel[0], value, 1e-5f * std::max(1.0f, value)) << value;
  }
}

// Issue 17: every shipped bracket maps the signed half range to finite working values and back.
TEST(ShippedOcioConfig, EveryWorkingSpaceRoundTripsNegativesOnTheCpu) {
  OCIO::ConstConfigRcPtr config = shippedConfig();
  for (const char* space : {"taa_log2", "taa_reinhard"}) {
    auto forward = config->getProcessor("linear", space)->getDefaultCPUProcessor();
    auto inverse = config->getProcessor(space, "linear")->getDefaultCPUProcessor();
    for (float value : {-65504.0f, -1000.0f, -5.0f, -4.0f, -1.0f, -1e-3f, 0.0f, 1e-3f, 65504.0f}) {
      float pixel[3] = {value, value, value};
      forward->applyRGB(pixel);
      EXPECT_TRUE(std::isfinite(pixel[0])) << space << " forward of " << value;
      inverse->applyRGB(pixel);
      EXPECT_NEAR(pixel[0], value, 1e-3f * std::max(1.0f, std::abs(value))) << space << " " << value;
    }
  }
  // The reinhard bracket's negative side is linear with the positive side's slope at 0.
  auto reinhard = config->getProcessor("linear", "taa_reinhard")->getDefaultCPUProcessor();
  float pixel[3] = {-1000.0f, -4.0f, -1e-3f};
  reinhard->applyRGB(pixel);
  EXPECT_NEAR(pixel[0], -250.0f, 1e-2f);
  EXPECT_NEAR(pixel[1], -1.0f, 1e-6f);
  EXPECT_NEAR(pixel[2], -2.5e-4f, 1e-7f);  // 1 - 2^w cancels: the positive side alike
}

}  // namespace
