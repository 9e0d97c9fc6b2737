// Every resolve option by name, settable from text. The one place where faces map names to
// ResolveOptions fields: taatool's flags are "--" + name, and the C ABI, OpenFX and Python use
// the same names, so an option added here reaches every face.
#pragma once

#include <string>
#include <vector>

#include "taa/options.h"

namespace taa {

struct OptionInfo {
  std::string name;          // e.g. "rectify"
  std::string topic;         // help group: "Jitter", "Reprojection", ...
  std::string values;        // what it accepts, e.g. "clip|clamp|variance|none", "0..1"
  std::string defaultValue;  // as text, from a default-constructed ResolveOptions
  std::string help;          // one line: what it does and what it trades
};

// All options, in pipeline order.
const std::vector<OptionInfo>& resolveOptionList();

// True when `name` is a resolve option.
bool isResolveOption(const std::string& name);

// Sets option `name` from `value` ("on"/"off"/"1"/"0" for switches). Throws taa::Error naming the
// option, the value and what it accepts.
void setResolveOption(ResolveOptions& options, const std::string& name, const std::string& value);

// The current value of option `name` as text (inverse of setResolveOption).
std::string resolveOptionValue(const ResolveOptions& options, const std::string& name);

}  // namespace taa
