// libFuzzer target: the C ABI's parameter setters (taa.h) with any name, type and value, as a host
// may call them. Each call returns a status from taa.h with a message on failure; no exception
// crosses the ABI, and the node stays usable (a known-good parameter can still be set).
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "taa/taa.h"

namespace {

const std::vector<std::string> kNames = {
    "blend", "velocity-blend", "velocity_scale", "anti-flicker", "luma-weighting",
    "sample-count", "reconstruction", "anti-ringing", "jitter", "jitter-offset", "jitter-period",
    "jitter-scale", "motion-dilation", "camera-motion", "camera-agreement", "history-filter",
    "depth-tolerance", "rectify", "box-space", "neighbourhood", "variance-gamma", "thin-hold",
    "thin-hold-speed", "cut-detection", "sharpen", "bracket", "colorspace-in", "colorspace-out",
    "ocio-config", "motion-y", "motion-to", "motion-scale", "depth-nohit", "reset-on-gap",
    "output-type", "ndc", "aov"};

taa_node* sharedNode() {
  static taa_node* node = [] {
    taa_create_options options;
    taa_create_options_init(&options);
    options.defer_context = 1;  // setters need no GL context
    taa_node* created = nullptr;
    if (taa_node_create(&options, &created) != TAA_OK) __builtin_trap();
    return created;
  }();
  return node;
}

bool knownStatus(taa_status status) {
  switch (status) {
    case TAA_OK:
    case TAA_ERROR_INVALID_ARGUMENT:
    case TAA_ERROR_UNKNOWN_PARAMETER:
    case TAA_ERROR_WRONG_TYPE:
    case TAA_ERROR_GL:
    case TAA_ERROR_NO_OUTPUT:
    case TAA_ERROR_BUSY:
    case TAA_ERROR_INTERNAL:
      return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  taa_node* node = sharedNode();
  while (input.remaining_bytes() > 0) {
    std::string name =
        input.ConsumeBool()
            ? kNames[input.ConsumeIntegralInRange<std::size_t>(0, kNames.size() - 1)]
            : input.ConsumeRandomLengthString(32);
    if (input.ConsumeBool()) std::replace(name.begin(), name.end(), '-', '_');
    const char* namePointer = input.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : name.c_str();
    taa_status status = TAA_OK;
    switch (input.ConsumeIntegralInRange(0, 3)) {
      case 0: status = taa_node_set_int(node, namePointer, input.ConsumeIntegral<int>()); break;
      case 1:
        status = taa_node_set_float(node, namePointer, input.ConsumeFloatingPoint<float>());
        break;
      case 2: {
        const std::string value = input.ConsumeRandomLengthString(24);
        const bool nullValue = input.ConsumeIntegralInRange(0, 15) == 0;
        status = taa_node_set_string(node, namePointer, nullValue ? nullptr : value.c_str());
        break;
      }
      default: status = taa_node_reset_history(node); break;
    }
    if (!knownStatus(status)) __builtin_trap();
    const char* message = taa_node_last_error(node);
    if (!message || (status != TAA_OK && std::strlen(message) == 0)) __builtin_trap();
  }
  if (taa_node_set_float(node, "blend", 0.1f) != TAA_OK) __builtin_trap();
  return 0;
}
