// Internal to gl/: the text processing behind expandedShaderSource and Program's error
// messages, with the file lookup as a parameter so tests can feed their own files.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace taa::gl {

// Returns the text of a shader file, or nullptr if there is no such file.
using ShaderLookup = std::function<const char*(const std::string& name)>;

// Expands `#include "file"` lines of `name` (recursively, each file once) and moves its
// #version line to the very top, then every #extension line of any file (once each), followed
// by `#line` directives that keep the driver's line
// numbers true to the files. fileNames (if given) receives the source-string-number legend:
// fileNames[0] is `name`. Throws taa::Error for an unknown file, a malformed #include, a
// missing top-level #version or a #version inside an included file.
std::string expandShaderIncludes(const std::string& name, const ShaderLookup& lookup,
                                 std::vector<std::string>* fileNames);

// Inserts `lines` (e.g. "#define X 1") right after the first line (the #version line) and the
// #extension lines that follow it.
std::string insertAfterFirstLine(const std::string& source, const std::vector<std::string>& lines);

// Makes a driver's info log readable: appends the legend of source-string numbers and, for
// each distinct location the log mentions, the file name, line number and that line's text.
std::string annotateShaderLog(const std::string& log, const std::string& source,
                              const std::vector<std::string>& fileNames);

}  // namespace taa::gl
