// The OpenColorIO tonemap bracket: two processors (input -> working space, working space ->
// output) turned into GLSL functions for the resolve program (DESIGN.md section 5).
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <string>
#include <vector>

#include "taa/options.h"

namespace taa::color {

namespace OCIO = OCIO_NAMESPACE;

// GLSL names of the two functions, each `vec4 name(in vec4 inPixel)`.
inline constexpr const char* kToWorkingFunction = "taaToWorking";
inline constexpr const char* kFromWorkingFunction = "taaFromWorking";

// Where the config came from, for messages and --list-brackets.
struct LoadedConfig {
  OCIO::ConstConfigRcPtr config;
  std::string description;  // the path, "$OCIO (path)" or "taa's shipped config"
};

// The ColorOptions::ocioConfig value that means "the config $OCIO names".
inline constexpr const char* kOcioEnvironmentConfig = "$OCIO";

// Loads the config `ColorOptions::ocioConfig` names, the same rule in every face: empty is the
// config $OCIO names when it is set, else taa's shipped config; kOcioEnvironmentConfig the one
// $OCIO names; anything else a file. Throws taa::Error naming the file for an unreadable or
// invalid config, and for "$OCIO" when $OCIO is not set.
LoadedConfig loadConfig(const std::string& path);

// The bracket names a config offers: "none", taa's own brackets (taa_reinhard, taa_log2: the
// shipped config's working spaces, pure maths that every config gets), then the config's
// colorspaces (not data spaces) and named transforms.
std::vector<std::string> listBrackets(const OCIO::ConstConfigRcPtr& config);

// The output's colorspace as the config names it ("ACEScg"; a role resolved to its colorspace)
// and the config's description ("$OCIO (/studio/config.ocio)"), for the output header.
// Throws as OcioBracket does.
struct OutputColorspace {
  std::string colorspace, config;
};
OutputColorspace outputColorspace(const ColorOptions& options);

// The bracket: taa's own brackets (taa_reinhard, taa_log2) work in any config: the input is
// converted to the config's scene_linear role, the bracket's maths applied, and back to the
// output colorspace (a config without the role, given no colorspace names, takes the input as
// linear). Any other name is the config's colorspace or named transform, as before; "none"
// skips the working space.
class OcioBracket {
 public:
  // Builds both processors and their GPU shader descriptions. Throws taa::Error naming the
  // config and the name for an unknown colorspace, role or bracket, and for a bracket whose
  // round trip (forward then inverse) does not give its input back on the CPU.
  explicit OcioBracket(const ColorOptions& options);

  const OCIO::GpuShaderDescRcPtr& toWorking() const { return toWorking_; }
  const OCIO::GpuShaderDescRcPtr& fromWorking() const { return fromWorking_; }
  // GLSL defining both functions and their resources, for the resolve fragment shader.
  std::string glsl() const;
  // Changes when either processor changes: the resolve program is rebuilt only then.
  std::string cacheId() const;

  // The working-space image of half float's range, toWorking(-65504) .. toWorking(65504) of grey,
  // where the inverse gives finite values: the resolve keeps reconstruction overshoot within
  // reach of it (glsl/finite_range.glsl). No limit (-inf, inf) for a bracket that is not finite
  // and increasing there.
  struct Range {
    float lo, hi;
  };
  Range workingRange() const;

  const OCIO::ConstCPUProcessorRcPtr& toWorkingCpu() const { return toWorkingCpu_; }
  const OCIO::ConstCPUProcessorRcPtr& fromWorkingCpu() const { return fromWorkingCpu_; }

 private:
  std::string cacheId_;
  OCIO::GpuShaderDescRcPtr toWorking_, fromWorking_;
  OCIO::ConstCPUProcessorRcPtr toWorkingCpu_, fromWorkingCpu_;
};

}  // namespace taa::color
