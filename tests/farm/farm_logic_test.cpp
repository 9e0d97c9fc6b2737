// taa-farm's logic without running it: chunks, the history pre-roll, arguments, the commands
// handed to schedulers.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "farm/chunk_plan.h"
#include "farm/farm_arguments.h"
#include "farm/farm_errors.h"
#include "farm/sbatch_directives.h"
#include "farm/task_commands.h"
#include "sbatch_script_model.h"

namespace taa::farm {
namespace {

std::vector<int> range(int first, int last) {
  std::vector<int> frames;
  for (int f = first; f <= last; ++f) frames.push_back(f);
  return frames;
}

TEST(ChunkPlan, ChunksPartitionTheShot) {
  const auto chunks = splitIntoChunks(range(1001, 1024), 10);
  ASSERT_EQ(chunks.size(), 3u);
  EXPECT_EQ(chunks[0], range(1001, 1010));
  EXPECT_EQ(chunks[2], range(1021, 1024));
  EXPECT_EQ(splitIntoChunks(range(1, 24), 6).size(), 4u);
  EXPECT_EQ(splitIntoChunks({1, 2, 3, 10, 11}, 2),
            (std::vector<std::vector<int>>{{1, 2}, {3, 10}, {11}}));
}

TEST(ChunkPlan, ARangeIsClippedToTheShot) {
  // OpenCue's #FRAME_END# can run past the shot's end (OpenCue issue 1129).
  EXPECT_EQ(framesWithin(range(1, 72), 71, 80), range(71, 72));
  EXPECT_TRUE(framesWithin(range(1, 72), 73, 80).empty());
  EXPECT_EQ(framesWithin({-3, -2, -1, 0}, -2, -1), (std::vector<int>{-2, -1}));
}

TEST(ChunkPlan, HistoryPrerollIsFixedPerChunk) {
  const auto shot = range(1, 24);
  const auto chunk = range(13, 18);
  ChunkWork all = planHistoryChunk(shot, chunk, chunk, 4, {});
  EXPECT_EQ(all.resolve, range(9, 18));
  EXPECT_EQ(all.preroll, (std::set<int>{9, 10, 11, 12}));
  EXPECT_EQ(all.write, chunk);
  // A rerun after 13-15 were written: the same history from 9, 13-15 resolved but not written,
  // so 16-18 come out as the first run would have made them.
  ChunkWork rest = planHistoryChunk(shot, chunk, {16, 17, 18}, 4, {});
  EXPECT_EQ(rest.resolve, range(9, 18));
  EXPECT_EQ(rest.preroll, (std::set<int>{9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(rest.write, (std::vector<int>{16, 17, 18}));
  // Only the first frame missing: nothing after it is resolved.
  EXPECT_EQ(planHistoryChunk(shot, chunk, {13}, 4, {}).resolve, range(9, 13));
}

TEST(ChunkPlan, HistoryPrerollStopsWhereAHistoryStarts) {
  const auto chunk = range(13, 18);
  EXPECT_EQ(planHistoryChunk(range(1, 24), chunk, chunk, 100, {}).resolve.front(), 1);
  EXPECT_EQ(planHistoryChunk(range(1, 24), chunk, chunk, 0, {}).resolve.front(), 13);
  EXPECT_EQ(planHistoryChunk(range(1, 24), chunk, chunk, 8, {10}).resolve.front(), 10);
  EXPECT_EQ(planHistoryChunk(range(1, 24), chunk, chunk, 8, {13}).resolve.front(), 13);
  std::vector<int> gap = range(1, 5);
  for (int f : range(11, 24)) gap.push_back(f);  // 6-10 missing: history restarts at 11
  EXPECT_EQ(planHistoryChunk(gap, chunk, chunk, 8, {}).resolve.front(), 11);
  EXPECT_TRUE(planHistoryChunk(range(1, 24), chunk, {}, 8, {}).resolve.empty());
}

TEST(ChunkPlan, WindowChunksResolveOnlyWhatIsMissing) {
  const ChunkWork work = planWindowChunk({14, 17});
  EXPECT_EQ(work.resolve, (std::vector<int>{14, 17}));
  EXPECT_TRUE(work.preroll.empty());
  EXPECT_EQ(work.write, (std::vector<int>{14, 17}));
}

std::string usageErrorOf(const std::vector<std::string>& args) {
  try {
    parseFarmArguments(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(FarmArguments, FarmOptionsAnywhereTaatoolsPassThrough) {
  const FarmArguments args =
      parseFarmArguments({"submit", "b.####.exr", "--chunk", "20", "--frames", "1001-1240",
                          "--partition", "gpu", "-o", "o.####.exr", "--blend", "0.1",
                          "--sbatch-arg", "--qos=high", "--sbatch-arg", "--exclusive"});
  EXPECT_EQ(args.verb, "submit");
  EXPECT_EQ(args.chunkSize, 20);
  EXPECT_EQ(args.preroll, kDefaultPreroll);
  EXPECT_EQ(args.slurm.partition, "gpu");
  EXPECT_EQ(args.slurm.extra, (std::vector<std::string>{"--qos=high", "--exclusive"}));
  EXPECT_EQ(args.taatoolArgs, (std::vector<std::string>{"b.####.exr", "--frames", "1001-1240",
                                                        "-o", "o.####.exr", "--blend", "0.1"}));
  const FarmArguments run = parseFarmArguments({"run", "--chunk", "-5--1", "x.#.exr"});
  EXPECT_EQ(run.chunkRange, std::make_pair(-5, -1));
  EXPECT_EQ(parseFarmArguments({"verify", "x.#.exr"}).verb, "status");
}

TEST(FarmArguments, MistakesAreUsageErrors) {
  EXPECT_NE(usageErrorOf({}).find("no verb"), std::string::npos);
  EXPECT_NE(usageErrorOf({"resolve"}).find("unknown verb \"resolve\""), std::string::npos);
  EXPECT_NE(usageErrorOf({"submit", "x.#.exr"}).find("needs --chunk N"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "x.#.exr"}).find("needs --chunk"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "--chunk", "0"}).find("--chunk expects an integer >= 1"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "--chunk", "20-10"}).find("FIRST-LAST"), std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "--chunk", "5", "--partition", "p"})
                .find("--partition is not an option of taa-farm run"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"run", "--chunk", "1-5", "--task", "2"}).find("--task"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"submit", "--chunk", "5", "--preroll", "-1"}).find("--preroll"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"submit", "--chunk", "5", "--chunk", "6"}).find("given twice"),
            std::string::npos);
  EXPECT_NE(usageErrorOf({"submit", "--chunk", "5", "--scheduler", "tractor"}).find("tractor"),
            std::string::npos);
  // taa-farm's own options also take "--name=value"; taatool's pass through as they are.
  const FarmArguments attached =
      parseFarmArguments({"submit", "--chunk=6", "--sbatch-arg=--qos=high", "--blend=0.1"});
  EXPECT_EQ(attached.chunkSize, 6);
  EXPECT_EQ(attached.slurm.extra, (std::vector<std::string>{"--qos=high"}));
  EXPECT_EQ(attached.taatoolArgs, (std::vector<std::string>{"--blend=0.1"}));
}

TEST(TaskCommands, ShellQuoting) {
  EXPECT_EQ(shellQuoted("beauty.####.exr"), "beauty.####.exr");
  EXPECT_EQ(shellQuoted("/a/b_c-1.exr"), "/a/b_c-1.exr");
  EXPECT_EQ(shellQuoted("#FRAME_START#-#FRAME_END#"), "'#FRAME_START#-#FRAME_END#'");
  EXPECT_EQ(shellQuoted("my shot"), "'my shot'");
  EXPECT_EQ(shellQuoted("it's"), "'it'\\''s'");
  EXPECT_EQ(shellQuoted("$HOME"), "'$HOME'");
  EXPECT_EQ(shellQuoted(""), "''");
}

TaskCommand exampleTask() {
  TaskCommand task;
  task.farmPath = "/opt/taa/bin/taa-farm";
  task.workingFolder = "/shots/sh010";
  task.taatoolArgs = {"render.####.exr", "--preset", "cycles", "--frames", "1001-1240", "-o",
                      "out/resolved.####.exr"};
  task.framesText = "1001-1240";
  task.chunkSize = 20;
  task.chunkCount = 12;
  task.preroll = 16;
  return task;
}

TEST(TaskCommands, SlurmArrayScript) {
  SlurmOptions slurm;
  slurm.partition = "comp";
  slurm.time = "01:00:00";
  slurm.extra = {"--qos=high", "--exclusive", "-A show"};
  const std::string script = slurmArrayScript(exampleTask(), slurm);
  EXPECT_EQ(script.rfind("#!/bin/sh\n", 0), 0u);
  for (const char* line :
       {"#SBATCH --array=\"0-11\"\n", "#SBATCH --output=\"taa-farm-%A_%a.log\"\n",
        "#SBATCH --open-mode=\"append\"\n", "#SBATCH --requeue\n",
        "#SBATCH --partition=\"comp\"\n", "#SBATCH --time=\"01:00:00\"\n",
        "#SBATCH --qos=\"high\"\n", "#SBATCH --exclusive\n", "#SBATCH -A \"show\"\n",
        "\ncd -- /shots/sh010 || exit 1\n"
        "exec /opt/taa/bin/taa-farm run --chunk 20 --preroll 16 render.####.exr --preset cycles "
        "--frames 1001-1240 -o out/resolved.####.exr\n"}) {
    EXPECT_NE(script.find(line), std::string::npos) << line << " in\n" << script;
  }
  EXPECT_EQ(script.find("--mem"), std::string::npos);
  EXPECT_EQ(script.find("--chdir"), std::string::npos);  // sbatch starts where submit runs it
  slurm.logDir = "/logs/sh010";
  EXPECT_NE(slurmArrayScript(exampleTask(), slurm)
                .find("#SBATCH --output=\"/logs/sh010/taa-farm-%A_%a.log\"\n"),
            std::string::npos);
}

std::string usageErrorOfScript(const TaskCommand& task, const SlurmOptions& slurm) {
  try {
    slurmArrayScript(task, slurm);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(SbatchDirectives, SbatchReadsBackExactlyTheValueGiven) {
  for (const std::string value :
       {"plain", "My Show", "it's \"quoted\"", "back\\slash\\", "#not a comment", ":colon",
        "a hetjob and a PackJob", "$(touch pwned) `id` ${HOME}", "tab\there", "\xff\xfe bytes",
        "trailing\\"}) {
    const testing::ParsedScript parsed =
        testing::parseBatchScript(sbatchLine("--job-name", value, "--job-name"));
    EXPECT_EQ(parsed.error, "") << value;
    EXPECT_EQ(parsed.sbatchWords, (std::vector<std::string>{"--job-name=" + value})) << value;
  }
}

TEST(SbatchDirectives, ALineBreakIsRefusedNamingWhereItCameFrom) {
  TaskCommand task = exampleTask();
  SlurmOptions slurm;
  slurm.mem = "4G\n#SBATCH --x";
  EXPECT_NE(usageErrorOfScript(task, slurm).find("--mem holds a line break"), std::string::npos);
  slurm = {};
  slurm.extra = {"--comment=a\rb"};
  EXPECT_NE(usageErrorOfScript(task, slurm).find("line break"), std::string::npos);
  slurm = {};
  slurm.logDir = "/logs/%j";
  EXPECT_NE(usageErrorOfScript(task, slurm).find("'%'"), std::string::npos);
  slurm = {};
  for (const std::string bad : {"qos=high", "--", "-", "--q os=x", "-5", "--$(x)=1"}) {
    slurm.extra = {bad};
    EXPECT_NE(usageErrorOfScript(task, slurm).find("expected one sbatch option"),
              std::string::npos)
        << bad;
  }
}

// Random values over every byte but NUL: whatever the folder, names and arguments hold, sbatch
// reads back the values given and bash runs cd and taa-farm with the arguments given, nothing
// else (a value with a line break in an #SBATCH line is refused instead).
TEST(SbatchDirectives, PropertyAnyValueComesBackExactlyOrIsRefused) {
  std::mt19937 random(25);
  auto randomText = [&random](bool lineBreaks) {
    static const std::string nasty = " '\"\\#$`;&|<>(){}*?~!:\t\n\r\xff\xc3";
    std::string text;
    const int length = int(random() % 24);
    for (int i = 0; i < length; ++i) {
      char c = random() % 2 ? nasty[random() % nasty.size()] : char(1 + random() % 255);
      if (!lineBreaks && (c == '\n' || c == '\r')) c = '_';
      text += c;
    }
    return text;
  };
  int submitted = 0, refused = 0;
  for (int round = 0; round < 200; ++round) {
    TaskCommand task = exampleTask();
    task.workingFolder = "/shots/" + randomText(true);
    task.taatoolArgs = {randomText(true), "--frames", "1-3", "-o", randomText(true)};
    SlurmOptions slurm;
    slurm.jobName = randomText(round % 4 == 0);
    slurm.partition = randomText(false);
    slurm.logDir = "/logs/" + randomText(false);
    std::replace(slurm.logDir.begin(), slurm.logDir.end(), '%', '_');
    slurm.extra = {"--comment=" + randomText(false)};
    std::string script;
    try {
      script = slurmArrayScript(task, slurm);
    } catch (const UsageError& e) {
      ASSERT_NE(slurm.jobName.find_first_of("\r\n"), std::string::npos) << e.what();
      ++refused;
      continue;
    }
    ++submitted;
    const testing::ParsedScript parsed = testing::parseBatchScript(script);
    ASSERT_EQ(parsed.error, "") << script;
    std::vector<std::string> sbatchExpected = {
        "--job-name=" + (slurm.jobName.empty() ? std::string("taa-farm") : slurm.jobName),
        "--array=0-11", "--output=" + slurm.logDir + "/taa-farm-%A_%a.log",
        "--open-mode=append", "--requeue"};
    if (!slurm.partition.empty()) sbatchExpected.push_back("--partition=" + slurm.partition);
    sbatchExpected.push_back(slurm.extra[0]);
    EXPECT_EQ(parsed.sbatchWords, sbatchExpected) << script;
    std::vector<std::string> expected = {"cd", "--", task.workingFolder, "exec", task.farmPath,
                                         "run", "--chunk", "20", "--preroll", "16"};
    expected.insert(expected.end(), task.taatoolArgs.begin(), task.taatoolArgs.end());
    EXPECT_EQ(testing::commandWordsBashRuns(parsed.body), expected) << script;
  }
  EXPECT_GT(submitted, 100);
  EXPECT_GT(refused, 5);
}

TEST(TaskCommands, OtherSchedulersRunTheSameLineWithTheirTokens) {
  TaskCommand task = exampleTask();
  EXPECT_NE(openCueLayerText(task).find(
                "\n/opt/taa/bin/taa-farm run --chunk '#FRAME_START#-#FRAME_END#' --preroll 16 "
                "render.####.exr --preset cycles --frames 1001-1240 -o out/resolved.####.exr\n"),
            std::string::npos)
      << openCueLayerText(task);
  task.taatoolArgs[0] = "my render.####.exr";
  const std::string deadline = deadlineJobText(task);
  EXPECT_NE(deadline.find("-frames 1001-1240 -chunksize 20 -startupdirectory /shots/sh010 "
                          "-arguments 'run --chunk <STARTFRAME>-<ENDFRAME> --preroll 16 "
                          "<QUOTE>my render.####.exr<QUOTE> --preset cycles"),
            std::string::npos)
      << deadline;
  task.history = false;  // window mode: no pre-roll
  EXPECT_EQ(runCommandLine(task, "1-2").find("--preroll"), std::string::npos);
}

}  // namespace
}  // namespace taa::farm
