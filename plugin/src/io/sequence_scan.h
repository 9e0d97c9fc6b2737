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

// The frame number a single file's name carries, as renderers and oiiotool write it: a run of
// digits (an optional '-' before it) after a '.' or '_' and right before the extension
// ("shot.0001.exr": 1, "beauty_1001.exr": 1001). Nothing for a name without one ("shot.exr",
// "take2.exr") or a number beyond int.
std::optional<int> frameNumberInFileName(const std::string& path);

}  // namespace taa::io
