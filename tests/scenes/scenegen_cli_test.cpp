// taa-scenegen: arguments, errors and the files it writes.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace taa::scenes::test {
namespace {

struct ToolRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

ToolRun runScenegen(const std::string& arguments) {
  ToolRun run;
  const std::string command = std::string(TAA_SCENEGEN_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) run.output += buffer;
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

TEST(ScenegenCli, ListsScenes) {
  const ToolRun run = runScenegen("--list");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  for (const char* name : {"static", "translate", "moving_object"}) {
    EXPECT_NE(run.output.find(name), std::string::npos) << name;
  }
}

TEST(ScenegenCli, BadArgumentsFailWithMessage) {
  const std::string out = freshTempDir("cli_bad");
  const std::vector<std::string> badArguments = {"--scene nope --out " + out,
                                                 "--scene static",
                                                 "--out " + out,
                                                 "--scene static --out " + out + " --frames 5-2",
                                                 "--scene static --out " + out + " --frames x",
                                                 "--scene static --out " + out + " --size 0x10",
                                                 "--scene static --out " + out + " --size 320",
                                                 "--scene static --out " + out + " --layout nuke",
                                                 "--bogus"};
  for (const std::string& arguments : badArguments) {
    const ToolRun run = runScenegen(arguments);
    EXPECT_EQ(run.exitCode, 1) << arguments;
    EXPECT_EQ(run.output.rfind("taa-scenegen ERROR: ", 0), 0u) << arguments << ": " << run.output;
  }
}

TEST(ScenegenCli, WritesRequestedFramesInBothLayouts) {
  const std::string separate = freshTempDir("cli_separate");
  ToolRun run = runScenegen("--scene translate --frames 9-10 --size 24x16 --out " + separate);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* stem : {"beauty", "depth", "motion", "truth"}) {
    EXPECT_TRUE(std::filesystem::exists(separate + "/" + stem + ".0009.exr")) << stem;
    EXPECT_TRUE(std::filesystem::exists(separate + "/" + stem + ".0010.exr")) << stem;
    EXPECT_FALSE(std::filesystem::exists(separate + "/" + stem + ".0011.exr")) << stem;
  }
  EXPECT_EQ(readExr(separate + "/beauty.0009.exr").width, 24);

  const std::string cycles = freshTempDir("cli_cycles");
  run = runScenegen("--scene static --frames 3 --size 24x16 --layout cycles --out " + cycles);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(cycles + "/render.0003.exr"));
  EXPECT_TRUE(std::filesystem::exists(cycles + "/truth.0003.exr"));
  EXPECT_FALSE(std::filesystem::exists(cycles + "/beauty.0003.exr"));
}

}  // namespace
}  // namespace taa::scenes::test
