#include "farm/sbatch_directives.h"

#include <algorithm>
#include <cctype>

#include "farm/farm_errors.h"
#include "util/one_line_text.h"

namespace taa::farm {
namespace {

bool isOptionName(const std::string& name, bool longOption) {
  const std::size_t dashes = longOption ? 2 : 1;
  if (name.size() <= dashes || name.compare(0, dashes, std::string(dashes, '-')) != 0) {
    return false;
  }
  if (!std::isalpha(static_cast<unsigned char>(name[dashes]))) return false;
  if (!longOption) return name.size() == 2;
  return std::all_of(name.begin() + long(dashes), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '-' || c == '_';
  });
}

bool startsWithFolded(const std::string& text, std::size_t at, const std::string& word) {
  if (text.size() - at < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[at + i])) != word[i]) return false;
  }
  return true;
}

// `value` double-quoted for sbatch's parser: '\\' and '"' escaped, and the words sbatch blanks
// broken by an escape of their second letter (which the parser reads as the letter itself).
std::string quoted(const std::string& value, const std::string& what) {
  if (value.find_first_of(std::string("\r\n\0", 3)) != std::string::npos) {
    throw UsageError(what + " holds a line break, which an #SBATCH line cannot carry: \"" +
                     oneLineText(value) + "\"");
  }
  std::string out = "\"";
  for (std::size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    if (c == '\\' || c == '"') out += '\\';
    out += c;
    if (startsWithFolded(value, i, "hetjob") || startsWithFolded(value, i, "packjob")) {
      out += '\\';  // before the word's second letter
    }
  }
  return out + "\"";
}

}  // namespace

std::string sbatchLine(const std::string& name, const std::string& value,
                       const std::string& what) {
  if (!isOptionName(name, true)) {
    throw UsageError(what + ": \"" + oneLineText(name) + "\" is not an sbatch option name");
  }
  return "#SBATCH " + name + "=" + quoted(value, what) + "\n";
}

std::string sbatchLineOf(const std::string& optionText) {
  const std::string what = "--sbatch-arg \"" + oneLineText(optionText) + "\"";
  const std::string expected =
      ": expected one sbatch option, --name=VALUE, --flag or -x VALUE (e.g. --qos=high)";
  if (optionText.compare(0, 2, "--") == 0) {
    const std::size_t equals = optionText.find('=');
    const std::string name = optionText.substr(0, equals);
    if (!isOptionName(name, true)) throw UsageError(what + expected);
    if (equals == std::string::npos) return "#SBATCH " + name + "\n";
    return sbatchLine(name, optionText.substr(equals + 1), what);
  }
  const std::string name = optionText.substr(0, 2);
  if (!isOptionName(name, false)) throw UsageError(what + expected);
  std::size_t valueStart = 2;
  while (valueStart < optionText.size() && optionText[valueStart] == ' ') ++valueStart;
  if (valueStart == optionText.size()) return "#SBATCH " + name + "\n";
  return "#SBATCH " + name + " " + quoted(optionText.substr(valueStart), what) + "\n";
}

}  // namespace taa::farm
