// End-to-end: frame numbers anywhere in the int range, both ends included (issue 25, defect 2:
// a sequence ending at frame 2147483647 made the window mode grow without bound). taatool runs
// under `timeout`, so a run that never ends fails the test instead of the suite.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <random>

#include "io/sequence_pattern.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

// Three frames of the moving-object scene, renumbered to start at `first`.
void writeFramesNumbered(const fs::path& source, const fs::path& folder, int first) {
  fs::create_directories(folder);
  for (const char* aov : {"beauty", "depth", "motion"}) {
    for (int i = 0; i < 3; ++i) {
      const std::string pattern = std::string(aov) + ".####.exr";
      fs::copy_file(source / io::expandFramePattern(pattern, 1 + i),
                    folder / io::expandFramePattern(pattern, int((long long)first + i)),
                    fs::copy_options::overwrite_existing);
    }
  }
}

test::ToolRun resolveWithin(const fs::path& in, const fs::path& out,
                            const std::vector<std::string>& extra, const fs::path& scratch) {
  std::vector<std::string> args = {"120", test::taatoolPath()};
  const std::vector<std::string> files = test::separateFileArgs(in, out / "r.####.exr");
  args.insert(args.end(), files.begin(), files.end());
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back("-q");
  return test::runProgram("timeout", args, scratch);
}

class FrameNumbersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    test::writeSeparateFrames(dir_ / "source", 1, 3, 32, 20);
  }
  // Resolves the three frames numbered from `first` in both modes; every frame is written.
  void expectResolved(int first) {
    const fs::path in = dir_ / ("in" + std::to_string(first));
    writeFramesNumbered(dir_ / "source", in, first);
    for (const char* mode : {"window", "history"}) {
      const fs::path out = dir_ / ("out" + std::to_string(first) + mode);
      const test::ToolRun run = resolveWithin(in, out, {"--mode", mode}, dir_);
      ASSERT_EQ(run.exitCode, 0) << "frames from " << first << ", " << mode << ": " << run.err;
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(fs::exists(out / io::expandFramePattern("r.####.exr", first + i)))
            << "frame " << first + i << ", " << mode;
      }
    }
  }
  fs::path dir_;
};

TEST_F(FrameNumbersTest, ASequenceEndingAtIntMaxResolves) { expectResolved(INT_MAX - 2); }

TEST_F(FrameNumbersTest, ASequenceStartingAtIntMinResolves) { expectResolved(INT_MIN); }

TEST_F(FrameNumbersTest, RandomFrameNumbersAnywhereInTheRangeResolve) {
  std::mt19937 random(2147483647u);
  for (int round = 0; round < 3; ++round) {
    const long long start = (long long)INT_MIN + (long long)(random() % 4294967293u);  // to INT_MAX - 2
    expectResolved(int(start));
  }
}

// The same frames through a single-file pattern ("%d", as the probe ran it).
TEST_F(FrameNumbersTest, PrintfPatternUpToIntMax) {
  const fs::path in = dir_ / "printf";
  fs::create_directories(in);
  for (const char* aov : {"beauty", "depth", "motion"}) {
    for (int i = 0; i < 2; ++i) {
      fs::copy_file(dir_ / "source" / io::expandFramePattern(std::string(aov) + ".####.exr", 1 + i),
                    in / (std::string(aov) + "." + std::to_string(INT_MAX - 1 + i) + ".exr"));
    }
  }
  const test::ToolRun run = test::runProgram(
      "timeout",
      {"120", test::taatoolPath(), (in / "beauty.%d.exr").string(), "--depth",
       (in / "depth.%d.exr").string(), "--motion", (in / "motion.%d.exr").string(), "-o",
       (dir_ / "printf-out" / "r.%d.exr").string(), "-q"},
      dir_);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir_ / "printf-out" / ("r." + std::to_string(INT_MAX) + ".exr")));
}

}  // namespace
}  // namespace taa
