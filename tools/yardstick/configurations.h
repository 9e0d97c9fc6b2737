// Named taatool configurations: sets of flags kept in configurations.txt, or given ad hoc.
#pragma once

#include <string>
#include <vector>

namespace taa::yardstick {

struct Configuration {
  std::string name;
  std::vector<std::string> flags;  // taatool arguments, one per element
  std::string flagsText;           // as written, for the table's legend
};

// Splits a flag string at whitespace; single or double quotes group (and are removed).
std::vector<std::string> splitFlags(const std::string& text);

// "name flags..." per line; '#' starts a comment, blank lines are skipped. Throws taa::Error
// on a duplicate or malformed name.
std::vector<Configuration> parseConfigurations(const std::string& text);
std::vector<Configuration> readConfigurations(const std::string& path);

// "name=flags" (the command line's --config).
Configuration parseAdHocConfiguration(const std::string& text);

}  // namespace taa::yardstick
