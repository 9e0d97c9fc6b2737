// Named configurations: the file format, ad-hoc ones, and the fixed classic baseline.
#include <gtest/gtest.h>

#include "taa/error.h"
#include "yardstick/configurations.h"

namespace taa::yardstick {
namespace {

TEST(YardstickConfigurations, SplitsFlagsWithQuotes) {
  EXPECT_EQ(splitFlags("  --blend 0.1   --bracket 'a b' \"c\"d "),
            (std::vector<std::string>{"--blend", "0.1", "--bracket", "a b", "cd"}));
  EXPECT_TRUE(splitFlags("").empty());
  EXPECT_THROW(splitFlags("--bracket 'open"), Error);
}

TEST(YardstickConfigurations, ParsesFileWithCommentsAndEmptyFlags) {
  const auto configs = parseConfigurations(
      "# comment\n\nclassic --rectify clamp  # trailing\ndefault\n");
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_EQ(configs[0].name, "classic");
  EXPECT_EQ(configs[0].flags, (std::vector<std::string>{"--rectify", "clamp"}));
  EXPECT_EQ(configs[1].name, "default");
  EXPECT_TRUE(configs[1].flags.empty());
  EXPECT_THROW(parseConfigurations("a\na --blend 1\n"), Error);
}

TEST(YardstickConfigurations, AdHocNameEqualsFlags) {
  const Configuration c = parseAdHocConfiguration("reinhard=--bracket taa_reinhard");
  EXPECT_EQ(c.name, "reinhard");
  EXPECT_EQ(c.flags, (std::vector<std::string>{"--bracket", "taa_reinhard"}));
  EXPECT_THROW(parseAdHocConfiguration("--blend 1"), Error);
  EXPECT_THROW(parseAdHocConfiguration("bad name=--blend 1"), Error);
}

// The baseline every figure is compared against must never drift.
TEST(YardstickConfigurations, ClassicIsTheFixedBaseline) {
  const auto configs = readConfigurations(TAA_YARDSTICK_CONFIGURATIONS);
  ASSERT_GE(configs.size(), 2u);
  EXPECT_EQ(configs[0].name, "classic");
  EXPECT_EQ(configs[0].flagsText,
            "--history-filter bilinear --reconstruction blackman-harris --rectify clamp "
            "--box-space rgb --neighbourhood 9 --motion-dilation centre --camera-motion vectors "
            "--depth-tolerance 0 --blend 0.1 --sample-count off --velocity-blend 0 "
            "--anti-flicker 0 --luma-weighting off --thin-hold 0 --cut-detection 0 --sharpen 0 "
            "--bracket none --mode history");
  EXPECT_EQ(configs[1].name, "default");
  EXPECT_TRUE(configs[1].flags.empty());
}

}  // namespace
}  // namespace taa::yardstick
