#include "color/ocio_bracket.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "color/shipped_config.h"
#include "taa/error.h"

namespace taa::color {
namespace {

// Values the round-trip check sends through forward then inverse: black, shadows, mid grey,
// white, highlights up to half float's maximum.
constexpr float kRoundTripValues[] = {0.0f, 0.001f, 0.18f, 1.0f, 10.0f, 100.0f, 1000.0f, 65504.0f};
// Gross non-invertibility (clamps, non-monotonic curves) only; the shipped brackets meet 1e-3
// on the GPU (tests/gl/ocio_bracket_gl_test.cpp).
constexpr float kRoundTripTolerance = 1e-2f;

std::string configError(const std::string& what, const LoadedConfig& loaded) {
  return what + " in the OCIO config " + loaded.description;
}

// "a, b, c" for at most kMaxListed names, then how many more there are.
std::string nameList(const std::vector<std::string>& names) {
  constexpr std::size_t kMaxListed = 40;
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < kMaxListed; ++i) {
    text += (i ? ", " : "") + names[i];
  }
  if (names.size() > kMaxListed) {
    text += " and " + std::to_string(names.size() - kMaxListed) + " more";
  }
  return text;
}

std::vector<std::string> colorSpaceNames(const OCIO::ConstConfigRcPtr& config) {
  std::vector<std::string> names;
  for (int i = 0; i < config->getNumColorSpaces(); ++i) {
    names.push_back(config->getColorSpaceNameByIndex(i));
  }
  return names;
}

// The colorspace a name or role refers to, or throws naming both and what the config offers
// for that purpose (brackets for the bracket, colorspaces otherwise): a studio config
// rarely has the shipped config's names.
std::string requireColorSpace(const LoadedConfig& loaded, const std::string& name,
                              const char* purpose) {
  OCIO::ConstColorSpaceRcPtr space = loaded.config->getColorSpace(name.c_str());
  if (!space) {
    const bool bracket = std::string(purpose) == "bracket";
    const std::vector<std::string> offered =
        bracket ? listBrackets(loaded.config) : colorSpaceNames(loaded.config);
    throw Error(configError(std::string("unknown ") + purpose + " colorspace or role \"" + name +
                                "\"",
                            loaded) +
                ", which offers " + (bracket ? "the brackets " : "the colorspaces ") +
                nameList(offered));
  }
  return space->getName();
}

OCIO::GpuShaderDescRcPtr gpuShader(const OCIO::ConstProcessorRcPtr& processor,
                                   const char* functionName) {
  OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
  desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
  desc->setFunctionName(functionName);
  desc->setResourcePrefix((std::string(functionName) + "_").c_str());
  processor->getDefaultGPUProcessor()->extractGpuShaderInfo(desc);
  return desc;
}

void checkRoundTrip(const OCIO::ConstCPUProcessorRcPtr& forward,
                    const OCIO::ConstCPUProcessorRcPtr& backToInput, const std::string& bracket,
                    const LoadedConfig& loaded) {
  for (float value : kRoundTripValues) {
    float pixel[3] = {value, 0.5f * value, 0.25f * value};
    forward->applyRGB(pixel);
    backToInput->applyRGB(pixel);
    const float expected[3] = {value, 0.5f * value, 0.25f * value};
    for (int c = 0; c < 3; ++c) {
      const float tolerance = kRoundTripTolerance * std::max(1.0f, expected[c]);
      if (!(std::abs(pixel[c] - expected[c]) <= tolerance)) {
        std::ostringstream what;
        what << "bracket \"" << bracket << "\" is not invertible: " << expected[c]
             << " comes back as " << pixel[c];
        throw Error(configError(what.str(), loaded));
      }
    }
  }
}

// A named transform's transform in `direction`: the one defined for it, or the inverse of the
// one defined for the other direction. Null when it defines neither.
OCIO::TransformRcPtr namedTransformIn(const OCIO::ConstNamedTransformRcPtr& named,
                                      OCIO::TransformDirection direction) {
  if (OCIO::ConstTransformRcPtr t = named->getTransform(direction)) return t->createEditableCopy();
  const auto other = direction == OCIO::TRANSFORM_DIR_FORWARD ? OCIO::TRANSFORM_DIR_INVERSE
                                                              : OCIO::TRANSFORM_DIR_FORWARD;
  OCIO::ConstTransformRcPtr t = named->getTransform(other);
  if (!t) return nullptr;
  OCIO::TransformRcPtr inverted = t->createEditableCopy();
  inverted->setDirection(OCIO::GetInverseTransformDirection(inverted->getDirection()));
  return inverted;
}

// taa's shipped config, parsed once: its working spaces are the brackets every config gets.
OCIO::ConstConfigRcPtr shippedConfig() {
  static const OCIO::ConstConfigRcPtr config = [] {
    std::istringstream text(shippedConfigText());
    OCIO::ConstConfigRcPtr parsed = OCIO::Config::CreateFromStream(text);
    parsed->validate();
    return parsed;
  }();
  return config;
}

// The family of the shipped config's bracket spaces (ocio/config.ocio).
constexpr const char* kShippedBracketFamily = "taa/working";

// The shipped bracket `name`'s transform from scene-linear values into its working space, or
// null when `name` is not one. Pure maths (log, matrix), so it runs in any config.
OCIO::ConstTransformRcPtr shippedBracket(const std::string& name) {
  OCIO::ConstColorSpaceRcPtr space = shippedConfig()->getColorSpace(name.c_str());
  if (!space || std::string(space->getFamily()) != kShippedBracketFamily) return nullptr;
  return space->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE);
}

bool isShippedBracket(const std::string& name) { return shippedBracket(name) != nullptr; }

std::vector<std::string> shippedBracketNames() {
  std::vector<std::string> names;
  const OCIO::ConstConfigRcPtr& config = shippedConfig();
  for (int i = 0; i < config->getNumColorSpaces(); ++i) {
    if (isShippedBracket(config->getColorSpaceNameByIndex(i))) {
      names.push_back(config->getColorSpaceNameByIndex(i));
    }
  }
  return names;
}

OCIO::TransformRcPtr inverted(const OCIO::ConstTransformRcPtr& transform) {
  OCIO::TransformRcPtr copy = transform->createEditableCopy();
  copy->setDirection(OCIO::GetInverseTransformDirection(copy->getDirection()));
  return copy;
}

// The colorspaces a bracket converts between, by their names in the config: `linear` is the
// config's scene_linear, where taa's own brackets work.
struct Spaces {
  std::string in, out, linear;
  bool unmanaged = false;  // no scene_linear role and none asked for: values pass unconverted
};

// A config without a scene_linear role (OCIO does not require one) still resolves by default:
// the input is taken as the linear values the bracket expects, output in the same space, as
// with taa's own config. Naming a colorspace then needs the role, to know where linear is.
Spaces resolveSpaces(const LoadedConfig& loaded, const ColorOptions& options) {
  const OCIO::ConstConfigRcPtr& config = loaded.config;
  const bool shipped = isShippedBracket(options.bracket);
  const bool defaultSpaces = (shipped || options.bracket == "none") &&
      options.colorspaceIn == OCIO::ROLE_SCENE_LINEAR &&
      (options.colorspaceOut.empty() || options.colorspaceOut == OCIO::ROLE_SCENE_LINEAR);
  const bool hasLinear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR) != nullptr;
  if (defaultSpaces && !hasLinear) {
    return {OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_SCENE_LINEAR, true};
  }
  Spaces spaces;
  spaces.in = requireColorSpace(loaded, options.colorspaceIn, "input");
  spaces.out = requireColorSpace(
      loaded, options.colorspaceOut.empty() ? options.colorspaceIn : options.colorspaceOut,
      "output");
  if (shipped) {
    if (!hasLinear) {
      throw Error(configError("the bracket \"" + options.bracket + "\" works on scene-linear "
                              "values, and there is no scene_linear role",
                              loaded) +
                  " to convert the colorspaces named to them: add the role to the config, or "
                  "resolve without a bracket (--bracket none)");
    }
    spaces.linear = requireColorSpace(loaded, OCIO::ROLE_SCENE_LINEAR, "scene_linear");
  }
  return spaces;
}

}  // namespace

LoadedConfig loadConfig(const std::string& path) {
  LoadedConfig loaded;
  std::string file = path;
  const char* env = std::getenv("OCIO");
  const bool environment = path == kOcioEnvironmentConfig || (path.empty() && env && *env);
  if (environment) {
    if (!env || !*env) {
      throw Error("the OCIO config was asked for from $OCIO, but $OCIO is not set");
    }
    file = env;
    loaded.description = std::string("$OCIO (") + env + ")";
  } else {
    loaded.description = path;
  }
  try {
    if (file.empty()) {
      loaded.description = "taa's shipped config";
      loaded.config = shippedConfig();
    } else {
      loaded.config = OCIO::Config::CreateFromFile(file.c_str());
      loaded.config->validate();
    }
  } catch (const OCIO::Exception& e) {
    throw Error(std::string("cannot load the OCIO config: ") + e.what(), {file});
  }
  return loaded;
}

std::vector<std::string> listBrackets(const OCIO::ConstConfigRcPtr& config) {
  std::vector<std::string> names = {"none"};
  const std::vector<std::string> shipped = shippedBracketNames();
  names.insert(names.end(), shipped.begin(), shipped.end());
  auto add = [&](const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  for (int i = 0; i < config->getNumColorSpaces(); ++i) {
    OCIO::ConstColorSpaceRcPtr space = config->getColorSpace(config->getColorSpaceNameByIndex(i));
    if (space && !space->isData()) add(space->getName());
  }
  for (int i = 0; i < config->getNumNamedTransforms(); ++i) {
    add(config->getNamedTransformNameByIndex(i));
  }
  return names;
}

OutputColorspace outputColorspace(const ColorOptions& options) {
  const LoadedConfig loaded = loadConfig(options.ocioConfig);
  return {resolveSpaces(loaded, options).out, loaded.description};
}

OcioBracket::OcioBracket(const ColorOptions& options) {
  const LoadedConfig loaded = loadConfig(options.ocioConfig);
  const OCIO::ConstConfigRcPtr& config = loaded.config;
  const OCIO::ConstTransformRcPtr shipped = shippedBracket(options.bracket);
  const Spaces spaces = resolveSpaces(loaded, options);
  const std::string& in = spaces.in;
  const std::string& out = spaces.out;

  OCIO::ConstProcessorRcPtr toWorking, fromWorking, backToInput;
  try {
    if (shipped) {
      // taa's own maths on the config's scene-linear values: the user's config converts the
      // input there and back, whatever it calls its spaces.
      auto chain = [&](const std::string& from, const std::string& to, bool intoWorking) {
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        if (!intoWorking) group->appendTransform(inverted(shipped));
        if (from != to && !spaces.unmanaged) {
          auto convert = OCIO::ColorSpaceTransform::Create();
          convert->setSrc(from.c_str());
          convert->setDst(to.c_str());
          group->appendTransform(convert);
        }
        if (intoWorking) group->appendTransform(shipped->createEditableCopy());
        return config->getProcessor(group);
      };
      toWorking = chain(in, spaces.linear, true);
      fromWorking = chain(spaces.linear, out, false);
      backToInput = chain(spaces.linear, in, false);
    } else if (options.bracket == "none" && spaces.unmanaged) {
      toWorking = config->getProcessor(OCIO::GroupTransform::Create());
      fromWorking = toWorking;
      backToInput = toWorking;
    } else if (options.bracket == "none") {  // no working space: the resolve sees input values
      toWorking = config->getProcessor(in.c_str(), in.c_str());
      fromWorking = config->getProcessor(in.c_str(), out.c_str());
      backToInput = toWorking;
    } else if (OCIO::ConstNamedTransformRcPtr named =
                   config->getNamedTransform(options.bracket.c_str())) {
      // A named transform works on scene-linear values: reach them from the input first.
      const std::string linear = requireColorSpace(loaded, OCIO::ROLE_SCENE_LINEAR, "scene_linear");
      auto chain = [&](const std::string& from, const std::string& to, bool intoWorking) {
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        auto convert = OCIO::ColorSpaceTransform::Create();
        convert->setSrc(from.c_str());
        convert->setDst(to.c_str());
        OCIO::TransformRcPtr working = namedTransformIn(
            named, intoWorking ? OCIO::TRANSFORM_DIR_FORWARD : OCIO::TRANSFORM_DIR_INVERSE);
        if (!working) {
          throw Error(configError("named transform \"" + options.bracket + "\" has no transform",
                                  loaded));
        }
        if (intoWorking) {
          group->appendTransform(convert);
          group->appendTransform(working);
        } else {
          group->appendTransform(working);
          group->appendTransform(convert);
        }
        return config->getProcessor(group);
      };
      toWorking = chain(in, linear, true);
      fromWorking = chain(linear, out, false);
      backToInput = chain(linear, in, false);
    } else {
      const std::string working = requireColorSpace(loaded, options.bracket, "bracket");
      toWorking = config->getProcessor(in.c_str(), working.c_str());
      fromWorking = config->getProcessor(working.c_str(), out.c_str());
      backToInput = config->getProcessor(working.c_str(), in.c_str());
    }
    toWorkingCpu_ = toWorking->getDefaultCPUProcessor();
    fromWorkingCpu_ = fromWorking->getDefaultCPUProcessor();
    checkRoundTrip(toWorkingCpu_, backToInput->getDefaultCPUProcessor(), options.bracket, loaded);
    toWorking_ = gpuShader(toWorking, kToWorkingFunction);
    fromWorking_ = gpuShader(fromWorking, kFromWorkingFunction);
  } catch (const OCIO::Exception& e) {
    throw Error(configError("cannot build the bracket \"" + options.bracket + "\": " + e.what(),
                            loaded));
  }
  cacheId_ = std::string(toWorking->getCacheID()) + "|" + fromWorking->getCacheID();
}

std::string OcioBracket::glsl() const {
  return std::string(toWorking_->getShaderText()) + "\n" + fromWorking_->getShaderText() + "\n";
}

std::string OcioBracket::cacheId() const { return cacheId_; }

OcioBracket::Range OcioBracket::workingRange() const {
  constexpr float kHalfMax = 65504.0f;
  float lo[3] = {-kHalfMax, -kHalfMax, -kHalfMax}, hi[3] = {kHalfMax, kHalfMax, kHalfMax};
  toWorkingCpu_->applyRGB(lo);
  toWorkingCpu_->applyRGB(hi);
  const float inf = std::numeric_limits<float>::infinity();
  if (!std::isfinite(lo[0]) || !std::isfinite(hi[0]) || !(lo[0] < hi[0])) return {-inf, inf};
  return {lo[0], hi[0]};
}

}  // namespace taa::color
