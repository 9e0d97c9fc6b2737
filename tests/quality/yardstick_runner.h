// Runs the real taa-yardstick for the end-to-end tests and reads what it wrote.
#pragma once

#include <string>

namespace taa::yardstick::test {

struct ToolRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// taa-yardstick with `arguments` (a shell-quoted string).
ToolRun runYardstick(const std::string& arguments);

std::string readFile(const std::string& path);

bool contains(const std::string& text, const std::string& part);

// The first line of `text` that starts with `prefix` ("" when none).
std::string lineStartingWith(const std::string& text, const std::string& prefix);

}  // namespace taa::yardstick::test
