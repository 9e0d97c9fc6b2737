#include "gl/shader_library.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <utility>

#include "gl/shader_expansion.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

// The directive word of a preprocessor line ("include" for `  # include "x"`), else empty;
// `rest` receives what follows the word.
std::string directive(const std::string& line, std::string* rest) {
  size_t p = line.find_first_not_of(" \t");
  if (p == std::string::npos || line[p] != '#') return {};
  p = line.find_first_not_of(" \t", p + 1);
  if (p == std::string::npos) return {};
  size_t end = p;
  while (end < line.size() && std::isalpha(static_cast<unsigned char>(line[end]))) ++end;
  *rest = line.substr(end);
  return line.substr(p, end - p);
}

// The file name of `#include "name"` (rest = ` "name" // comment`), empty if malformed.
std::string includedName(const std::string& rest) {
  static const std::regex pattern(R"re(^\s+"([^"]+)"\s*(//.*)?$)re");
  std::smatch match;
  return std::regex_match(rest, match, pattern) ? match[1].str() : std::string();
}

class IncludeExpander {
 public:
  explicit IncludeExpander(const ShaderLookup& lookup) : lookup_(lookup) {}

  std::string expandTopLevel(const std::string& name) {
    const char* text = lookup_(name);
    if (!text) throw Error("unknown shader file \"" + name + "\"");
    std::vector<std::string> lines = splitLines(text);
    size_t versionLine = lines.size();
    for (size_t i = 0; i < lines.size() && versionLine == lines.size(); ++i) {
      std::string rest;
      if (directive(lines[i], &rest) == "version") versionLine = i;
    }
    if (versionLine == lines.size()) throw Error("shader \"" + name + "\" has no #version line");
    // GLSL wants #version first, then #extension lines before any code; defines go right
    // after them. Those lines are blanked where they stand, so line numbers stay true.
    lines[versionLine].clear();
    const std::string version = splitLines(text)[versionLine];
    files_.push_back(name);
    expandLines(name, 0, lines);
    std::string header = version + "\n";
    for (const std::string& extension : extensions_) header += extension + "\n";
    return header + "#line 1 0\n" + out_;
  }

  std::vector<std::string> files() const { return files_; }

 private:
  void expandLines(const std::string& name, int index, const std::vector<std::string>& lines) {
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string where = name + ":" + std::to_string(i + 1) + ": ";
      std::string rest;
      const std::string word = directive(lines[i], &rest);
      if (word == "version" && index != 0) {
        throw Error(where + "#version is only allowed in the top-level shader");
      }
      if (word == "extension") {
        if (std::find(extensions_.begin(), extensions_.end(), lines[i]) == extensions_.end()) {
          extensions_.push_back(lines[i]);
        }
        out_ += "\n";
        continue;
      }
      if (word != "include") {
        out_ += lines[i] + "\n";
        continue;
      }
      const std::string included = includedName(rest);
      if (included.empty()) throw Error(where + "malformed #include (expected #include \"file\")");
      if (isIncluded(included)) {
        out_ += "// " + lines[i] + " (already included)\n";
        continue;
      }
      const char* text = lookup_(included);
      if (!text) throw Error(where + "#include of unknown shader file \"" + included + "\"");
      const int includedIndex = static_cast<int>(files_.size());
      files_.push_back(included);
      out_ += "#line 1 " + std::to_string(includedIndex) + "\n";
      expandLines(included, includedIndex, splitLines(text));
      out_ += "#line " + std::to_string(i + 2) + " " + std::to_string(index) + "\n";
    }
  }

  bool isIncluded(const std::string& name) const {
    for (const std::string& file : files_) {
      if (file == name) return true;
    }
    return false;
  }

  const ShaderLookup& lookup_;
  std::vector<std::string> files_;
  std::vector<std::string> extensions_;  // hoisted to just after #version
  std::string out_;
};

}  // namespace

std::string expandShaderIncludes(const std::string& name, const ShaderLookup& lookup,
                                 std::vector<std::string>* fileNames) {
  IncludeExpander expander(lookup);
  std::string source = expander.expandTopLevel(name);
  if (fileNames) *fileNames = expander.files();
  return source;
}

std::string expandedShaderSource(const std::string& name, std::vector<std::string>* fileNames) {
  const ShaderLookup embedded = [](const std::string& file) -> const char* {
    for (const EmbeddedShader& shader : embeddedShaders()) {
      if (file == shader.name) return shader.source;
    }
    return nullptr;
  };
  if (!embedded(name)) throw Error("unknown embedded shader \"" + name + "\"");
  return expandShaderIncludes(name, embedded, fileNames);
}

std::string insertAfterFirstLine(const std::string& source, const std::vector<std::string>& lines) {
  if (lines.empty()) return source;
  std::string inserted;
  for (const std::string& line : lines) inserted += line + "\n";
  size_t end = source.find('\n');
  if (end == std::string::npos) return source + "\n" + inserted;
  // After the #extension lines that follow #version too: they must precede any code.
  std::string rest;
  for (size_t next = source.find('\n', end + 1); next != std::string::npos;
       next = source.find('\n', end + 1)) {
    if (directive(source.substr(end + 1, next - end - 1), &rest) != "extension") break;
    end = next;
  }
  return source.substr(0, end + 1) + inserted + source.substr(end + 1);
}

std::string annotateShaderLog(const std::string& log, const std::string& source,
                              const std::vector<std::string>& fileNames) {
  // Replay the #line directives to know which file line each source line came from.
  std::map<std::pair<int, int>, std::string> lineText;
  int line = 1, file = 0;
  static const std::regex lineDirective(R"(^\s*#\s*line\s+(\d+)(\s+(\d+))?\s*$)");
  for (const std::string& text : splitLines(source)) {
    std::smatch match;
    if (std::regex_match(text, match, lineDirective)) {
      line = std::stoi(match[1].str());
      if (match[3].matched) file = std::stoi(match[3].str());
      continue;
    }
    lineText[{file, line++}] = text;
  }

  std::string annotated = log;
  if (!annotated.empty() && annotated.back() != '\n') annotated += '\n';
  annotated += "source strings:";
  for (size_t i = 0; i < fileNames.size(); ++i) {
    annotated += (i ? ", " : " ") + std::to_string(i) + " = " + fileNames[i];
  }
  annotated += "\n";

  // Locations as Mesa ("0:12(5):"), NVIDIA ("0(12) :") and others ("ERROR: 0:12:") write them.
  static const std::regex location(R"((?:^|\s)(\d+)(?::(\d+)\(\d+\)|\((\d+)\)\s*:|:(\d+):))");
  std::set<std::pair<int, int>> seen;
  for (const std::string& logLine : splitLines(log)) {
    std::smatch match;
    if (!std::regex_search(logLine, match, location)) continue;
    const int fileIndex = std::stoi(match[1].str());
    const std::string number = match[2].matched ? match[2].str()
                               : match[3].matched ? match[3].str()
                                                  : match[4].str();
    const std::pair<int, int> key{fileIndex, std::stoi(number)};
    if (!seen.insert(key).second || seen.size() > 8) continue;
    auto found = lineText.find(key);
    const std::string fileName = fileIndex >= 0 && fileIndex < static_cast<int>(fileNames.size())
                                     ? fileNames[fileIndex]
                                     : "source string " + std::to_string(fileIndex);
    annotated += fileName + ":" + number + ": " +
                 (found != lineText.end() ? found->second : std::string("(line not found)")) +
                 "\n";
  }
  while (!annotated.empty() && annotated.back() == '\n') annotated.pop_back();
  return annotated;
}

}  // namespace taa::gl
