#include "taatool_runner.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"

extern char** environ;

namespace taa::test {
namespace fs = std::filesystem;
namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

fs::path freshTestFolderIn(const fs::path& root) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder = root / info->name();
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
                   const fs::path& scratch, const std::vector<std::string>& unset) {
  // Spawned directly, no shell: arguments reach the program as they are, whatever they hold.
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv = {const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<char*> environment;
  for (char** variable = environ; *variable; ++variable) {
    const std::string entry = *variable;
    const std::string name = entry.substr(0, entry.find('='));
    if (std::find(unset.begin(), unset.end(), name) == unset.end()) {
      environment.push_back(*variable);
    }
  }
  environment.push_back(nullptr);
  pid_t pid = 0;
  const int failed =
      posix_spawnp(&pid, program.c_str(), &files, nullptr, argv.data(), environment.data());
  posix_spawn_file_actions_destroy(&files);
  ToolRun run;
  if (failed != 0) {
    run.err = "cannot run " + program + ": " + std::strerror(failed);
    return run;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readText(out);
  run.err = readText(err);
  return run;
}

void expectToolError(const ToolRun& run, const std::vector<std::string>& fragments) {
  EXPECT_EQ(run.exitCode, 1) << run.err;
  // The error is the last line (progress lines may come before it when stderr is no terminal).
  const std::size_t at = run.err.rfind("taatool ERROR: ");
  EXPECT_TRUE(at != std::string::npos && (at == 0 || run.err[at - 1] == '\n')) << run.err;
  EXPECT_EQ(run.err.find('\n', at), run.err.size() - 1) << run.err;
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

std::string frameName(const std::string& stem, int frame) {
  char name[64];
  std::snprintf(name, sizeof name, "%s.%04d.exr", stem.c_str(), frame);
  return name;
}

Exr readExr(const fs::path& path) {
  Exr exr;
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  if (!in) return exr;
  exr.spec = in->spec();
  exr.pixels.resize(exr.spec.image_pixels() * std::size_t(exr.spec.nchannels));
  EXPECT_TRUE(in->read_image(0, 0, 0, exr.spec.nchannels, OIIO::TypeFloat, exr.pixels.data()));
  return exr;
}

}  // namespace taa::test
