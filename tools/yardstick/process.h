// Runs another program (taatool, taa-scenegen) with an argument vector, no shell involved.
#pragma once

#include <string>
#include <vector>

namespace taa::yardstick {

// Runs argv[0] (found on PATH when it has no slash) with its arguments, stdout and stderr
// appended to `logPath`; returns the exit status (-1 when it could not be started or did not
// exit normally).
int runProcess(const std::vector<std::string>& argv, const std::string& logPath);

// One printable line for a command (arguments with spaces quoted), for logs and docs.
std::string commandLine(const std::vector<std::string>& argv);

}  // namespace taa::yardstick
