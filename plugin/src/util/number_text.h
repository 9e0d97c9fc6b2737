// Whole-string number parsing for option values and file keys: "12" is 12, "12x" is nothing.
#pragma once

#include <optional>
#include <string>

namespace taa {

// The finite float `text` spells out entirely, or nothing.
std::optional<float> parseFloatText(const std::string& text);

// The int `text` spells out entirely, or nothing.
std::optional<int> parseIntText(const std::string& text);

}  // namespace taa
