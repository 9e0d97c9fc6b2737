#include "taatool_runner.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"

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

std::string taatoolPath() {
  const char* other = std::getenv("TAA_TAATOOL_PATH");
  return other && *other ? other : TAA_TAATOOL_PATH;
}

ToolRun runTaatool(const std::vector<std::string>& args, const fs::path& scratch) {
  return runProgram(taatoolPath(), args, scratch);
}

ToolRun runProgram(const std::string& program, const std::vector<std::string>& args,
                   const fs::path& scratch) {
  std::string command = quoted(program);
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

void writeSeparateFrames(const fs::path& folder, int first, int last, int width, int height,
                         const std::string& scene) {
  auto generator = scenes::makeScene(scene, width, height);
  scenes::RenderSettings settings;
  settings.truthSamplesPerAxis = 1;  // the truth is not what end-to-end tests check
  for (int frame = first; frame <= last; ++frame) {
    scenes::writeFrame(generator->render(frame, settings), scene, scenes::OutputLayout::Separate,
                       folder.string());
  }
}

std::vector<std::string> separateFileArgs(const fs::path& in, const fs::path& outPattern) {
  return {(in / "beauty.####.exr").string(), "--depth", (in / "depth.####.exr").string(),
          "--motion", (in / "motion.####.exr").string(), "-o", outPattern.string()};
}

}  // namespace taa::test
