// What sbatch and the shell make of a batch script taa-farm wrote, for the tests and the fuzz
// target: the `#SBATCH` words as sbatch's own parser splits them (Slurm 22.05,
// src/sbatch/opt.c: quotes, backslash escapes, '#' comments, the hetjob/packjob blanking), the
// rest as lines. The model is checked against the real sbatch by tests/farm/test_slurm_farm.py,
// which submits such scripts and reads the values back with scontrol.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace taa::farm::testing {

struct ParsedScript {
  std::vector<std::string> sbatchWords;  // every #SBATCH line's words, in order
  std::string body;                      // the script from the first command on
  std::string error;                     // what sbatch would refuse ("unmatched quote"), if any
};

ParsedScript parseBatchScript(const std::string& script);

// The commands the real bash runs for `body`, with `cd` and `exec` replaced by functions that
// print their name and arguments, NUL-separated: [cd, --, folder, exec, taa-farm, run, ...].
// Anything else the body ran would print among them. Nothing when bash fails.
std::optional<std::vector<std::string>> commandWordsBashRuns(const std::string& body);

}  // namespace taa::farm::testing
