// End-to-end: TAA_GL_PROFILE (docs/PERFORMANCE.md, "Profiling the GL passes"). With it, taatool
// ends a run with a line per GL pass (its draws, total and mean milliseconds); the resolve is
// the same bit for bit; without it, nothing is printed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class GlProfileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    test::writeSeparateFrames(dir_ / "in", 1, 4);
  }
  void TearDown() override { unsetenv("TAA_GL_PROFILE"); }
  test::ToolRun run(const std::string& out, std::vector<std::string> extra) const {
    std::vector<std::string> a = test::separateFileArgs(dir_ / "in", dir_ / out / "r.####.exr");
    a.push_back("-q");
    a.insert(a.end(), extra.begin(), extra.end());
    return test::runTaatool(a, dir_);
  }
  // The draws the profile gives `pass`; -1 when it has no line for it.
  static int drawsOf(const std::string& err, const std::string& pass) {
    std::smatch match;
    const std::regex line("(^|\n)" + std::regex_replace(pass, std::regex("[()]"), "\\$&") +
                          " +([0-9]+) draws +[0-9.]+ ms +[0-9.]+ ms each +[0-9.]+ %");
    return std::regex_search(err, match, line) ? std::stoi(match[2]) : -1;
  }
  fs::path dir_;
};

TEST_F(GlProfileTest, EachWindowPassIsCountedAndTheResolveIsUnchanged) {
  const test::ToolRun plain = run("plain", {});
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(plain.err, "");

  setenv("TAA_GL_PROFILE", "1", 1);
  const test::ToolRun profiled = run("profiled", {});
  ASSERT_EQ(profiled.exitCode, 0) << profiled.err;
  EXPECT_NE(profiled.err.find("taatool: GL passes (TAA_GL_PROFILE):"), std::string::npos)
      << profiled.err;
  // Four frames: each prepared once and gathered once, with its surroundings' two passes.
  EXPECT_EQ(drawsOf(profiled.err, "window prepare pass"), 4) << profiled.err;
  EXPECT_EQ(drawsOf(profiled.err, "window gather pass"), 4) << profiled.err;
  EXPECT_EQ(drawsOf(profiled.err, "window surroundings pass (rows)"), 4) << profiled.err;
  EXPECT_EQ(drawsOf(profiled.err, "window surroundings pass (columns)"), 4) << profiled.err;
  EXPECT_GE(drawsOf(profiled.err, "window classify pass"), 4) << profiled.err;
  EXPECT_EQ(drawsOf(profiled.err, "resolve pass"), -1) << profiled.err;  // the history's
  EXPECT_TRUE(std::regex_search(profiled.err, std::regex("\nall passes +[0-9.]+ ms\n$")))
      << profiled.err;

  for (int frame = 1; frame <= 4; ++frame) {
    const test::Exr a = test::readExr(dir_ / "plain" / test::frameName("r", frame));
    const test::Exr b = test::readExr(dir_ / "profiled" / test::frameName("r", frame));
    ASSERT_FALSE(a.pixels.empty());
    EXPECT_EQ(a.pixels, b.pixels) << "frame " << frame;
  }
}

TEST_F(GlProfileTest, TheHistoryModeCountsItsPassesAndZeroTurnsItOff) {
  setenv("TAA_GL_PROFILE", "1", 1);
  const test::ToolRun history = run("history", {"--mode", "history"});
  ASSERT_EQ(history.exitCode, 0) << history.err;
  EXPECT_EQ(drawsOf(history.err, "resolve pass"), 4) << history.err;
  EXPECT_EQ(drawsOf(history.err, "window gather pass"), -1) << history.err;

  setenv("TAA_GL_PROFILE", "0", 1);
  const test::ToolRun off = run("off", {"--mode", "history"});
  ASSERT_EQ(off.exitCode, 0) << off.err;
  EXPECT_EQ(off.err, "");
}

}  // namespace
}  // namespace taa
