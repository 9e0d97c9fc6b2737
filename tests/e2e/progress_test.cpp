// End-to-end: taatool's progress (issue 24). On a terminal, one line on stderr rewritten after
// each frame with frames done, frames per second and the time left; in a log, a line per frame;
// nothing with -q. The terminal is a real pseudo-terminal, as a user's shell gives taatool.
#include <gtest/gtest.h>

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <regex>

#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

// Runs taatool with stdin, stdout and stderr on a pseudo-terminal; returns what it printed.
std::string runOnTerminal(const std::vector<std::string>& args, int* exitCode) {
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    std::vector<char*> argv;
    const std::string program = test::taatoolPath();
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  EXPECT_GT(pid, 0) << "forkpty failed";
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t got = read(master, buffer, sizeof buffer);
    if (got > 0) {
      text.append(buffer, std::size_t(got));
    } else if (got < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // EIO once the child has closed the terminal
    }
  }
  close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  *exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return text;
}

class ProgressTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    test::writeSeparateFrames(dir_ / "in", 1, 4);
  }
  std::vector<std::string> args(const std::string& out, std::vector<std::string> extra) const {
    std::vector<std::string> a = test::separateFileArgs(dir_ / "in", dir_ / out / "r.####.exr");
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }
  fs::path dir_;
};

TEST_F(ProgressTest, OnATerminalOneLineRewrittenWithRateAndTimeLeft) {
  int exitCode = -1;
  const std::string text = runOnTerminal(args("tty", {"--mode", "history"}), &exitCode);
  ASSERT_EQ(exitCode, 0) << text;
  // The terminal turns "\n" into "\r\n"; every update starts with a bare '\r'.
  for (int done = 1; done <= 4; ++done) {
    const std::regex update("\rtaatool: " + std::to_string(done) +
                            "/4 frames, [0-9.]+ frames/s(, [0-9]+:[0-9]{2} left)?\x1b\\[K");
    EXPECT_TRUE(std::regex_search(text, update)) << done << ": " << text;
  }
  EXPECT_NE(text.find(", 0:0"), std::string::npos) << text;  // a time left was given
  const std::size_t lastUpdate = text.rfind("\rtaatool: 4/4 frames");
  ASSERT_NE(lastUpdate, std::string::npos);
  EXPECT_EQ(text.find("\n"), text.find("\r\n", lastUpdate) + 1) << text;  // one line, ended
}

TEST_F(ProgressTest, InALogALinePerFrameAndNothingWithQuiet) {
  const test::ToolRun logged = test::runTaatool(args("log", {}), dir_);
  ASSERT_EQ(logged.exitCode, 0) << logged.err;
  for (int frame = 1; frame <= 4; ++frame) {
    const std::regex line("(^|\n)taatool: frame " + std::to_string(frame) + " written, " +
                          std::to_string(frame) + "/4 frames, [0-9.]+ frames/s");
    EXPECT_TRUE(std::regex_search(logged.err, line)) << logged.err;
  }
  EXPECT_EQ(logged.err.find('\r'), std::string::npos);

  const test::ToolRun quiet = test::runTaatool(args("quiet", {"-q"}), dir_);
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out, "");

  const test::ToolRun verbose = test::runTaatool(args("verbose", {"-v"}), dir_);
  ASSERT_EQ(verbose.exitCode, 0) << verbose.err;
  EXPECT_TRUE(std::regex_search(verbose.out, std::regex("frame 3 \\(3/4, [0-9.]+ "
                                                        "frames/s, [0-9]+:[0-9]{2} left\\): ")))
      << verbose.out;
  EXPECT_EQ(verbose.err.find("written, "), std::string::npos) << verbose.err;
}

}  // namespace
}  // namespace taa
