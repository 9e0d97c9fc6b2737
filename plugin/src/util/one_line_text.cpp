#include "util/one_line_text.h"

#include <cstdio>

namespace taa {

std::string oneLineText(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {  // bytes of UTF-8 stay as they are
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", unsigned(byte));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace taa
