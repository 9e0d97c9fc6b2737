// Helpers of taa-farm's end-to-end tests: comparing frames and reading the tool's output.
#pragma once

#include <string>
#include <vector>

namespace taa::test {

// Empty when the two EXRs hold the same frame: every part's channels, pixel types, windows and
// pixels bit for bit, and every header attribute but DateTime, which OpenImageIO's EXR writer
// sets to the time of writing when the input has none (taa copies the input's when it has one;
// then equal frames make byte-identical files). Else what differs.
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
