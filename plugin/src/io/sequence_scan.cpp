#include "io/sequence_scan.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <filesystem>

#include "io/sequence_pattern.h"

namespace taa::io {
namespace {

// True for an optional '-' followed by one or more digits.
bool isFrameNumber(const std::string& text) {
  const std::size_t start = (!text.empty() && text[0] == '-') ? 1 : 0;
  if (text.size() == start) return false;
  return std::all_of(text.begin() + start, text.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

std::optional<int> frameOfFileName(const std::string& pattern, const std::string& fileName) {
  if (!hasFramePlaceholder(pattern)) return std::nullopt;
  namespace fs = std::filesystem;
  // The text around the placeholder in the file name, found by expanding two frames and
  // comparing, so the placeholder syntax is parsed in one place only (sequence_pattern.cpp).
  const std::string one = fs::path(expandFramePattern(pattern, 1)).filename().string();
  const std::string two = fs::path(expandFramePattern(pattern, 2)).filename().string();
  std::size_t prefixLength = 0;
  while (prefixLength < one.size() && one[prefixLength] == two[prefixLength]) ++prefixLength;
  while (prefixLength > 0 && one[prefixLength - 1] == '0') --prefixLength;  // padding zeros
  std::size_t suffixLength = 0;  // both names have the same length: same padding, one digit
  while (suffixLength < one.size() - prefixLength &&
         one[one.size() - 1 - suffixLength] == two[two.size() - 1 - suffixLength]) {
    ++suffixLength;
  }
  const std::string prefix = one.substr(0, prefixLength);
  const std::string suffix = one.substr(one.size() - suffixLength);

  const std::string& name = fileName;
  if (name.size() <= prefix.size() + suffix.size()) return std::nullopt;
  if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  if (name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return std::nullopt;
  const std::string middle =
      name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  // At most 10 digits and a sign: "-2147483648" is INT_MIN's name.
  if (!isFrameNumber(middle) || middle.size() > (middle[0] == '-' ? 11u : 10u)) {
    return std::nullopt;
  }
  const long long number = std::stoll(middle);
  if (number < INT_MIN || number > INT_MAX) return std::nullopt;
  const int frame = int(number);
  // Keep only names the pattern itself produces (rejects other paddings).
  if (fs::path(expandFramePattern(pattern, frame)).filename() != name) return std::nullopt;
  return frame;
}

std::optional<int> frameNumberInFileName(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  const std::size_t extension = name.rfind('.');
  if (extension == std::string::npos || extension == 0) return std::nullopt;
  std::size_t begin = extension;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(name[begin - 1]))) --begin;
  if (begin == extension) return std::nullopt;
  if (begin > 0 && name[begin - 1] == '-') --begin;
  if (begin == 0 || (name[begin - 1] != '.' && name[begin - 1] != '_')) return std::nullopt;
  const std::string number = name.substr(begin, extension - begin);
  if (number.size() > (number[0] == '-' ? 11u : 10u)) return std::nullopt;
  const long long value = std::stoll(number);
  if (value < INT_MIN || value > INT_MAX) return std::nullopt;
  return int(value);
}

std::vector<int> scanExistingFrames(const std::string& pattern) {
  if (!hasFramePlaceholder(pattern)) return {};
  namespace fs = std::filesystem;
  fs::path folder = fs::path(expandFramePattern(pattern, 1)).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  std::vector<int> frames;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::optional<int> frame = frameOfFileName(pattern, entry.path().filename().string());
    if (frame) frames.push_back(*frame);
  }
  std::sort(frames.begin(), frames.end());
  return frames;
}

}  // namespace taa::io
