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

// The file name for one frame. Every placeholder in the pattern is replaced (so a frame folder
// and file name can both carry one); a pattern without a placeholder is returned unchanged.
// A '%' not followed by "d" or "0Nd" is literal.
std::string expandFramePattern(const std::string& pattern, int frame);

// Parses "1-48", "1-48x2" (step), "7", "1-3,10,20-22" into frames in the order listed,
// duplicates removed. Negative frames are written with their sign: "-5--1", "-2-3". A range
// whose end is below its start runs backwards ("5-1x2" = 5, 3, 1). Spaces around items are
// ignored. Throws taa::Error quoting the text for malformed text, an empty list, a step below 1
// or a list of more than a million frames.
std::vector<int> parseFrameRange(const std::string& text);

}  // namespace taa::io
