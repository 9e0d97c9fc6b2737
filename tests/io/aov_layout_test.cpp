#include "io/aov_layout.h"

#include <gtest/gtest.h>

#include "taa/error.h"

namespace taa::io {
namespace {

using Names = std::vector<std::string>;

TEST(CyclesLayout, AllAovsComeFromTheColorFile) {
  const AovLayout layout = cyclesLayout("render.####.exr");
  EXPECT_EQ(layout.color.pattern, "render.####.exr");
  EXPECT_EQ(layout.color.channels, Names({"ViewLayer.Combined.R", "ViewLayer.Combined.G",
                                          "ViewLayer.Combined.B", "ViewLayer.Combined.A"}));
  ASSERT_TRUE(layout.depth.has_value());
  EXPECT_EQ(layout.depth->pattern, "");
  EXPECT_EQ(layout.depth->channels, Names({"ViewLayer.Depth.Z"}));
  ASSERT_TRUE(layout.motion.has_value());
  EXPECT_EQ(layout.motion->pattern, "");
  EXPECT_EQ(layout.motion->channels, Names({"ViewLayer.Vector.X", "ViewLayer.Vector.Y"}));
}

TEST(CyclesLayout, ConventionsMatchCycles) {
  const AovLayout layout = cyclesLayout("render.####.exr");
  EXPECT_TRUE(layout.motionConvention.yUp);
  EXPECT_TRUE(layout.motionConvention.toPrevious);
  EXPECT_EQ(layout.motionConvention.scale, 1.0f);
  // Cycles writes 1e10 for "no hit"; real distances stay far below the threshold.
  EXPECT_LE(layout.depthConvention.noHitAbove, 1e10f);
  EXPECT_GT(layout.depthConvention.noHitAbove, 1e6f);
}

TEST(CyclesLayout, OtherRenderLayer) {
  const AovLayout layout = cyclesLayout("r.exr", "Hero");
  EXPECT_EQ(layout.color.channels.front(), "Hero.Combined.R");
  EXPECT_EQ(layout.depth->channels.front(), "Hero.Depth.Z");
  EXPECT_EQ(layout.motion->channels.back(), "Hero.Vector.Y");
}

TEST(ParseChannelList, SplitsOnCommasAndTrims) {
  EXPECT_EQ(parseChannelList("R,G,B,A"), Names({"R", "G", "B", "A"}));
  EXPECT_EQ(parseChannelList(" depth.Z "), Names({"depth.Z"}));
  EXPECT_EQ(parseChannelList("forward.u, forward.v"), Names({"forward.u", "forward.v"}));
}

TEST(ParseChannelList, EmptyItemsAreErrors) {
  for (const std::string text : {"", "R,,G", "R,", ",R", " , "}) {
    try {
      parseChannelList(text);
      ADD_FAILURE() << "no error for \"" << text << "\"";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("\"" + text + "\""), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace taa::io
