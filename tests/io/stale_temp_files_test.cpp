// Temporaries of dead runs beside an output (issue 17, defect 8): the names the writers give
// them, and which a later run removes.
#include "io/stale_temp_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/exr_writer.h"
#include "test_files.h"

namespace taa::io {
namespace {

namespace fs = std::filesystem;

using taa::test::listFolder;
using taa::test::scratchFolder;

// A process id that just ended: a child that exits at once, reaped.
pid_t deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

void touch(const fs::path& path) { std::ofstream(path) << "partial"; }

TEST(StaleTemporaries, NamesCarryHostAndProcess) {
  const std::string host = temporaryHostTag();
  EXPECT_FALSE(host.empty());
  EXPECT_EQ(host.find('-'), std::string::npos);  // '-' separates the name's fields
  EXPECT_EQ(temporaryFileName("r.0001.exr", "0f3a"),
            ".r.0001.exr.taa-tmp-" + host + "-" + std::to_string(::getpid()) + "-0f3a.exr");
  EXPECT_EQ(farmScratchPrefix(), ".taa-farm-" + host + "-" + std::to_string(::getpid()) + "-");
  // A long name is cut so that the whole fits a file system's 255 bytes.
  EXPECT_LE(temporaryFileName(std::string(250, 'x'), std::string(16, 'f')).size(), 255u);
}

// The run that dies is simulated by names with a dead pid; the writer's own names are tested in
// WriteExrAtomic and the real kill in tests/e2e/interruption_test.cpp.
TEST(StaleTemporaries, OnlyThoseOfDeadWritersOnThisHostAndOfThePatternAreRemoved) {
  const fs::path folder = scratchFolder();
  const std::string host = temporaryHostTag();
  const std::string dead = std::to_string(deadPid());
  const std::string live = std::to_string(::getpid());
  const std::vector<std::string> stale = {
      ".r.0002.exr.taa-tmp-" + host + "-" + dead + "-0.exr",
      ".r.0008.exr.taa-tmp-" + host + "-" + dead + "-9c0ffee5d00dfeed.exr",  // random part
      ".r.0003.exr.taa-tmp-" + dead + "-4.exr",  // named before temporaries carried the host
      ".taa-farm-" + host + "-" + dead + "-k2j3h4",
  };
  const std::vector<std::string> kept = {
      ".r.0004.exr.taa-tmp-" + host + "-" + live + "-0.exr",       // this process: running
      ".r.0005.exr.taa-tmp-otherhost-" + dead + "-0.exr",           // cannot be checked here
      ".other.0001.exr.taa-tmp-" + host + "-" + dead + "-0.exr",   // another output's
      ".r.0006.exr.taa-tmp-" + host + "-" + dead + "-x.exr",       // not a temporary's name
      ".r.0009.exr.taa-tmp-" + host + "-" + dead + "-" + std::string(17, 'a') + ".exr",
      ".taa-farm-" + host + "-" + live + "-abcd",
      ".taa-farm-k2j3h4",                                            // no writer named
      "r.0001.exr",
  };
  for (const auto& name : stale) touch(folder / name);
  for (const auto& name : kept) touch(folder / name);
  fs::remove(folder / stale[3]);
  fs::create_directories(folder / stale[3]);
  touch(folder / stale[3] / "r.0007.exr");
  fs::remove(folder / kept[5]);
  fs::create_directories(folder / kept[5]);

  const StaleTemporaries result = removeStaleTemporaries((folder / "r.####.exr").string());
  EXPECT_TRUE(result.failed.empty());
  std::vector<std::string> removed;
  for (const auto& path : result.removed) removed.push_back(fs::path(path).filename().string());
  std::sort(removed.begin(), removed.end());
  std::vector<std::string> expected = stale;
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(removed, expected);
  std::vector<std::string> left = kept;
  std::sort(left.begin(), left.end());
  EXPECT_EQ(listFolder(folder.string()), left);
}

TEST(StaleTemporaries, ASingleFileOutputAndMissingFoldersAreHandled) {
  const fs::path folder = scratchFolder();
  const std::string dead = std::to_string(deadPid());
  touch(folder / (".still.exr.taa-tmp-" + temporaryHostTag() + "-" + dead + "-0.exr"));
  EXPECT_EQ(removeStaleTemporaries((folder / "still.exr").string()).removed.size(), 1u);
  EXPECT_TRUE(listFolder(folder.string()).empty());
  EXPECT_TRUE(removeStaleTemporaries((folder / "none" / "r.####.exr").string()).removed.empty());
  EXPECT_TRUE(removeStaleTemporaries("").removed.empty());
}

}  // namespace
}  // namespace taa::io
