// Text from outside (paths, option values) made safe to print as part of one line.
#pragma once

#include <string>

namespace taa {

// `text` with its control characters and backslashes written as escapes (\n, \t, \\, \xNN),
// so that a path stays on one line of a log a farm manager parses.
std::string oneLineText(const std::string& text);

}  // namespace taa
