// Why an input file cannot be opened, said precisely: a link whose target is gone, or a loop of
// links, is not the same fault as a frame never rendered (issue 25: both read "missing").
#pragma once

#include <string>

namespace taa::io {

// "" when `path` is a regular file (after following links); otherwise what it is: "missing",
// "a symbolic link to TARGET, which does not exist", "a loop of symbolic links", "a folder",
// "not a regular file", or the system's reason ("Permission denied").
std::string fileAbsence(const std::string& path);

}  // namespace taa::io
