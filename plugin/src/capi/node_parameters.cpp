#include "capi/node_parameters.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "capi/status_error.h"
#include "io/renderer_presets.h"
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

// A parameter of the node's own (the input conventions taatool applies to files), typed, with
// what it accepts and its help (Python's docstring is made from these and the registry).
struct InputParameter {
  Type type;
  std::string values, help;
  std::function<std::string(const NodeParameters&)> get;
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

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

using Getter = std::function<std::string(const NodeParameters&)>;

InputParameter intParameter(std::string values, std::string help, Getter get,
                            std::function<void(NodeParameters&, int)> set) {
  return {Type::Int, std::move(values), std::move(help), std::move(get), std::move(set), {}, {}};
}
InputParameter floatParameter(std::string values, std::string help, Getter get,
                              std::function<void(NodeParameters&, float)> set) {
  return {Type::Float, std::move(values), std::move(help), std::move(get), {}, std::move(set), {}};
}
InputParameter stringParameter(std::string values, std::string help, Getter get,
                               std::function<void(NodeParameters&, const std::string&)> set) {
  return {Type::String, std::move(values), std::move(help), std::move(get), {}, {}, std::move(set)};
}

// A choice of names for an enum field: its getter and its setter, values "a|b|c".
template <typename Enum>
InputParameter enumParameter(const char* name, std::vector<std::pair<std::string, Enum>> names,
                             std::string help, std::function<Enum&(NodeParameters&)> field) {
  std::string values;
  for (const auto& entry : names) values += (values.empty() ? "" : "|") + entry.first;
  auto get = [names, field](const NodeParameters& p) {
    NodeParameters copy = p;
    const Enum value = field(copy);
    for (const auto& entry : names) {
      if (entry.second == value) return entry.first;
    }
    return std::string("?");
  };
  auto set = [name, names, field](NodeParameters& p, const std::string& v) {
    std::vector<std::string> choices;
    for (const auto& entry : names) choices.push_back(entry.first);
    field(p) = names[choice(name, v, choices)].second;
  };
  return stringParameter(values, std::move(help), get, set);
}

// Parameters in the order they are documented.
const std::vector<std::pair<std::string, InputParameter>>& inputParameterList() {
  using io::DepthKind;
  using io::MotionEncoding;
  using io::MotionUnits;
  static const std::vector<std::pair<std::string, InputParameter>> list = {
      {"preset",
       stringParameter(io::presetNames(),
                       "a renderer's motion and depth conventions (taatool --preset; the host "
                       "picks the channels), set before the fields it should not override",
                       [](const NodeParameters& p) { return p.preset; },
                       [](NodeParameters& p, const std::string& v) {
                         io::AovLayout layout;  // "": taa's own conventions again
                         try {
                           if (!v.empty()) layout = io::presetLayout(v, "");
                         } catch (const Error& e) {
                           throw StatusError(TAA_ERROR_INVALID_ARGUMENT, e.what());
                         }
                         p.motion = layout.motionConvention;
                         p.depth = layout.depthConvention;
                         p.preset = v;
                       })},
      {"motion-y",
       stringParameter("down|up", "y axis direction of the motion vectors",
                       [](const NodeParameters& p) { return p.motion.yUp ? "up" : "down"; },
                       [](NodeParameters& p, const std::string& v) {
                         p.motion.yUp = choice("motion-y", v, {"down", "up"}) == 1;
                       })},
      {"motion-to",
       stringParameter(
           "previous|next", "where the vectors point (next: forward in time)",
           [](const NodeParameters& p) { return p.motion.toPrevious ? "previous" : "next"; },
           [](NodeParameters& p, const std::string& v) {
             p.motion.toPrevious = choice("motion-to", v, {"previous", "next"}) == 0;
           })},
      {"motion-scale",
       floatParameter("number", "multiplies the vectors",
                      [](const NodeParameters& p) { return numberText(p.motion.scale); },
                      [](NodeParameters& p, float v) {
                        if (!std::isfinite(v)) {
                          outOfRange("motion-scale", "a finite number", std::to_string(v));
                        }
                        p.motion.scale = v;
                      })},
      {"motion-units",
       enumParameter<MotionUnits>(
           "motion-units",
           {{"pixels", MotionUnits::Pixels}, {"ndc", MotionUnits::Ndc}, {"uv", MotionUnits::Uv}},
           "units of the vectors: pixels, ndc ([-1, 1] across the image), uv ([0, 1])",
           [](NodeParameters& p) -> MotionUnits& { return p.motion.units; })},
      {"motion-encoding",
       enumParameter<MotionEncoding>(
           "motion-encoding",
           {{"signed", MotionEncoding::Signed}, {"centred", MotionEncoding::Centred}},
           "centred: 0.5 = no motion, value = 0.5 + motion / (2 motion-max)",
           [](NodeParameters& p) -> MotionEncoding& { return p.motion.encoding; })},
      {"motion-max",
       floatParameter("> 0", "centred: the motion a value of 1 stands for",
                      [](const NodeParameters& p) { return numberText(p.motion.centredMax); },
                      [](NodeParameters& p, float v) {
                        if (!(v > 0.0f) || !std::isfinite(v)) {
                          outOfRange("motion-max", "a positive number", std::to_string(v));
                        }
                        p.motion.centredMax = v;
                      })},
      {"depth-kind",
       enumParameter<DepthKind>(
           "depth-kind",
           {{"planar", DepthKind::Planar},
            {"radial", DepthKind::Radial},
            {"ndc", DepthKind::Ndc},
            {"reversed-z", DepthKind::ReversedZ},
            {"inverse", DepthKind::Inverse}},
           "what depth measures; radial needs the frame's camera or depth-fov",
           [](NodeParameters& p) -> DepthKind& { return p.depth.kind; })},
      {"depth-near",
       floatParameter("> 0", "near plane of ndc and reversed-z depth",
                      [](const NodeParameters& p) { return numberText(p.depth.nearPlane); },
                      [](NodeParameters& p, float v) {
                        if (!(v > 0.0f)) outOfRange("depth-near", "a positive distance",
                                                    std::to_string(v));
                        p.depth.nearPlane = v;
                      })},
      {"depth-far",
       floatParameter("> 0 or inf", "far plane of ndc and reversed-z depth",
                      [](const NodeParameters& p) { return numberText(p.depth.farPlane); },
                      [](NodeParameters& p, float v) {
                        if (!(v > 0.0f)) outOfRange("depth-far", "a positive distance",
                                                    std::to_string(v));
                        p.depth.farPlane = v;
                      })},
      {"depth-fov",
       floatParameter("degrees in (0, 180)",
                      "radial depth without a camera: horizontal field of view of a centred "
                      "pinhole",
                      [](const NodeParameters& p) {
                        return p.depth.horizontalFovDegrees
                                   ? numberText(*p.depth.horizontalFovDegrees)
                                   : std::string();
                      },
                      [](NodeParameters& p, float v) {
                        if (!(v > 0.0f && v < 180.0f)) {
                          outOfRange("depth-fov", "degrees in (0, 180)", std::to_string(v));
                        }
                        p.depth.horizontalFovDegrees = v;
                      })},
      {"depth-nohit",
       floatParameter("number", "planar depth at or above this means nothing was hit",
                      [](const NodeParameters& p) { return numberText(p.depth.noHitAbove); },
                      [](NodeParameters& p, float v) {
                        if (std::isnan(v)) outOfRange("depth-nohit", "a number", "NaN");
                        p.depth.noHitAbove = v;
                      })},
      {"ndc",
       enumParameter<NdcConvention>(
           "ndc",
           {{"zero-one-y-down", NdcConvention::ZeroOneYDown},
            {"minus-one-one-y-up", NdcConvention::MinusOneOneYUp}},
           "what the frames' world_to_ndc maps to",
           [](NodeParameters& p) -> NdcConvention& { return p.ndc; })},
      {"camera-sidecar",
       stringParameter("path", "taatool's camera sidecar (JSON): each pushed frame without "
                               "matrices takes its entry's camera, without a jitter its entry's "
                               "jitter",
                       [](const NodeParameters& p) { return p.cameraSidecarPath; },
                       [](NodeParameters& p, const std::string& v) {
                         std::shared_ptr<const io::CameraSidecar> loaded;
                         if (!v.empty()) {
                           try {
                             loaded = std::make_shared<io::CameraSidecar>(
                                 io::CameraSidecar::load(v));
                           } catch (const Error& e) {
                             throw StatusError(TAA_ERROR_INVALID_ARGUMENT, e.what());
                           }
                         }
                         p.cameraSidecar = std::move(loaded);
                         p.cameraSidecarPath = v;
                       })},
      {"aov",
       stringParameter("rules", "the passes' kinds (taa_node_push_frame_passes): taatool's --aov "
                                "rules, PATTERN=kind separated by ';', first match wins; \"\" "
                                "for the kinds the channel names give",
                       [](const NodeParameters& p) { return p.passRulesText; },
                       [](NodeParameters& p, const std::string& v) {
                         std::vector<io::ChannelKindRule> rules;
                         std::istringstream text(v);
                         for (std::string rule; std::getline(text, rule, ';');) {
                           if (rule.empty()) continue;
                           try {
                             rules.push_back(io::parseChannelKindRule(rule));
                           } catch (const Error& e) {
                             throw StatusError(TAA_ERROR_INVALID_ARGUMENT,
                                               std::string("parameter \"aov\": ") + e.what());
                           }
                         }
                         p.passRules = std::move(rules);
                         p.passRulesText = v;
                       })},
      {"reset-on-gap",
       intParameter("0|1", "history mode: restart history when a frame is not the last + 1",
                    [](const NodeParameters& p) { return std::string(p.resetOnGap ? "1" : "0"); },
                    [](NodeParameters& p, int v) {
                      if (v != 0 && v != 1) outOfRange("reset-on-gap", "0 or 1", std::to_string(v));
                      p.resetOnGap = v == 1;
                    })},
      {"output-type",
       enumParameter<SampleType>(
           "output-type", {{"float", SampleType::Float}, {"half", SampleType::Half}},
           "the type the result is read back in",
           [](NodeParameters& p) -> SampleType& { return p.outputType; })},
  };
  return list;
}

const std::map<std::string, InputParameter>& inputParameters() {
  static const std::map<std::string, InputParameter> table = [] {
    std::map<std::string, InputParameter> byName;
    for (const auto& [name, parameter] : inputParameterList()) byName.emplace(name, parameter);
    return byName;
  }();
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
  for (const auto& entry : inputParameterList()) {
    names += (names.empty() ? "" : ", ") + entry.first;
  }
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

namespace taa::capi {

const std::vector<OptionInfo>& nodeInputParameterInfo() {
  static const std::vector<OptionInfo> list = [] {
    std::vector<OptionInfo> infos;
    const NodeParameters defaults;
    for (const auto& [name, parameter] : inputParameterList()) {
      infos.push_back({name, typeName(parameter.type), parameter.values, parameter.get(defaults),
                       parameter.help});
    }
    return infos;
  }();
  return list;
}

}  // namespace taa::capi
