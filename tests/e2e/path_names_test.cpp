// End-to-end: folders and files named with whatever a file system allows (spaces, quotes,
// $(...), backticks, line breaks, bytes that are not UTF-8) through taatool and taa-farm run:
// the frames are read and written under exactly those names, nothing is run by a shell, and
// taa-farm's PROGRESS lines stay one line each (issue 25).
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <sstream>

#include "io/sequence_pattern.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

// A name part of random bytes from the troublesome ones and any others, never '/', NUL or the
// frame placeholders' characters ('#', '@', '%': a pattern's syntax).
std::string randomName(std::mt19937& random) {
  static const std::string nasty = " '\"\\$`;&|<>(){}*?~!\t\n\r\xff\xc3-";
  std::string name = "n";
  const int length = 1 + int(random() % 12);
  for (int i = 0; i < length; ++i) {
    char c = random() % 2 ? nasty[random() % nasty.size()] : char(1 + random() % 255);
    if (c == '/' || c == '#' || c == '@' || c == '%') c = '_';
    name += c;
  }
  return name;
}

class PathNamesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    test::writeSeparateFrames(dir_ / "source", 1, 3, 32, 20);
  }
  // The three frames copied to `folder`, each AOV's files named `stem`-AOV.####.exr.
  void copyFrames(const fs::path& folder, const std::string& stem) {
    fs::create_directories(folder);
    for (const char* aov : {"beauty", "depth", "motion"}) {
      for (int frame = 1; frame <= 3; ++frame) {
        fs::copy_file(dir_ / "source" / io::expandFramePattern(std::string(aov) + ".####.exr", frame),
                      folder / io::expandFramePattern(stem + aov + ".####.exr", frame));
      }
    }
  }
  std::vector<std::string> args(const fs::path& in, const std::string& stem, const fs::path& out) {
    return {(in / (stem + "beauty.####.exr")).string(), "--depth",
            (in / (stem + "depth.####.exr")).string(), "--motion",
            (in / (stem + "motion.####.exr")).string(), "-o", out.string(), "-q"};
  }
  fs::path dir_;
};

TEST_F(PathNamesTest, AnyNameIsReadAndWrittenAsItIs) {
  std::mt19937 random(25);
  for (int round = 0; round < 4; ++round) {
    const std::string folderName = randomName(random), stem = randomName(random);
    const fs::path in = dir_ / folderName;
    copyFrames(in, stem);
    const fs::path out = dir_ / ("out" + randomName(random)) / (randomName(random) + ".####.exr");
    const test::ToolRun run = test::runTaatool(args(in, stem, out), dir_);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (int frame = 1; frame <= 3; ++frame) {
      EXPECT_TRUE(fs::is_regular_file(io::expandFramePattern(out.string(), frame)))
          << "round " << round << ", frame " << frame;
    }
  }
  // Nothing ran a shell: no file appeared beside the folders the runs used.
  for (const auto& entry : fs::directory_iterator(dir_)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "source" || name[0] == 'n' || name.rfind("out", 0) == 0 ||
                name.rfind(".", 0) == 0 || name.find("std") != std::string::npos)
        << "unexpected " << name;
  }
}

// A line break in the output's path: each PROGRESS line is still one line, the path escaped.
TEST_F(PathNamesTest, FarmProgressLinesStayOneLineEach) {
  copyFrames(dir_ / "in", "");
  const fs::path out = dir_ / "a\nPROGRESS: 100% forged" / "r.####.exr";
  std::vector<std::string> farm = {"run", "--chunk", "1-3"};
  const std::vector<std::string> rest = args(dir_ / "in", "", out);
  farm.insert(farm.end(), rest.begin(), rest.end());
  const test::ToolRun run = test::runProgram(TAA_FARM_PATH, farm, dir_);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::istringstream lines(run.out);
  int progress = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("PROGRESS:", 0) != 0) continue;
    ++progress;
    EXPECT_NE(line.find("written: "), std::string::npos) << line;
    EXPECT_NE(line.find("a\\nPROGRESS: 100% forged/r.000"), std::string::npos) << line;
  }
  EXPECT_EQ(progress, 3) << run.out;
  EXPECT_TRUE(fs::is_regular_file(io::expandFramePattern(out.string(), 3)));
}

}  // namespace
}  // namespace taa
