// Finding which frames of a pattern exist on disk, for runs without an explicit --frames.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace taa::io {

// Frame numbers whose file exists for `pattern`, ascending. Looks in the pattern's folder for
// names that match it with digits (and an optional leading '-') in place of the placeholder,
// honouring the placeholder's padding. A pattern without a placeholder yields nothing.
std::vector<int> scanExistingFrames(const std::string& pattern);

// The frame whose file name (no folder) `pattern` gives as `fileName`, if any: the same matching
// as scanExistingFrames. Nothing for a pattern without a placeholder.
std::optional<int> frameOfFileName(const std::string& pattern, const std::string& fileName);

}  // namespace taa::io
