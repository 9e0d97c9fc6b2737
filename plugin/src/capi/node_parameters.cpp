#include "capi/node_parameters.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

#include "capi/status_error.h"
#include "resolve/option_registry.h"
#include "taa/error.h"

namespace taa::capi {
namespace {

enum class Type { Int, Float, String };

const char* typeName(Type type) {
  switch (type) {
    case Type::Int: return "int";
    case Type::Float: return "float";
    case Type::String: return "string";
  }
  return "?";
}

// A parameter of the node's own (the input conventions taatool applies to files), typed.
struct InputParameter {
  Type type;
  std::function<void(NodeParameters&, int)> setInt;
  std::function<void(NodeParameters&, float)> setFloat;
  std::function<void(NodeParameters&, const std::string&)> setString;
};

[[noreturn]] void outOfRange(const std::string& name, const std::string& expected,
                             const std::string& got) {
  throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                    "parameter \"" + name + "\" expects " + expected + ", got " + got);
}

// Returns which of `choices` `value` is (its index).
std::size_t choice(const char* name, const std::string& value,
                   const std::vector<std::string>& choices) {
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (value == choices[i]) return i;
  }
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : "|") + c;
  outOfRange(name, list, "\"" + value + "\"");
}

InputParameter intParameter(std::function<void(NodeParameters&, int)> set) {
  return {Type::Int, std::move(set), {}, {}};
}
InputParameter floatParameter(std::function<void(NodeParameters&, float)> set) {
  return {Type::Float, {}, std::move(set), {}};
}
InputParameter stringParameter(std::function<void(NodeParameters&, const std::string&)> set) {
  return {Type::String, {}, {}, std::move(set)};
}

const std::map<std::string, InputParameter>& inputParameters() {
  static const std::map<std::string, InputParameter> table = {
      {"motion-y", stringParameter([](NodeParameters& p, const std::string& v) {
         p.motion.yUp = choice("motion-y", v, {"down", "up"}) == 1;
       })},
      {"motion-to", stringParameter([](NodeParameters& p, const std::string& v) {
         p.motion.toPrevious = choice("motion-to", v, {"previous", "next"}) == 0;
       })},
      {"motion-scale", floatParameter([](NodeParameters& p, float v) {
         if (!std::isfinite(v)) outOfRange("motion-scale", "a finite number", std::to_string(v));
         p.motion.scale = v;
       })},
      {"depth-nohit", floatParameter([](NodeParameters& p, float v) {
         if (std::isnan(v)) outOfRange("depth-nohit", "a number", "NaN");
         p.depth.noHitAbove = v;
       })},
      {"reset-on-gap", intParameter([](NodeParameters& p, int v) {
         if (v != 0 && v != 1) outOfRange("reset-on-gap", "0 or 1", std::to_string(v));
         p.resetOnGap = v == 1;
       })},
      {"output-type", stringParameter([](NodeParameters& p, const std::string& v) {
         p.outputType = choice("output-type", v, {"float", "half"}) == 1 ? SampleType::Half
                                                                          : SampleType::Float;
       })},
      {"ndc", stringParameter([](NodeParameters& p, const std::string& v) {
         p.ndc = choice("ndc", v, {"zero-one-y-down", "minus-one-one-y-up"}) == 0
                     ? NdcConvention::ZeroOneYDown
                     : NdcConvention::MinusOneOneYUp;
       })},
  };
  return table;
}

// taatool's spelling: Python keywords and C identifiers may use '_' for '-'.
std::string canonicalName(const std::string& name) {
  std::string canonical = name;
  for (char& c : canonical) c = c == '_' ? '-' : c;
  return canonical;
}

[[noreturn]] void unknown(const std::string& name) {
  std::string names;
  for (const auto& entry : inputParameters()) names += (names.empty() ? "" : ", ") + entry.first;
  for (const OptionInfo& option : resolveOptionList()) names += ", " + option.name;
  throw StatusError(TAA_ERROR_UNKNOWN_PARAMETER,
                    "unknown parameter \"" + name + "\" (parameters: " + names + ")");
}

// Finds the node's own parameter `name` of type `wanted`; nullptr when `name` is a resolve
// option instead. Throws for unknown names and wrong types.
const InputParameter* findInput(const std::string& given, const std::string& name, Type wanted) {
  const auto& table = inputParameters();
  const auto it = table.find(name);
  if (it == table.end()) {
    if (!isResolveOption(name)) unknown(given);
    return nullptr;
  }
  if (it->second.type != wanted) {
    throw StatusError(TAA_ERROR_WRONG_TYPE, "parameter \"" + given + "\" is a " +
                                                typeName(it->second.type) + ", not a " +
                                                typeName(wanted));
  }
  return &it->second;
}

// Resolve options take text (as on taatool's command line); numbers are written exactly.
void setResolve(NodeParameters& parameters, const std::string& name, const std::string& text) {
  ResolveOptions options = parameters.resolve;
  try {
    setResolveOption(options, name, text);
  } catch (const Error& e) {
    throw StatusError(TAA_ERROR_INVALID_ARGUMENT, e.what());
  }
  parameters.resolve = options;
}

}  // namespace

void setIntParameter(NodeParameters& parameters, const std::string& given, int value) {
  const std::string name = canonicalName(given);
  if (auto input = findInput(given, name, Type::Int)) return input->setInt(parameters, value);
  setResolve(parameters, name, std::to_string(value));
}

void setFloatParameter(NodeParameters& parameters, const std::string& given, float value) {
  const std::string name = canonicalName(given);
  if (auto input = findInput(given, name, Type::Float)) return input->setFloat(parameters, value);
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(value));  // round-trips every float
  setResolve(parameters, name, text);
}

void setStringParameter(NodeParameters& parameters, const std::string& given,
                        const std::string& value) {
  const std::string name = canonicalName(given);
  if (auto input = findInput(given, name, Type::String)) {
    return input->setString(parameters, value);
  }
  setResolve(parameters, name, value);
}

}  // namespace taa::capi
