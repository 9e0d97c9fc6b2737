#include "yardstick/configurations.h"

#include <cctype>
#include <fstream>
#include <sstream>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

bool validName(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') {
      return false;
    }
  }
  return true;
}

Configuration make(const std::string& name, const std::string& flags) {
  if (!validName(name)) {
    throw Error("bad configuration name \"" + name + "\" (letters, digits, _ - . only)");
  }
  return {name, splitFlags(flags), trim(flags)};
}

}  // namespace

std::vector<std::string> splitFlags(const std::string& text) {
  std::vector<std::string> flags;
  std::string current;
  bool inWord = false;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) {
        quote = 0;
      } else {
        current += c;
      }
    } else if (c == '"' || c == '\'') {
      quote = c;
      inWord = true;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (inWord) flags.push_back(current);
      current.clear();
      inWord = false;
    } else {
      current += c;
      inWord = true;
    }
  }
  if (quote) throw Error("unbalanced quote in flags: " + text);
  if (inWord) flags.push_back(current);
  return flags;
}

std::vector<Configuration> parseConfigurations(const std::string& text) {
  std::vector<Configuration> configurations;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const auto space = content.find_first_of(" \t");
    const std::string name = content.substr(0, space);
    const std::string flags = space == std::string::npos ? "" : content.substr(space + 1);
    for (const Configuration& known : configurations) {
      if (known.name == name) throw Error("configuration \"" + name + "\" defined twice");
    }
    configurations.push_back(make(name, flags));
  }
  return configurations;
}

std::vector<Configuration> readConfigurations(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw Error("cannot read the configurations", {path});
  std::stringstream text;
  text << file.rdbuf();
  return parseConfigurations(text.str());
}

Configuration parseAdHocConfiguration(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos) {
    throw Error("--config expects name=\"flags\", got \"" + text + "\"");
  }
  return make(trim(text.substr(0, equals)), text.substr(equals + 1));
}

}  // namespace taa::yardstick
