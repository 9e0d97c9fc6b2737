// End-to-end: taa-farm run, status and submit's job texts on generated frames, without a
// scheduler (tests/farm/slurm_farm_test.py runs them under a real Slurm cluster). Chunked
// output against one taatool run over the shot, resuming, exit statuses and messages.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "../e2e/taatool_runner.h"
#include "farm_files.h"
#include "io/output_completeness.h"
#include "io/stale_temp_files.h"

namespace taa::test {
namespace {

namespace fs = std::filesystem;
constexpr int kFrames = 24;

std::string frameName(const std::string& stem, int frame) {
  char name[64];
  std::snprintf(name, sizeof name, "%s.%04d.exr", stem.c_str(), frame);
  return name;
}

class FarmRunTest : public ::testing::Test {
 protected:
  // One shot for the suite (64x40, frames 1-24) and taatool's whole-shot output of it in both
  // modes: what every chunked run must reproduce. CTest runs each test in its own process, some
  // at once: each process has its own folder.
  static void SetUpTestSuite() {
    root_ = fs::path(TAA_TEST_TMPDIR) / ("suite-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "ref");
    writeSeparateFrames(root_ / "in", 1, kFrames);
    for (const auto& [mode, extra] : modes()) {
      std::vector<std::string> args = shotArgs(root_ / "ref" / mode);
      args.insert(args.end(), extra.begin(), extra.end());
      const ToolRun run = runTaatool(args, root_ / "ref");
      ASSERT_EQ(run.exitCode, 0) << run.err;
    }
  }

  static std::vector<std::pair<std::string, std::vector<std::string>>> modes() {
    return {{"history", {"--mode", "history"}}, {"window", {"--mode", "window", "--window", "3"}}};
  }

  // taatool's arguments for the shot, output into `folder`.
  static std::vector<std::string> shotArgs(const fs::path& folder) {
    std::vector<std::string> args = separateFileArgs(root_ / "in", folder / "r.####.exr");
    args.insert(args.end(), {"--frames", "1-" + std::to_string(kFrames)});
    return args;
  }

  static void TearDownTestSuite() { fs::remove_all(root_); }

  void SetUp() override { dir_ = freshTestFolder(); }

  // taa-farm VERB ARGS... with the shot's taatool arguments, output into dir_/out; history
  // mode unless `mode` says otherwise (the pre-roll, resume and exit-status tests were written
  // for it; the window mode's exactness has its own test).
  ToolRun farm(std::vector<std::string> args,
               const std::vector<std::string>& mode = {"--mode", "history"}) {
    std::vector<std::string> all = shotArgs(dir_ / "out");
    all.insert(all.end(), mode.begin(), mode.end());
    args.insert(args.end(), all.begin(), all.end());
    return runProgram(TAA_FARM_PATH, args, dir_);
  }

  std::string out(int frame) const { return (dir_ / "out" / frameName("r", frame)).string(); }
  static std::string ref(const std::string& mode, int frame) {
    return (root_ / "ref" / mode / frameName("r", frame)).string();
  }

  static fs::path root_;
  fs::path dir_;
};
fs::path FarmRunTest::root_;

const std::vector<std::string> kWindow = {"--mode", "window", "--window", "3"};

TEST_F(FarmRunTest, WindowChunksAreBitIdenticalToOneRunWhateverTheChunkSize) {
  for (int chunk : {1, 5, 7, 24}) {
    fs::remove_all(dir_ / "out");
    const int tasks = (kFrames + chunk - 1) / chunk;
    for (int task = tasks - 1; task >= 0; --task) {  // any order
      const ToolRun run =
          farm({"run", "--chunk", std::to_string(chunk), "--task", std::to_string(task)}, kWindow);
      ASSERT_EQ(run.exitCode, 0) << run.err;
    }
    for (int frame = 1; frame <= kFrames; ++frame) {
      EXPECT_EQ(frameDifference(out(frame), ref("window", frame)), "")
          << "chunks of " << chunk << ", frame " << frame;
    }
  }
}

TEST_F(FarmRunTest, HistoryChunksWithThePrerollReachingTheShotStartAreBitIdentical) {
  // The default pre-roll (128) is longer than this shot: every chunk starts its history at 1.
  for (int task = 0; task < 4; ++task) {
    const ToolRun run = farm({"run", "--chunk", "6", "--task", std::to_string(task)});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    if (task == 3) {  // pre-roll 1-18: resolved, not written
      EXPECT_EQ(linesStartingWith(run.out, "PROGRESS: ").size(), 24u) << run.out;
      EXPECT_NE(run.out.find("PROGRESS: 4% frame 1 resolved for history, not written\n"),
                std::string::npos)
          << run.out;
      EXPECT_NE(run.out.find("PROGRESS: 100% frame 24 written: " + out(24) + "\n"),
                std::string::npos)
          << run.out;
      EXPECT_EQ(run.out.find("written: " + out(18)), std::string::npos) << run.out;
    }
  }
  for (int frame = 1; frame <= kFrames; ++frame) {
    EXPECT_EQ(frameDifference(out(frame), ref("history", frame)), "") << "frame " << frame;
  }
}

TEST_F(FarmRunTest, ALongerHistoryPrerollComesCloserToTheWholeShotRun) {
  // Chunk 19-24 with its history from 17, then from 11: the gap to the whole-shot run (history
  // from 1) shrinks and is never zero before the pre-roll reaches frame 1.
  double previous = 1e9;
  for (int preroll : {2, 8}) {
    fs::remove_all(dir_ / "out");
    ASSERT_EQ(farm({"run", "--chunk", "19-24", "--preroll", std::to_string(preroll)}).exitCode, 0);
    double largest = 0;
    for (int frame = 19; frame <= kFrames; ++frame) {
      largest = std::max(largest, toneDifference(out(frame), ref("history", frame)).maxAbs);
    }
    EXPECT_GT(largest, 0.0) << "pre-roll " << preroll;
    EXPECT_LT(largest, previous) << "pre-roll " << preroll;
    previous = largest;
  }
}

TEST_F(FarmRunTest, SchedulerRangesAreClippedToTheShot) {
  const ToolRun run = farm({"run", "--chunk", "21-30"}, kWindow);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("done: wrote 21-24 (4 frame(s))"), std::string::npos) << run.out;
  for (int frame = 21; frame <= 24; ++frame) {
    EXPECT_EQ(frameDifference(out(frame), ref("window", frame)), "") << frame;
  }
  EXPECT_FALSE(fs::exists(out(20)));
  const ToolRun outside = farm({"run", "--chunk", "30-40"}, kWindow);
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.err.find("--chunk 30-40 holds no frame of the shot (1-24)"),
            std::string::npos)
      << outside.err;
}

TEST_F(FarmRunTest, ARerunSkipsCompleteFramesAndRedoesTheRestIdentically) {
  ASSERT_EQ(farm({"run", "--chunk", "13-18", "--preroll", "4"}).exitCode, 0);
  fs::create_directories(dir_ / "first");
  for (int frame : {15, 17}) fs::copy_file(out(frame), dir_ / "first" / frameName("r", frame));
  const auto untouched = fs::last_write_time(out(13));
  fs::remove(out(15));
  fs::resize_file(out(17), fs::file_size(out(17)) / 2);  // cut short after it was written
  // A task killed by SIGKILL left this temporary: the rerun removes it.
  const std::string stale = (dir_ / "out" / ("." + frameName("r", 16) + ".taa-tmp-" +
                                             io::temporaryHostTag() + "-999999999-0.exr"))
                                .string();
  std::ofstream(stale) << "partial";

  const ToolRun again = farm({"run", "--chunk", "13-18", "--preroll", "4"});
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.out.find("frame 13 complete, skipped"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("frame 17 is resolved again (cannot read the pixels"),
            std::string::npos)
      << again.out;
  EXPECT_NE(again.out.find("done: wrote 15, 17 (2 frame(s)), 4 already complete"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(linesStartingWith(again.out, "PROGRESS: ").size(), 9u);  // 9-17: history from 9
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_NE(again.err.find("removed a dead run's temporary"), std::string::npos) << again.err;
  EXPECT_EQ(fs::last_write_time(out(13)), untouched);
  // The same history from 9 as the first run: the same frames.
  for (int frame : {15, 17}) {
    EXPECT_EQ(frameDifference(out(frame), (dir_ / "first" / frameName("r", frame)).string()), "")
        << frame;
  }
  const ToolRun done = farm({"run", "--chunk", "13-18", "--preroll", "4"});
  EXPECT_EQ(done.exitCode, 0);
  EXPECT_NE(done.out.find("already complete\nPROGRESS: 100%\n"), std::string::npos) << done.out;
}

TEST_F(FarmRunTest, ExitStatusesSayWhatWentWrong) {
  // 2: bad arguments, named.
  ToolRun run = runProgram(TAA_FARM_PATH, {"run", "--chunk", "6", "--task", "0", "in.#.exr",
                                           "-o", "o.#.exr", "--blend", "fast"},
                           dir_);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_EQ(run.err.rfind("taa-farm ERROR: ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("fast"), std::string::npos) << run.err;
  run = farm({"run", "--chunk", "6", "--task", "4"});
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("task 4 is past the last chunk: the shot (1-24) makes 4 chunk(s) of 6 "
                         "(tasks 0-3)"),
            std::string::npos)
      << run.err;
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  run = farm({"run", "--chunk", "6"});
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find("SLURM_ARRAY_TASK_ID is not set"), std::string::npos) << run.err;

  // 3: an input frame the chunk needs is not there yet; nothing is written.
  const fs::path in = dir_ / "in";
  fs::create_directories(in);
  for (const auto& entry : fs::directory_iterator(root_ / "in")) {
    fs::create_symlink(entry.path(), in / entry.path().filename());
  }
  fs::remove(in / frameName("motion", 20));
  const std::vector<std::string> history = {"--mode", "history"};
  auto farmOn = [&](std::vector<std::string> args, const std::vector<std::string>& extra) {
    std::vector<std::string> shot = separateFileArgs(in, dir_ / "out" / "r.####.exr");
    args.insert(args.end(), shot.begin(), shot.end());
    args.insert(args.end(), {"--frames", "1-24"});
    args.insert(args.end(), extra.begin(), extra.end());
    return runProgram(TAA_FARM_PATH, args, dir_);
  };
  run = farmOn({"run", "--chunk", "19-24"}, history);
  EXPECT_EQ(run.exitCode, 3) << run.err;
  EXPECT_NE(run.err.find("taa-farm ERROR: input frame not ready (missing), needed by chunk "
                         "19-24 : " + (in / frameName("motion", 20)).string() +
                         " (frame 20, channel motion)"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out(19)));
  // Window mode: frame 20 is in the window (K = 3) of 17, not of 13-16.
  EXPECT_EQ(farmOn({"run", "--chunk", "17-17"}, kWindow).exitCode, 3);
  EXPECT_EQ(farmOn({"run", "--chunk", "13-16"}, kWindow).exitCode, 0);
  // History: the chunk before has its pre-roll and frames before 20.
  EXPECT_EQ(farmOn({"run", "--chunk", "13-18"}, history).exitCode, 0);

  // 1: a resolve error names the file and frame.
  fs::remove(in / frameName("beauty", 22));
  std::ofstream(in / frameName("beauty", 22)) << "not an EXR";
  run = farmOn({"run", "--chunk", "22-22", "--preroll", "0"}, history);
  EXPECT_EQ(run.exitCode, 1) << run.err;
  EXPECT_NE(run.err.find((in / frameName("beauty", 22)).string() + " (frame 22"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out(22)));
}

TEST_F(FarmRunTest, StatusListsWhatIsMissingOrIncomplete) {
  ToolRun status = farm({"status"});
  EXPECT_EQ(status.exitCode, 1);
  EXPECT_NE(status.out.find("missing: 1-24\n"), std::string::npos) << status.out;
  EXPECT_NE(status.out.find("taa-farm status: 0 of 24 frames complete, missing 1-24"),
            std::string::npos)
      << status.out;
  for (int task = 0; task < 4; ++task) {
    ASSERT_EQ(farm({"run", "--chunk", "6", "--task", std::to_string(task)}, kWindow).exitCode, 0);
  }
  status = farm({"verify"}, kWindow);
  EXPECT_EQ(status.exitCode, 0) << status.out;
  EXPECT_EQ(status.out, "taa-farm status: 24 of 24 frames complete (" +
                            (dir_ / "out" / "r.####.exr").string() + ")\n");
  // Resolved in window mode: for a history job these frames are not its output.
  status = farm({"status"});
  EXPECT_EQ(status.exitCode, 1);
  EXPECT_NE(status.out.find("frame 3: incomplete (resolved with other options"),
            std::string::npos)
      << status.out;
  fs::remove(out(8));
  fs::resize_file(out(20), 1000);
  status = farm({"status", "--chunk", "6"}, kWindow);
  EXPECT_EQ(status.exitCode, 1);
  EXPECT_NE(status.out.find("missing: 8\n"), std::string::npos);
  EXPECT_NE(status.out.find("frame 20: incomplete ("), std::string::npos);
  EXPECT_NE(status.out.find("tasks to run again: 1,3"), std::string::npos) << status.out;
  EXPECT_NE(status.out.find("taa-farm status: 22 of 24 frames complete, missing 8, incomplete 20"),
            std::string::npos)
      << status.out;
}

// The job text taa-farm prints for a scheduler, from `submit --scheduler NAME`.
std::string jobText(const fs::path& dir, const std::vector<std::string>& shot,
                    const std::string& scheduler) {
  std::vector<std::string> args = {"submit", "--chunk", "7", "--scheduler", scheduler};
  args.insert(args.end(), shot.begin(), shot.end());
  const ToolRun run = runProgram(TAA_FARM_PATH, args, dir);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  return run.out;
}

// Replaces every `token` in `text` with `value`, as a scheduler does before it runs a command.
std::string expand(std::string text, const std::string& token, const std::string& value) {
  for (std::size_t at = text.find(token); at != std::string::npos;
       at = text.find(token, at + value.size())) {
    text.replace(at, token.size(), value);
  }
  return text;
}

TEST_F(FarmRunTest, OpenCueAndDeadlineTokensExpandToTheSameChunks) {
  std::vector<std::string> shot = shotArgs(dir_ / "cue");
  shot.insert(shot.end(), kWindow.begin(), kWindow.end());
  // OpenCue: a shell command; chunks of 7 over 1-24, the last one's #FRAME_END# past the end
  // as OpenCue has it (issue 1129).
  const std::string cue = jobText(dir_, shot, "opencue");
  EXPECT_EQ(cue.rfind("# OpenCue (printed, not submitted): one layer, frame range 1-24, chunk "
                      "size 7, working folder ",
                      0),
            0u)
      << cue;
  const std::string command = linesStartingWith(cue, TAA_FARM_PATH).at(0);
  for (int start = 1; start <= kFrames; start += 7) {
    const std::string line = expand(expand(command, "#FRAME_START#", std::to_string(start)),
                                    "#FRAME_END#", std::to_string(start + 6));
    const ToolRun run = runProgram("/bin/sh", {"-c", line}, dir_);
    ASSERT_EQ(run.exitCode, 0) << line << "\n" << run.err;
  }
  // Deadline: the -arguments string, <STARTFRAME>, <ENDFRAME> and <QUOTE> replaced, split at
  // spaces outside quotes (a path with a space exercises <QUOTE>).
  fs::create_directory_symlink(root_ / "in", dir_ / "in put");
  shot = separateFileArgs(dir_ / "in put", dir_ / "deadline" / "r.####.exr");
  shot.insert(shot.end(), {"--frames", "1-24"});
  shot.insert(shot.end(), kWindow.begin(), kWindow.end());
  const std::string deadline = jobText(dir_, shot, "deadline");
  const std::size_t at = deadline.find(" -arguments '");
  ASSERT_NE(at, std::string::npos) << deadline;
  ASSERT_NE(deadline.find("-executable " + std::string(TAA_FARM_PATH) +
                          " -frames 1-24 -chunksize 7 -startupdirectory "),
            std::string::npos)
      << deadline;
  const std::string arguments =
      deadline.substr(at + 13, deadline.find("'\n", at) - at - 13);  // no ' inside here
  for (int start = 1; start <= kFrames; start += 7) {
    const std::string expanded =
        expand(expand(expand(arguments, "<STARTFRAME>", std::to_string(start)), "<ENDFRAME>",
                      std::to_string(std::min(start + 6, kFrames))),
               "<QUOTE>", "\"");
    std::vector<std::string> argv;
    std::string word;
    bool quoted = false, any = false;
    for (char c : expanded + " ") {
      if (c == '"') {
        quoted = !quoted;
        any = true;
      } else if (c == ' ' && !quoted) {
        if (any || !word.empty()) argv.push_back(word);
        word.clear();
        any = false;
      } else {
        word += c;
      }
    }
    const ToolRun run = runProgram(TAA_FARM_PATH, argv, dir_);
    ASSERT_EQ(run.exitCode, 0) << expanded << "\n" << run.err;
  }
  for (int frame = 1; frame <= kFrames; ++frame) {
    for (const char* folder : {"cue", "deadline"}) {
      EXPECT_EQ(frameDifference((dir_ / folder / frameName("r", frame)).string(),
                                ref("window", frame)),
                "")
          << folder << " frame " << frame;
    }
  }
}

TEST_F(FarmRunTest, SubmitDryRunPrintsTheArrayScript) {
  const fs::path in = dir_ / "in";
  fs::create_directories(in);
  for (int frame = 5; frame <= 14; ++frame) {  // no --frames: the frames on disk are the shot
    for (const char* aov : {"beauty", "depth", "motion"}) {
      fs::create_symlink(root_ / "in" / frameName(aov, frame), in / frameName(aov, frame));
    }
  }
  std::vector<std::string> args = {"submit", "--chunk", "4", "--dry-run", "--partition", "comp",
                                   "--mem", "2G", "--log-dir", (dir_ / "logs").string()};
  for (const std::string& a : separateFileArgs(in, dir_ / "out" / "r.####.exr")) args.push_back(a);
  const ToolRun run = runProgram(TAA_FARM_PATH, args, dir_);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  for (const std::string& line : std::vector<std::string>{
           "#SBATCH --array=\"0-2\"\n", "#SBATCH --partition=\"comp\"\n",
           "#SBATCH --mem=\"2G\"\n",
           "#SBATCH --output=\"" + (dir_ / "logs").string() + "/taa-farm-%A_%a.log\"\n",
        "exec " + std::string(TAA_FARM_PATH) + " run --chunk 4 " +
            (in / "beauty.####.exr").string()}) {
    EXPECT_NE(run.out.find(line), std::string::npos) << line << " in\n" << run.out;
  }
  // The history resolve's pre-roll goes with it (the window resolve reads its own windows).
  args.insert(args.end(), {"--mode", "history"});
  const ToolRun history = runProgram(TAA_FARM_PATH, args, dir_);
  ASSERT_EQ(history.exitCode, 0) << history.err;
  EXPECT_NE(history.out.find("run --chunk 4 --preroll 128 " + (in / "beauty.####.exr").string()),
            std::string::npos)
      << history.out;
  EXPECT_NE(run.out.find(" --frames 5-14\n"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(dir_ / "logs"));  // a dry run changes nothing
}

TEST_F(FarmRunTest, SigtermStopsBetweenFramesLeavingCompleteFramesOnly) {
  // A chunk resolved slowly enough to be stopped in the middle: 256x160 frames.
  const fs::path in = dir_ / "big";
  writeSeparateFrames(in, 1, 12, 256, 160);
  std::vector<std::string> args = {"run", "--chunk", "1-12", "--threads", "0"};
  for (const std::string& a : separateFileArgs(in, dir_ / "out" / "r.####.exr")) args.push_back(a);
  std::string command = "exec '" + std::string(TAA_FARM_PATH) + "'";
  for (const std::string& a : args) command += " '" + a + "'";
  command += " >" + (dir_ / "stdout.txt").string() + " 2>" + (dir_ / "stderr.txt").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  auto text = [&](const char* name) {
    std::ifstream file(dir_ / name);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (text("stdout.txt").find("PROGRESS: ") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143) << text("stderr.txt");
  EXPECT_NE(text("stderr.txt").find("taa-farm ERROR: interrupted by SIGTERM"), std::string::npos);
  int written = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
    const std::string name = entry.path().filename().string();
    EXPECT_NE(name[0], '.') << "temporary left: " << name;
    EXPECT_TRUE(io::checkOutputComplete(entry.path().string()).complete) << name;
    ++written;
  }
  EXPECT_GE(written, 1);
  EXPECT_LT(written, 12);
}

}  // namespace
}  // namespace taa::test
