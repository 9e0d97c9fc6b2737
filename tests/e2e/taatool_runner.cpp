#include "taatool_runner.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace taa::test {
namespace fs = std::filesystem;
namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

fs::path freshTestFolder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder = fs::path(TAA_TEST_TMPDIR) / info->name();
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

ToolRun runTaatool(const std::vector<std::string>& args, const fs::path& scratch) {
  std::string command = quoted(TAA_TAATOOL_PATH);
  for (const auto& a : args) command += " " + quoted(a);
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  command += " >" + quoted(out.string()) + " 2>" + quoted(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  ToolRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readText(out);
  run.err = readText(err);
  return run;
}

void expectToolError(const ToolRun& run, const std::vector<std::string>& fragments) {
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_EQ(run.err.rfind("taatool ERROR: ", 0), 0u) << run.err;
  for (const auto& f : fragments) {
    EXPECT_NE(run.err.find(f), std::string::npos) << f << " in " << run.err;
  }
}

}  // namespace taa::test
