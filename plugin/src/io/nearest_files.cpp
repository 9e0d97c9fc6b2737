#include "io/nearest_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <vector>

#include "io/sequence_pattern.h"

namespace taa::io {
namespace {

namespace fs = std::filesystem;

// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The name with every run of digits as one '#': the files of one sequence become one name.
std::string withoutNumbers(const std::string& name) {
  std::string shape;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(name[i]))) {
      if (shape.empty() || shape.back() != '#') shape += '#';
    } else {
      shape += name[i];
    }
  }
  return shape;
}

// The pattern's placeholder as the user wrote it, for "(#### = the frame number)".
std::string placeholderText(const std::string& name) {
  const std::string one = expandFramePattern(name, 1);
  std::size_t begin = 0;
  while (begin < name.size() && begin < one.size() && name[begin] == one[begin]) ++begin;
  std::size_t end = 0;
  while (end < name.size() - begin && end < one.size() - begin &&
         name[name.size() - 1 - end] == one[one.size() - 1 - end]) {
    ++end;
  }
  return name.substr(begin, name.size() - begin - end);
}

}  // namespace

std::string patternMissText(const std::string& pattern) {
  const bool sequence = hasFramePlaceholder(pattern);
  const fs::path example = fs::path(sequence ? expandFramePattern(pattern, 1) : pattern);
  const fs::path folder = example.parent_path().empty() ? fs::path(".") : example.parent_path();
  const std::string name = example.filename().string();
  std::error_code ec;
  const fs::path shown = fs::absolute(folder, ec).lexically_normal();
  if (!fs::is_directory(folder, ec)) {
    fs::path above = shown.parent_path();
    while (!above.empty() && !fs::is_directory(above, ec) && above != above.parent_path()) {
      above = above.parent_path();
    }
    return "the folder " + shown.string() + " does not exist (the nearest folder above it that "
           "does: " + above.string() + ")";
  }
  std::string text = "looked in " + shown.string() + " for ";
  text += sequence ? "names like " + name + " (" +
                         placeholderText(fs::path(pattern).filename().string()) +
                         " = the frame number)"
                   : name;

  // Files grouped by their shape without numbers, each group ranked by its nearest member.
  struct Group {
    std::size_t distance = std::string::npos;
    std::vector<std::string> names;
  };
  std::map<std::string, Group> groups;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    const std::string candidate = entry.path().filename().string();
    Group& group = groups[withoutNumbers(candidate)];
    group.distance = std::min(group.distance, editDistance(candidate, name));
    group.names.push_back(candidate);
  }
  if (groups.empty()) return text + "; the folder holds no files";
  std::vector<Group*> ranked;
  for (auto& [shape, group] : groups) {
    std::sort(group.names.begin(), group.names.end());
    ranked.push_back(&group);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Group* a, const Group* b) { return a->distance < b->distance; });
  constexpr std::size_t kShown = 4;
  text += "; nearest there: ";
  for (std::size_t i = 0; i < ranked.size() && i < kShown; ++i) {
    const std::vector<std::string>& names = ranked[i]->names;
    text += i ? ", " : "";
    text += names.size() == 1 ? names.front()
                              : names.front() + " .. " + names.back() + " (" +
                                    std::to_string(names.size()) + " files)";
  }
  if (ranked.size() > kShown) text += " and " + std::to_string(ranked.size() - kShown) + " more";
  return text;
}

}  // namespace taa::io
