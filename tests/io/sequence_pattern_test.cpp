#include "io/sequence_pattern.h"

#include <gtest/gtest.h>

#include "taa/error.h"

namespace taa::io {
namespace {

using Frames = std::vector<int>;

TEST(ExpandFramePattern, SingleHashPadsToFourDigits) {
  EXPECT_EQ(expandFramePattern("beauty.#.exr", 7), "beauty.0007.exr");
  EXPECT_EQ(expandFramePattern("beauty.#.exr", 12345), "beauty.12345.exr");
}

TEST(ExpandFramePattern, HashRunPadsToItsLength) {
  EXPECT_EQ(expandFramePattern("beauty.####.exr", 42), "beauty.0042.exr");
  EXPECT_EQ(expandFramePattern("beauty.##.exr", 3), "beauty.03.exr");
  EXPECT_EQ(expandFramePattern("beauty.######.exr", 42), "beauty.000042.exr");
  EXPECT_EQ(expandFramePattern("beauty.##.exr", 1234), "beauty.1234.exr");
}

TEST(ExpandFramePattern, AtRunPadsOneDigitPerSign) {
  EXPECT_EQ(expandFramePattern("beauty.@.exr", 7), "beauty.7.exr");
  EXPECT_EQ(expandFramePattern("beauty.@@@.exr", 7), "beauty.007.exr");
  EXPECT_EQ(expandFramePattern("beauty.@@@@@.exr", 1001), "beauty.01001.exr");
}

TEST(ExpandFramePattern, PrintfStyle) {
  EXPECT_EQ(expandFramePattern("beauty.%04d.exr", 7), "beauty.0007.exr");
  EXPECT_EQ(expandFramePattern("beauty.%06d.exr", 1001), "beauty.001001.exr");
  EXPECT_EQ(expandFramePattern("beauty.%d.exr", 7), "beauty.7.exr");
  EXPECT_EQ(expandFramePattern("beauty.%d.exr", 1001), "beauty.1001.exr");
}

TEST(ExpandFramePattern, NegativeFramesKeepTheSignBeforeThePadding) {
  EXPECT_EQ(expandFramePattern("b.#.exr", -5), "b.-0005.exr");
  EXPECT_EQ(expandFramePattern("b.###.exr", -12), "b.-012.exr");
  EXPECT_EQ(expandFramePattern("b.@@.exr", -123), "b.-123.exr");
  EXPECT_EQ(expandFramePattern("b.%04d.exr", -5), "b.-0005.exr");
  EXPECT_EQ(expandFramePattern("b.%d.exr", -5), "b.-5.exr");
  EXPECT_EQ(expandFramePattern("b.####.exr", 0), "b.0000.exr");
}

TEST(ExpandFramePattern, WithoutPlaceholderIsUnchanged) {
  EXPECT_EQ(expandFramePattern("/shots/still.exr", 12), "/shots/still.exr");
  // A '%' that is not a %d or %0Nd placeholder stays literal.
  EXPECT_EQ(expandFramePattern("grade_100%.exr", 12), "grade_100%.exr");
  EXPECT_EQ(expandFramePattern("a%5s.exr", 12), "a%5s.exr");
}

TEST(ExpandFramePattern, ReplacesEveryPlaceholder) {
  EXPECT_EQ(expandFramePattern("f####/beauty.%04d.exr", 9), "f0009/beauty.0009.exr");
}

TEST(HasFramePlaceholder, RecognisesEveryKind) {
  EXPECT_TRUE(hasFramePlaceholder("a.#.exr"));
  EXPECT_TRUE(hasFramePlaceholder("a.####.exr"));
  EXPECT_TRUE(hasFramePlaceholder("a.@@.exr"));
  EXPECT_TRUE(hasFramePlaceholder("a.%04d.exr"));
  EXPECT_TRUE(hasFramePlaceholder("a.%d.exr"));
  EXPECT_FALSE(hasFramePlaceholder("a.0001.exr"));
  EXPECT_FALSE(hasFramePlaceholder("100%.exr"));
  EXPECT_FALSE(hasFramePlaceholder(""));
}

TEST(ParseFrameRange, SingleFrameAndInclusiveRange) {
  EXPECT_EQ(parseFrameRange("5"), Frames({5}));
  EXPECT_EQ(parseFrameRange("1-4"), Frames({1, 2, 3, 4}));
  EXPECT_EQ(parseFrameRange("1001-1003"), Frames({1001, 1002, 1003}));
}

TEST(ParseFrameRange, Step) {
  EXPECT_EQ(parseFrameRange("1-10x3"), Frames({1, 4, 7, 10}));
  EXPECT_EQ(parseFrameRange("1-48x2").size(), 24u);
  EXPECT_EQ(parseFrameRange("1-48x2").back(), 47);
}

TEST(ParseFrameRange, ListKeepsOrderAndDropsDuplicates) {
  EXPECT_EQ(parseFrameRange("1-3,10,20-22"), Frames({1, 2, 3, 10, 20, 21, 22}));
  EXPECT_EQ(parseFrameRange("10,1-3"), Frames({10, 1, 2, 3}));
  EXPECT_EQ(parseFrameRange("1-3,2-4"), Frames({1, 2, 3, 4}));
  EXPECT_EQ(parseFrameRange(" 1-2 , 5 "), Frames({1, 2, 5}));
  EXPECT_EQ(parseFrameRange("5,3,5,1-3,9"), Frames({5, 3, 1, 2, 9}));
}

TEST(ParseFrameRange, AListOfMoreThanAMillionFramesIsRefused) {
  // Each item is under the cap; together they pass it.
  try {
    parseFrameRange("1-600000,1-600000");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(e.description().find("more than a million frames"), std::string::npos)
        << e.description();
  }
  EXPECT_EQ(parseFrameRange("1-1000000").size(), 1000000u);  // the cap itself is allowed
}

TEST(ParseFrameRange, ARangeOfMoreThanAMillionFramesIsRefused) {
  // The fuzzer's input that took over 20 s under ASan with a cap of 10 million.
  try {
    parseFrameRange("1-9174846,213,-10,6-222");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(e.description().find("\"1-9174846\" holds more than a million frames"),
              std::string::npos)
        << e.description();
  }
}

TEST(ParseFrameRange, NegativeFrames) {
  EXPECT_EQ(parseFrameRange("-5--1"), Frames({-5, -4, -3, -2, -1}));
  EXPECT_EQ(parseFrameRange("-2-1"), Frames({-2, -1, 0, 1}));
  EXPECT_EQ(parseFrameRange("-3"), Frames({-3}));
  EXPECT_EQ(parseFrameRange("-6--2x2"), Frames({-6, -4, -2}));
}

TEST(ParseFrameRange, DescendingRangeRunsBackwards) {
  EXPECT_EQ(parseFrameRange("5-1x2"), Frames({5, 3, 1}));
}

TEST(ParseFrameRange, MalformedTextIsAnErrorNamingTheText) {
  for (const std::string text : {"", " ", "abc", "1-", "1-x", "1-5x0", "1-5x", "1-5x-2", "1,,2",
                                 "1,", "5x2", "1-5y2", "1-5x2x3", "1..5", "99999999999",
                                 "1-99999999999", "0-2000000000"}) {
    try {
      parseFrameRange(text);
      ADD_FAILURE() << "no error for \"" << text << "\"";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("\"" + text + "\""), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace taa::io
