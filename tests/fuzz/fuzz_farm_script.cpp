// libFuzzer target: taa-farm submit's Slurm batch script (farm/task_commands.h, the only writer
// of #SBATCH lines). The input is split at NUL bytes into the working folder, the job name,
// the partition, the log folder, one --sbatch-arg and taatool's arguments. The script is either
// refused (UsageError) or, read back as sbatch reads it (tests/farm/sbatch_script_model), holds
// exactly the values given, and its body is exactly `cd -- FOLDER || exit 1` and `exec` of
// taa-farm with the arguments given, each one shell word (issue 25, defect 1).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "farm/farm_errors.h"
#include "farm/sbatch_directives.h"
#include "farm/task_commands.h"
#include "sbatch_script_model.h"

namespace {

using taa::farm::SlurmOptions;
using taa::farm::TaskCommand;

// The tokens of shell text as task_commands writes it: words (bare, 'quoted' runs, '\'' for a
// quote), "||" and line breaks as tokens of their own. Anything else the shell would act on (an
// unquoted $, `, ;, & or a lone |) makes it nothing.
bool shellTokens(const std::string& text, std::vector<std::string>& tokens) {
  std::string word;
  bool inWord = false;
  auto endWord = [&] {
    if (inWord) tokens.push_back(word);
    word.clear();
    inWord = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ') {
      endWord();
    } else if (c == '\n') {
      endWord();
      tokens.push_back("\n");
    } else if (c == '|' && i + 1 < text.size() && text[i + 1] == '|' && !inWord) {
      tokens.push_back("||");
      ++i;
    } else if (c == '\'') {
      const std::size_t end = text.find('\'', i + 1);
      if (end == std::string::npos) return false;
      word += text.substr(i + 1, end - i - 1);
      inWord = true;
      i = end;
    } else if (c == '\\' && i + 1 < text.size() && text[i + 1] == '\'') {
      word += '\'';
      inWord = true;
      ++i;
    } else if (std::string("$`;&|<>(){}*?~!\"\\\t\r").find(c) != std::string::npos ||
               (c == '#' && !inWord)) {
      return false;
    } else {
      word += c;
      inWord = true;
    }
  }
  endWord();
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> fields(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      fields.emplace_back();
    } else {
      fields.back() += char(data[i]);
    }
  }
  fields.resize(std::max<std::size_t>(fields.size(), 6));
  TaskCommand task;
  task.farmPath = "/opt/taa/bin/taa-farm";
  task.workingFolder = "/" + fields[0];
  task.taatoolArgs.assign(fields.begin() + 5, fields.end());
  task.framesText = "1-10";
  task.chunkSize = 5;
  task.chunkCount = 2;
  task.history = false;
  SlurmOptions slurm;
  slurm.jobName = fields[1];
  slurm.partition = fields[2];
  slurm.logDir = fields[3].empty() ? "" : "/" + fields[3];
  if (!fields[4].empty()) slurm.extra = {"--comment=" + fields[4]};

  std::string script;
  try {
    script = taa::farm::slurmArrayScript(task, slurm);
  } catch (const taa::farm::UsageError&) {
    return 0;  // refused, with a message
  }
  const taa::farm::testing::ParsedScript parsed = taa::farm::testing::parseBatchScript(script);
  if (!parsed.error.empty()) __builtin_trap();
  const std::string logs = slurm.logDir.empty() ? "" : slurm.logDir + "/";
  std::vector<std::string> expected = {
      "--job-name=" + (slurm.jobName.empty() ? std::string("taa-farm") : slurm.jobName),
      "--array=0-1", "--output=" + logs + "taa-farm-%A_%a.log", "--open-mode=append",
      "--requeue"};
  if (!slurm.partition.empty()) expected.push_back("--partition=" + slurm.partition);
  if (!slurm.extra.empty()) expected.push_back(slurm.extra[0]);
  if (parsed.sbatchWords != expected) __builtin_trap();

  std::vector<std::string> tokens;
  if (!shellTokens(parsed.body, tokens)) __builtin_trap();
  std::vector<std::string> wanted = {"cd", "--", task.workingFolder, "||", "exit", "1", "\n",
                                     "exec", task.farmPath, "run", "--chunk", "5"};
  wanted.insert(wanted.end(), task.taatoolArgs.begin(), task.taatoolArgs.end());
  wanted.push_back("\n");
  if (tokens != wanted) __builtin_trap();
  return 0;
}
