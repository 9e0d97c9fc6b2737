// The Python module's docstrings, made from the tables the parsers use (the option registry,
// the C ABI node's parameters, taatool's --help), so a keyword in them is one the code takes.
#pragma once

#include <string>
#include <vector>

#include "resolve/option_registry.h"

namespace taa::python {

// A Python keyword for a taatool option name: "--jitter-offset" or "jitter-offset" ->
// "jitter_offset"; "-o" -> "output", "-d" -> "pixel_type".
std::string keywordOf(const std::string& option);

// `title`, then one entry per option: "  name=values (default D): help", wrapped.
std::string optionsDoc(const std::string& title, const std::vector<OptionInfo>& options);

// taatool's options that are not resolve options (sequences, AOVs, conventions, camera, output,
// GL), one entry each with the first line of their --help text.
std::string sequenceOptionsDoc();

}  // namespace taa::python
