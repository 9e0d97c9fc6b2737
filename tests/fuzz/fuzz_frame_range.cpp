// libFuzzer target: --frames and --reset-frames text (io/sequence_pattern.h parseFrameRange).
// Any text gives frames or a taa::Error quoting it; nothing else may happen.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/sequence_pattern.h"
#include "taa/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const std::vector<int> frames = taa::io::parseFrameRange(text);
    if (frames.empty()) __builtin_trap();  // an empty list is an error, never a result
  } catch (const taa::Error& e) {
    if (e.description().find("malformed frame range") == std::string::npos) __builtin_trap();
  }
  return 0;
}
