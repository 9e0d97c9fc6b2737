// libFuzzer target: the camera sidecar JSON (io/camera_sidecar.h) as taatool reads it, from a
// file, then every entry's camera and jitter looked up. Malformed files are a taa::Error naming
// the file; nothing else may happen, and a jitter that loads is finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scratch_file.h"
#include "io/camera_sidecar.h"
#include "taa/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const FuzzScratchFile scratch("sidecar.json");
  const std::string& path = scratch.path();
  scratch.write(data, size);
  try {
    const taa::io::CameraSidecar sidecar = taa::io::CameraSidecar::load(path);
    for (int frame : {0, 1, 1001, -1}) {
      try {
        const glm::vec2 jitter = sidecar.jitter(frame);
        if (!std::isfinite(jitter.x) || !std::isfinite(jitter.y)) __builtin_trap();
      } catch (const taa::Error&) {
      }
      try {
        sidecar.camera(frame);
      } catch (const taa::Error&) {
      }
    }
  } catch (const taa::Error& e) {
    if (e.context().file != path) __builtin_trap();
  }
  return 0;
}
