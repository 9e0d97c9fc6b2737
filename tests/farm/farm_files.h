// Helpers of taa-farm's end-to-end tests: comparing frames and reading the tool's output.
#pragma once

#include <string>
#include <vector>

namespace taa::test {

// Empty when the two files are byte-identical (taa writes the input's header and no time of its
// own, and its ZIP is deterministic, so equal frames make equal files). Else what differs: the
// parts' channels, pixel types, windows, header attributes or pixels.
std::string frameDifference(const std::string& a, const std::string& b);

// Largest and mean absolute difference over the RGB of the first part, after Reinhard x/(1+x)
// (the yardstick's display values, DESIGN.md section 7), and PSNR on them (peak 1).
struct ToneDifference {
  double maxAbs = 0, meanAbs = 0, psnr = 0;
};
ToneDifference toneDifference(const std::string& a, const std::string& b);

// Lines of `text` starting with `prefix`.
std::vector<std::string> linesStartingWith(const std::string& text, const std::string& prefix);

}  // namespace taa::test
