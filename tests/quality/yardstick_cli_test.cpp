// taa-yardstick end to end on one tiny scene: generates it (then reuses it), runs the real
// taatool per configuration, and writes the table and page with the expected rows.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "yardstick_runner.h"

namespace {

using namespace taa::yardstick::test;

TEST(YardstickCli, TinySceneEndToEnd) {
  const std::string work = std::string(TAA_TEST_TMPDIR) + "/tiny";
  std::filesystem::remove_all(work);
  const std::string arguments =
      "--scenes moving_object_3d --size 48x27 --frames 1-8 --warmup 2 --truth-samples 4 "
      "--configs classic --config 'noaccumulation=--blend 1' --work " + work +
      " --doc " + work + "/QUALITY.md --command 'yardstick under test'";
  const ToolRun first = runYardstick(arguments);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  EXPECT_TRUE(contains(first.output, "moving_object_3d: generated")) << first.output;
  for (const char* row : {"| moving_object_3d | raw |", "| moving_object_3d | classic |",
                          "| moving_object_3d | noaccumulation |", "| **mean** | raw |",
                          "| **mean** | classic |", "| **mean** | noaccumulation |"}) {
    EXPECT_TRUE(contains(first.output, row)) << row << "\n" << first.output;
  }
  for (int f = 1; f <= 8; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "/runs/moving_object_3d/classic/resolved.%04d.exr", f);
    EXPECT_TRUE(std::filesystem::exists(work + name)) << name;
  }
  const std::string page = readFile(work + "/QUALITY.md");
  EXPECT_TRUE(contains(page, "`yardstick under test`")) << page;
  EXPECT_TRUE(contains(page, "| moving_object_3d | classic |")) << page;
  EXPECT_TRUE(contains(page, "`--blend 1`")) << page;
  EXPECT_TRUE(contains(page, "frames 1-8")) << page;
  EXPECT_TRUE(contains(page, "| PSNR (dB) | SSIM | temporal error | flicker | ghosting |")) << page;
  // The contact sheet sits beside the page and is linked from it.
  EXPECT_TRUE(std::filesystem::exists(work + "/quality/moving_object_3d.png"));
  EXPECT_TRUE(contains(page, "](quality/moving_object_3d.png)")) << page;

  // The raw input is its own ghosting reference.
  const auto rawRow = first.output.find("| moving_object_3d | raw |");
  ASSERT_NE(rawRow, std::string::npos);
  const std::string rawLine = first.output.substr(rawRow, first.output.find('\n', rawRow) - rawRow);
  EXPECT_TRUE(contains(rawLine, "| 1.000 |")) << rawLine;

  // A second run reuses the generated scene.
  const ToolRun second = runYardstick(arguments);
  ASSERT_EQ(second.exitCode, 0) << second.output;
  EXPECT_TRUE(contains(second.output, "moving_object_3d: cached")) << second.output;
}

TEST(YardstickCli, UnknownConfigurationFails) {
  const ToolRun run = runYardstick("--configs nosuchthing --work " + std::string(TAA_TEST_TMPDIR) +
                                   "/unknown");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_TRUE(contains(run.output, "taa-yardstick ERROR: no configuration named nosuchthing"))
      << run.output;
}

}  // namespace
