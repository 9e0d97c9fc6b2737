#include "python_doc.h"

#include <set>
#include <sstream>
#include <vector>

#include "cli/cli_options.h"

namespace taa::python {
namespace {

constexpr std::size_t kWidth = 96;

// `text` after `head`, wrapped at kWidth with continuation lines indented by 6.
std::string entry(const std::string& head, const std::string& text) {
  std::string out, line = head;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (line.size() + 1 + word.size() > kWidth) {
      out += line + "\n";
      line = "      " + word;
    } else {
      line += (line.empty() || line.back() == ' ' ? "" : " ") + word;
    }
  }
  return out + line + "\n";
}

}  // namespace

std::string keywordOf(const std::string& option) {
  if (option == "-o") return "output";
  if (option == "-d") return "pixel_type";
  std::string name = option.substr(option.find_first_not_of('-'));
  for (char& c : name) c = c == '-' ? '_' : c;
  return name;
}

std::string optionsDoc(const std::string& title, const std::vector<OptionInfo>& options) {
  std::string doc = title + "\n";
  for (const OptionInfo& o : options) {
    const std::string value = o.defaultValue.empty() ? "\"\"" : o.defaultValue;
    doc += entry("  " + keywordOf(o.name) + "=" + o.values + " (default " + value + "): ", o.help);
  }
  return doc;
}

std::string sequenceOptionsDoc() {
  // The entries of --help that start an option ("  --frames RANGE    frames to resolve, ..."),
  // their text running on over the lines indented below them; less what is no keyword (help,
  // info, listings, verbosity) and the resolve options, listed apart.
  static const std::set<std::string> skipped = {"--help", "-h",       "--info", "--list-brackets",
                                                "--list-options", "--color", "-v", "-q"};
  struct Entry {
    std::string option, value, text;
  };
  std::vector<Entry> entries;
  std::istringstream help(cli::helpText());
  for (std::string line; std::getline(help, line);) {
    if (line.rfind("  -", 0) == 0) {
      const std::string body = line.substr(2);
      const std::size_t gap = body.find("  ");
      const std::string head = body.substr(0, gap);
      std::string text = gap == std::string::npos ? "" : body.substr(gap);
      const std::size_t space = head.find(' ');
      entries.push_back({head.substr(0, space),
                         space == std::string::npos ? "" : head.substr(space + 1), text});
    } else if (!entries.empty() && line.rfind("     ", 0) == 0) {
      entries.back().text += " " + line;
    } else {
      entries.push_back({});  // a section heading or a blank line ends the entry
    }
  }
  std::string doc = "Sequence, AOV, convention, camera and output options (taatool --help):\n";
  std::set<std::string> seen;
  for (const Entry& e : entries) {
    // --jitter's job-level values (header:ATTR, sidecar) are --help's; halton|none the registry's.
    if (e.option.empty()) continue;
    const bool resolveOption = isResolveOption(e.option.substr(e.option.find_first_not_of('-')));
    const bool jobJitter = e.option == "--jitter" && (e.value == "header:ATTR" || e.value == "sidecar");
    if (e.option.back() == ',' || skipped.count(e.option) || (resolveOption && !jobJitter) ||
        !seen.insert(e.option + e.value).second) {
      continue;
    }
    const std::string head = "  " + keywordOf(e.option) + (e.value.empty() ? "=True" : "=" + e.value);
    doc += entry(head + ": ", e.text);
  }
  return doc;
}

}  // namespace taa::python
