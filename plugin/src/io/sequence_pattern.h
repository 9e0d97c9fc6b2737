// Frame-numbered file patterns and frame ranges, oiiotool style.
//   '#'          a single hash: the frame number padded to 4 digits (oiiotool)
//   '##...#'     a run of n > 1 hashes: padded to n digits (Nuke style, "####" = 4 digits)
//   '@@@'        a run of n at-signs: padded to n digits
//   '%0Nd', '%d' printf style
// Negative frames keep their sign in front of the padded digits: -0005.
#pragma once

#include <string>
#include <vector>

namespace taa::io {

// True if the pattern contains a frame placeholder.
bool hasFramePlaceholder(const std::string& pattern);

// The file name for one frame. A pattern without a placeholder is returned unchanged.
std::string expandFramePattern(const std::string& pattern, int frame);

// Parses "1-48", "1-48x2" (step), "7", "1-3,10,20-22" into frames in the order listed,
// duplicates removed. Throws taa::Error for malformed text or an empty result.
std::vector<int> parseFrameRange(const std::string& text);

}  // namespace taa::io
