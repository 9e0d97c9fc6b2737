// The parameters a C ABI node has, set by name with typed values (taa.h lists them). They
// mirror taatool's flags: the resolve options plus the input conventions taatool applies to
// files, which the node applies to host buffers.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "io/aov_layout.h"
#include "io/camera_sidecar.h"
#include "io/channel_kinds.h"
#include "resolve/option_registry.h"
#include "resolve/camera.h"
#include "taa/options.h"
#include "util/image.h"

namespace taa::capi {

inline ResolveOptions historyResolveOptions() {
  ResolveOptions options;
  options.mode = ResolveMode::History;
  return options;
}

struct NodeParameters {
  // History mode, unlike taatool: a node's contract is push a frame, read its result (window
  // mode needs taa_node_resolve_frame once the frame's window is pushed; "mode" chooses).
  ResolveOptions resolve = historyResolveOptions();
  io::MotionConvention motion;
  io::DepthConvention depth;
  bool resetOnGap = true;  // restart history when frame != previous frame + 1 (as taatool)
  NdcConvention ndc = NdcConvention::ZeroOneYDown;  // what the frames' world_to_ndc maps to
  // The type the result is read back from GL in. Half halves the read-back and skips the
  // conversion for hosts with half output buffers; float keeps the full result for any buffer.
  SampleType outputType = SampleType::Float;
  std::string preset;  // the renderer preset whose conventions were set last ("" none)
  // The camera sidecar (taatool's --camera-sidecar): frames pushed without matrices take
  // their entry's camera, without a jitter their entry's jitter. Null: none.
  std::string cameraSidecarPath;
  std::shared_ptr<const io::CameraSidecar> cameraSidecar;
  // taatool's --aov rules for the passes' kinds ("aov": "PATTERN=kind" separated by ';').
  std::string passRulesText;
  std::vector<io::ChannelKindRule> passRules;
};

// The node's own parameters (not the registry's resolve options), in documented order: name,
// type ("int", "float", "string") in `topic`, values, default as text, help.
const std::vector<OptionInfo>& nodeInputParameterInfo();

// Names are taatool's option names ('_' may stand for '-'). Resolve options (the registry of
// resolve/option_registry.h) accept any of the three types, converted to taatool's text; the
// node's own input-convention parameters are typed. Each throws StatusError:
// TAA_ERROR_UNKNOWN_PARAMETER for a name the node does not have (the message lists the names),
// TAA_ERROR_WRONG_TYPE for a typed parameter set with another type, TAA_ERROR_INVALID_ARGUMENT
// for a value out of range. `parameters` is unchanged on error.
void setIntParameter(NodeParameters& parameters, const std::string& name, int value);
void setFloatParameter(NodeParameters& parameters, const std::string& name, float value);
void setStringParameter(NodeParameters& parameters, const std::string& name,
                        const std::string& value);

}  // namespace taa::capi
