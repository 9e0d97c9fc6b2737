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

}  // namespace

LoadedConfig loadConfig(const std::string& path) {
  LoadedConfig loaded;
  std::string file = path;
  if (path == kOcioEnvironmentConfig) {
    const char* env = std::getenv("OCIO");
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
      std::istringstream text(shippedConfigText());
      loaded.config = OCIO::Config::CreateFromStream(text);
    } else {
      loaded.config = OCIO::Config::CreateFromFile(file.c_str());
    }
    loaded.config->validate();
  } catch (const OCIO::Exception& e) {
    throw Error(std::string("cannot load the OCIO config: ") + e.what(), {file});
  }
  return loaded;
}

std::vector<std::string> listBrackets(const OCIO::ConstConfigRcPtr& config) {
  std::vector<std::string> names = {"none"};
  for (int i = 0; i < config->getNumColorSpaces(); ++i) {
    OCIO::ConstColorSpaceRcPtr space = config->getColorSpace(config->getColorSpaceNameByIndex(i));
    if (space && !space->isData() && space->getName() != std::string("none")) {
      names.push_back(space->getName());
    }
  }
  for (int i = 0; i < config->getNumNamedTransforms(); ++i) {
    names.push_back(config->getNamedTransformNameByIndex(i));
  }
  return names;
}

OcioBracket::OcioBracket(const ColorOptions& options) {
  const LoadedConfig loaded = loadConfig(options.ocioConfig);
  const OCIO::ConstConfigRcPtr& config = loaded.config;
  const std::string in = requireColorSpace(loaded, options.colorspaceIn, "input");
  const std::string out = requireColorSpace(
      loaded, options.colorspaceOut.empty() ? options.colorspaceIn : options.colorspaceOut, "output");

  OCIO::ConstProcessorRcPtr toWorking, fromWorking, backToInput;
  try {
    if (options.bracket == "none") {  // no working space: the resolve sees input values
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
