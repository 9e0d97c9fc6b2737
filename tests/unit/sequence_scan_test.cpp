#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/sequence_scan.h"

namespace taa::io {
namespace {

namespace fs = std::filesystem;

class SequenceScan : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: CTest runs the tests of this file in parallel processes.
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(TAA_TEST_TMPDIR) / test->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void touch(const std::string& name) { std::ofstream(dir_ / name) << "x"; }
  std::string pattern(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(SequenceScan, FindsPaddedFramesOnly) {
  for (const char* name : {"a.0001.exr", "a.0002.exr", "a.0010.exr", "a.5.exr", "a.0003.tif",
                           "b.0004.exr", "a.00011.exr", "a.-0002.exr"}) {
    touch(name);
  }
  EXPECT_EQ(scanExistingFrames(pattern("a.####.exr")), (std::vector<int>{-2, 1, 2, 10}));
  EXPECT_EQ(scanExistingFrames(pattern("a.#.exr")), (std::vector<int>{-2, 1, 2, 10}));
  EXPECT_EQ(scanExistingFrames(pattern("a.%04d.exr")), (std::vector<int>{-2, 1, 2, 10}));
  EXPECT_EQ(scanExistingFrames(pattern("a.@.exr")), (std::vector<int>{5}));
  EXPECT_EQ(scanExistingFrames(pattern("a.%05d.exr")), (std::vector<int>{11}));
}

TEST_F(SequenceScan, NothingForMissingFolderOrNoPlaceholder) {
  EXPECT_TRUE(scanExistingFrames(pattern("nowhere/a.####.exr")).empty());
  touch("still.exr");
  EXPECT_TRUE(scanExistingFrames(pattern("still.exr")).empty());
}

}  // namespace
}  // namespace taa::io
