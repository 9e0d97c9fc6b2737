// End-to-end: faults of the machine around taatool (issue 17): a full disk, an output folder it
// may not write, several runs over one output at once. Each gives a clear error naming file and
// frame, or correct output, and never leaves a partial file or a temporary beside the output.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <future>
#include <vector>

#include "io/output_completeness.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class FaultsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    in_ = dir_ / "in";
    test::writeSeparateFrames(in_, 1, 4);
  }

  std::vector<std::string> args(const fs::path& out) const {
    std::vector<std::string> a = test::separateFileArgs(in_, out / "r.####.exr");
    a.insert(a.end(), {"-d", "float"});
    return a;
  }

  // Names in `folder`, and a failure for each that is not a complete output frame.
  static std::vector<std::string> expectCompleteFramesOnly(const fs::path& folder) {
    std::vector<std::string> names;
    if (!fs::exists(folder)) return names;
    for (const auto& entry : fs::directory_iterator(folder)) {
      names.push_back(entry.path().filename().string());
      const io::OutputCheck check = io::checkOutputComplete(entry.path().string());
      EXPECT_TRUE(check.complete) << names.back() << ": " << check.reason;
    }
    return names;
  }

  fs::path dir_, in_;
};

// The write of a frame fails as on a full disk (a file size limit: EFBIG instead of ENOSPC,
// the same failed write for OpenEXR).
TEST_F(FaultsTest, AFullDiskFailsTheFrameNamingItAndLeavesNothing) {
  std::vector<std::string> shell = {"-c", "trap \"\" XFSZ; ulimit -f 4; exec \"$0\" \"$@\"",
                                    test::taatoolPath()};
  for (const auto& a : args(dir_ / "out")) shell.push_back(a);
  const test::ToolRun r = test::runProgram("/bin/bash", shell, dir_);
  test::expectToolError(r, {"cannot write pixels", (dir_ / "out" / "r.0001.exr").string(),
                            "frame 1"});
  EXPECT_TRUE(expectCompleteFramesOnly(dir_ / "out").empty());
}

TEST_F(FaultsTest, AnOutputFolderThatCannotBeWrittenIsAClearError) {
  const fs::path out = dir_ / "locked";
  fs::create_directories(out);
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec | fs::perms::others_read |
                           fs::perms::others_exec);
  test::ToolRun r;
  if (::geteuid() == 0) {  // root writes anywhere: run as nobody (util-linux setpriv)
    fs::permissions(dir_, fs::perms::all);
    std::vector<std::string> setpriv = {"--reuid=65534", "--regid=65534", "--clear-groups",
                                        test::taatoolPath()};
    for (const auto& a : args(out)) setpriv.push_back(a);
    r = test::runProgram("/usr/bin/setpriv", setpriv, dir_);
  } else {
    r = test::runTaatool(args(out), dir_);
  }
  test::expectToolError(r, {"Permission denied", (out / "r.0001.exr").string(), "frame 1"});
  EXPECT_TRUE(expectCompleteFramesOnly(out).empty());
}

// Four runs over one output at once (a farm that queued a chunk twice): each writes its own
// temporaries, which no other run removes while it lives, and renames whole frames over each
// other. Every run succeeds; every frame left is complete.
TEST_F(FaultsTest, FourConcurrentRunsOverOneOutputLeaveCompleteFramesOnly) {
  std::vector<std::future<test::ToolRun>> runs;
  for (int i = 0; i < 4; ++i) {
    const fs::path scratch = dir_ / ("run" + std::to_string(i));
    fs::create_directories(scratch);
    runs.push_back(std::async(std::launch::async, [this, scratch] {
      return test::runTaatool(args(dir_ / "out"), scratch);
    }));
  }
  for (auto& run : runs) {
    const test::ToolRun r = run.get();
    EXPECT_EQ(r.exitCode, 0) << r.err;
  }
  std::vector<std::string> names = expectCompleteFramesOnly(dir_ / "out");
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"r.0001.exr", "r.0002.exr", "r.0003.exr",
                                             "r.0004.exr"}));
}

}  // namespace
}  // namespace taa
