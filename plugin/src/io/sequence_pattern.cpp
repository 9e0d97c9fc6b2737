#include "io/sequence_pattern.h"

#include <cctype>
#include <climits>
#include <cstdlib>
#include <algorithm>
#include <utility>

#include "taa/error.h"

namespace taa::io {
namespace {

// One frame placeholder found in a pattern: the characters [begin, end) and its padding.
struct Placeholder {
  std::size_t begin = 0;
  std::size_t end = 0;
  int padding = 0;  // minimum number of digits, 0 = none
};

// Parses a printf placeholder "%d" or "%0Nd" starting at `pos` (which holds '%').
bool parsePrintfPlaceholder(const std::string& pattern, std::size_t pos, Placeholder& found) {
  std::size_t cursor = pos + 1;
  int padding = 0;
  if (cursor < pattern.size() && pattern[cursor] == '0') {
    ++cursor;
    const std::size_t digitsBegin = cursor;
    while (cursor < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[cursor]))) {
      ++cursor;
    }
    // "%0d" (no width) is not a placeholder; widths beyond 2 digits are nonsense.
    if (cursor == digitsBegin || cursor - digitsBegin > 2) return false;
    padding = std::atoi(pattern.substr(digitsBegin, cursor - digitsBegin).c_str());
  }
  if (cursor >= pattern.size() || pattern[cursor] != 'd') return false;
  found = {pos, cursor + 1, padding};
  return true;
}

// Finds the next placeholder at or after `from`; false if there is none.
bool findPlaceholder(const std::string& pattern, std::size_t from, Placeholder& found) {
  for (std::size_t pos = from; pos < pattern.size(); ++pos) {
    const char c = pattern[pos];
    if (c == '#' || c == '@') {
      std::size_t end = pos;
      while (end < pattern.size() && pattern[end] == c) ++end;
      const int run = static_cast<int>(end - pos);
      // oiiotool: a lone '#' means 4 digits; '@' always counts one digit per sign.
      const int padding = (c == '#' && run == 1) ? 4 : run;
      found = {pos, end, padding};
      return true;
    }
    if (c == '%' && parsePrintfPlaceholder(pattern, pos, found)) return true;
  }
  return false;
}

std::string formatFrame(int frame, int padding) {
  // Widen before negating so that INT_MIN does not overflow.
  const long long magnitude = frame < 0 ? -static_cast<long long>(frame) : frame;
  std::string digits = std::to_string(magnitude);
  if (static_cast<int>(digits.size()) < padding) {
    digits.insert(0, std::size_t(padding) - digits.size(), '0');
  }
  return frame < 0 ? "-" + digits : digits;
}

[[noreturn]] void throwMalformedRange(const std::string& text, const std::string& why) {
  throw Error("malformed frame range \"" + text + "\": " + why);
}

// Reads an optionally signed integer at `cursor`, advancing it. False if none is there.
bool readInteger(const std::string& text, std::size_t& cursor, long long& value) {
  std::size_t pos = cursor;
  bool negative = false;
  if (pos < text.size() && (text[pos] == '-' || text[pos] == '+')) {
    negative = text[pos] == '-';
    ++pos;
  }
  const std::size_t digitsBegin = pos;
  long long magnitude = 0;
  while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
    magnitude = magnitude * 10 + (text[pos] - '0');
    if (magnitude > static_cast<long long>(INT_MAX) + 1) return false;
    ++pos;
  }
  if (pos == digitsBegin) return false;
  value = negative ? -magnitude : magnitude;
  cursor = pos;
  return true;
}

std::string trim(const std::string& text) {
  std::size_t begin = 0;
  std::size_t end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return text.substr(begin, end - begin);
}

// Guards against "1-2000000000" allocating gigabytes by accident. A million frames is over 11
// hours at 24 fps, more than any shot; at 10 million the fuzzer's overlapping 9 million frame
// list ("1-9174846,213,-10,6-222") took over 20 s to rid of duplicates under ASan.
constexpr long long kMaxFramesInRange = 1'000'000;

// Appends the frames of one item ("7", "1-48", "1-48x2", "-5--1", "10-1") to `frames`.
void appendRangeItem(const std::string& text, const std::string& item, std::vector<int>& frames) {
  std::size_t cursor = 0;
  long long first = 0;
  if (!readInteger(item, cursor, first)) {
    throwMalformedRange(text, "\"" + item + "\" does not start with a frame number");
  }
  long long last = first;
  long long step = 1;
  if (cursor < item.size() && item[cursor] == '-') {
    ++cursor;
    if (!readInteger(item, cursor, last)) {
      throwMalformedRange(text, "\"" + item + "\" has no frame number after '-'");
    }
    if (cursor < item.size() && item[cursor] == 'x') {
      ++cursor;
      if (!readInteger(item, cursor, step) || step <= 0) {
        throwMalformedRange(text, "\"" + item + "\" needs a positive step after 'x'");
      }
    }
  }
  if (cursor != item.size()) {
    throwMalformedRange(text, "unexpected \"" + item.substr(cursor) + "\" in \"" + item + "\"");
  }
  const auto inIntRange = [](long long v) { return v >= INT_MIN && v <= INT_MAX; };
  if (!inIntRange(first) || !inIntRange(last)) {
    throwMalformedRange(text, "frame number out of range in \"" + item + "\"");
  }
  const long long span = first <= last ? last - first : first - last;
  if (span / step + 1 > kMaxFramesInRange) {
    throwMalformedRange(text, "\"" + item + "\" holds more than a million frames");
  }
  // A descending range ("10-1") runs backwards, as oiiotool does.
  const long long direction = first <= last ? 1 : -1;
  for (long long offset = 0; offset <= span; offset += step) {
    frames.push_back(static_cast<int>(first + direction * offset));
  }
}

}  // namespace

bool hasFramePlaceholder(const std::string& pattern) {
  Placeholder found;
  return findPlaceholder(pattern, 0, found);
}

std::string expandFramePattern(const std::string& pattern, int frame) {
  // Every placeholder is replaced, so "shot.####/beauty.####.exr" works too.
  std::string result;
  std::size_t copiedUpTo = 0;
  Placeholder found;
  while (findPlaceholder(pattern, copiedUpTo, found)) {
    result += pattern.substr(copiedUpTo, found.begin - copiedUpTo);
    result += formatFrame(frame, found.padding);
    copiedUpTo = found.end;
  }
  result += pattern.substr(copiedUpTo);
  return result;
}

std::vector<int> parseFrameRange(const std::string& text) {
  if (trim(text).empty()) throwMalformedRange(text, "no frames given");
  std::vector<int> listed;
  std::size_t itemBegin = 0;
  while (itemBegin <= text.size()) {
    std::size_t itemEnd = text.find(',', itemBegin);
    if (itemEnd == std::string::npos) itemEnd = text.size();
    const std::string item = trim(text.substr(itemBegin, itemEnd - itemBegin));
    if (item.empty()) throwMalformedRange(text, "empty item");
    appendRangeItem(text, item, listed);
    if (listed.size() > std::size_t(kMaxFramesInRange)) {
      throwMalformedRange(text, "the list holds more than a million frames");
    }
    itemBegin = itemEnd + 1;
  }
  // Keep the listed order, dropping frames already seen: each frame's first place found by
  // sorting (value, place) pairs, not a tree of millions of nodes (the fuzzer's 8 million frame
  // list took over 20 s under ASan that way).
  std::vector<std::pair<int, std::size_t>> byFrame(listed.size());
  for (std::size_t i = 0; i < listed.size(); ++i) byFrame[i] = {listed[i], i};
  std::sort(byFrame.begin(), byFrame.end());
  std::vector<char> first(listed.size(), 0);
  for (std::size_t i = 0; i < byFrame.size(); ++i) {
    if (i == 0 || byFrame[i].first != byFrame[i - 1].first) first[byFrame[i].second] = 1;
  }
  std::vector<int> frames;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    if (first[i]) frames.push_back(listed[i]);
  }
  return frames;
}

}  // namespace taa::io
