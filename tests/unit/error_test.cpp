#include <gtest/gtest.h>

#include "taa/error.h"

namespace taa {
namespace {

TEST(Error, MessageNamesFileFrameAndChannel) {
  const Error e("missing channel", {"/shots/a.0004.exr", 4, "ViewLayer.Depth.Z"});
  EXPECT_STREQ(e.what(), "missing channel : /shots/a.0004.exr (frame 4, channel ViewLayer.Depth.Z)");
  EXPECT_EQ(e.description(), "missing channel");
  EXPECT_EQ(e.context().frame, 4);
}

TEST(Error, LeavesOutEmptyParts) {
  EXPECT_STREQ(Error("bad").what(), "bad");
  EXPECT_STREQ(Error("bad", {"f.exr"}).what(), "bad : f.exr");
  EXPECT_STREQ(Error("bad", {"", 7}).what(), "bad : frame 7");
  EXPECT_STREQ(Error("bad", {"f.exr", std::nullopt, "Z"}).what(), "bad : f.exr (channel Z)");
}

}  // namespace
}  // namespace taa
