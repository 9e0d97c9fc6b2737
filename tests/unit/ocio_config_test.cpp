#include <gtest/gtest.h>

#include <OpenColorIO/OpenColorIO.h>

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

}  // namespace
