// End-to-end: taatool stopped by SIGTERM, SIGINT or SIGKILL in the middle of a sequence (issue 17,
// defect 8). The frames written are complete, nothing partial stays beside the output, and the
// next run over the same output removes what a killed run left.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "io/output_completeness.h"
#include "io/stale_temp_files.h"
#include "taatool_runner.h"

extern char** environ;

namespace taa {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class InterruptionTest : public ::testing::Test {
 protected:
  // A sequence long enough that a signal always arrives mid-run: 3 rendered frames (256x160)
  // linked under 400 frame numbers; the motion is wrong at the joins, which does not matter here.
  void SetUp() override {
    dir_ = test::freshTestFolder();
    const fs::path rendered = dir_ / "rendered";
    test::writeSeparateFrames(rendered, 1, 3, 256, 160);
    in_ = dir_ / "in";
    fs::create_directories(in_);
    for (int frame = 1; frame <= kFrames; ++frame) {
      for (const char* aov : {"beauty", "depth", "motion"}) {
        fs::create_symlink(rendered / name(aov, 1 + (frame - 1) % 3), in_ / name(aov, frame));
      }
    }
  }

  static std::string name(const std::string& stem, int frame) {
    char text[64];
    std::snprintf(text, sizeof text, "%s.%04d.exr", stem.c_str(), frame);
    return text;
  }

  // Starts taatool -v on the sequence writing into out/, stdout and stderr into files.
  pid_t start(const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {test::taatoolPath()};
    for (const auto& a : test::separateFileArgs(in_, dir_ / "out" / "r.####.exr")) {
      args.push_back(a);
    }
    args.insert(args.end(), {"-v", "--frames", "1-" + std::to_string(kFrames)});
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string out = (dir_ / "stdout.txt").string(), err = (dir_ / "stderr.txt").string();
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    EXPECT_EQ(failed, 0);
    return pid;
  }

  // Waits until taatool reports `frame` written (-v), so the signal lands mid-sequence.
  void waitForFrame(int frame) const {
    const std::string line = "frame " + std::to_string(frame) + " (";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (readText(dir_ / "stdout.txt").find(line) == std::string::npos) {
      ASSERT_LT(std::chrono::steady_clock::now(), deadline) << readText(dir_ / "stderr.txt");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  static int waitForExit(pid_t pid, bool* signalled = nullptr) {
    int status = 0;
    EXPECT_EQ(::waitpid(pid, &status, 0), pid);
    if (signalled) *signalled = WIFSIGNALED(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  }

  // Output files and leftovers in out/: every r.*.exr must be a complete frame.
  void expectOnlyCompleteFrames(int* written = nullptr) const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
      const std::string file = entry.path().filename().string();
      EXPECT_EQ(file.find(".taa-"), std::string::npos) << "left behind: " << file;
      if (file.rfind("r.", 0) == 0) {
        const io::OutputCheck check = io::checkOutputComplete(entry.path().string());
        EXPECT_TRUE(check.complete) << file << ": " << check.reason;
        ++count;
      }
    }
    if (written) *written = count;
  }

  static constexpr int kFrames = 400;
  fs::path dir_, in_;
};

TEST_F(InterruptionTest, SigtermFinishesTheFramesInFlightAndExits143) {
  const pid_t pid = start();
  waitForFrame(3);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  EXPECT_EQ(waitForExit(pid), 143);
  const std::string err = readText(dir_ / "stderr.txt");
  EXPECT_NE(err.find("taatool ERROR: interrupted by SIGTERM: stopped after "), std::string::npos)
      << err;
  int written = 0;
  expectOnlyCompleteFrames(&written);
  EXPECT_GE(written, 3);
  EXPECT_LT(written, kFrames);
}

TEST_F(InterruptionTest, SigintLikewiseExits130) {
  const pid_t pid = start({"--threads", "0"});
  waitForFrame(2);
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  EXPECT_EQ(waitForExit(pid), 130);
  EXPECT_NE(readText(dir_ / "stderr.txt").find("interrupted by SIGINT"), std::string::npos);
  expectOnlyCompleteFrames();
}

// SIGKILL cannot be handled: whatever it leaves, the next run over the output removes. The
// deterministic half (names of a dead process) is io/stale_temp_files_test.cpp; here the kill is
// real and a dead writer's temporary is planted too, since the kill may land between writes.
TEST_F(InterruptionTest, AfterSigkillTheNextRunLeavesNothingBehind) {
  const pid_t pid = start({"--threads", "3"});
  waitForFrame(4);
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  bool signalled = false;
  waitForExit(pid, &signalled);
  EXPECT_TRUE(signalled);
  const std::string planted = ".r.0002.exr.taa-tmp-" + io::temporaryHostTag() + "-" +
                              std::to_string(pid) + "-99.exr";
  std::ofstream(dir_ / "out" / planted) << "partial";

  const test::ToolRun rerun = test::runTaatool(
      [&] {
        auto args = test::separateFileArgs(in_, dir_ / "out" / "r.####.exr");
        args.insert(args.end(), {"--frames", "1-6"});
        return args;
      }(),
      dir_);
  ASSERT_EQ(rerun.exitCode, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("removed a dead run's temporary " + (dir_ / "out" / planted).string()),
            std::string::npos)
      << rerun.err;
  expectOnlyCompleteFrames();
}

}  // namespace
}  // namespace taa
