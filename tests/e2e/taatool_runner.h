// Running the taatool binary from the end-to-end tests, and checking how it failed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace taa::test {

struct ToolRun {
  int exitCode = -1;  // -1 when taatool did not exit normally
  std::string out, err;
};

// A fresh folder for the running test: TAA_TEST_TMPDIR/<test name>, emptied first.
std::filesystem::path freshTestFolder();

// Runs taatool (TAA_TAATOOL_PATH) with `args` and no standard input; stdout and stderr are
// captured through files in `scratch`.
ToolRun runTaatool(const std::vector<std::string>& args, const std::filesystem::path& scratch);

// Expects a failure as taatool reports one: exit status 1, stderr starting "taatool ERROR: ",
// and each of `fragments` in the message.
void expectToolError(const ToolRun& run, const std::vector<std::string>& fragments);

}  // namespace taa::test
