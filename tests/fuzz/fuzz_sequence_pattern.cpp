// libFuzzer target: frame-numbered file patterns (io/sequence_pattern.h, io/sequence_scan.h):
// expansion of any pattern for any frame, and matching file names back to frames. A name the
// pattern gives for a frame must match back to that frame.
#include <fuzzer/FuzzedDataProvider.h>

#include <climits>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/sequence_pattern.h"
#include "io/sequence_scan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  const int frame = input.ConsumeIntegral<int>();
  const std::string name = input.ConsumeRandomLengthString(64);
  const std::string pattern = input.ConsumeRemainingBytesAsString();
  const bool placeholder = taa::io::hasFramePlaceholder(pattern);
  const std::string expanded = taa::io::expandFramePattern(pattern, frame);
  if (!placeholder && expanded != pattern) __builtin_trap();
  taa::io::frameOfFileName(pattern, name);
  // Round trip, where the name stands alone (no folder in the expansion, no placeholder left
  // after it): the frame found is the frame given.
  const std::filesystem::path path(expanded);
  if (placeholder && path.filename() == path && !path.empty() &&
      pattern.find('/') == std::string::npos && frame != INT_MIN) {
    const auto back = taa::io::frameOfFileName(pattern, expanded);
    if (back && taa::io::expandFramePattern(pattern, *back) != expanded) __builtin_trap();
  }
  return 0;
}
