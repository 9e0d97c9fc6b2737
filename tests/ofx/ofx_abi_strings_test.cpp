// The OpenFX strings and status values taa's plugin and test host use, next to the values the
// published OpenFX specification gives them. The plugin and the test host share ofx_abi.h, so a
// wrong value there is invisible to every test that goes through it (both sides agree on the
// wrong string); this test reads the header as text and holds each value against a table
// written from the specification, not from the header.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct SpecValue {
  const char* value;  // the string (or number) the specification defines
  const char* where;  // the official header it is defined in
};

// Written from the OpenFX specification's headers (openfx/include). Where the macro's name and
// its value differ in spelling, the value is the one that counts: hosts compare values.
const std::map<std::string, SpecValue>& specification() {
  static const std::map<std::string, SpecValue> table = {
      // ofxCore.h: status codes
      {"kOfxStatOK", {"0", "ofxCore.h"}},
      {"kOfxStatFailed", {"1", "ofxCore.h"}},
      {"kOfxStatErrFatal", {"2", "ofxCore.h"}},
      {"kOfxStatErrUnknown", {"3", "ofxCore.h"}},
      {"kOfxStatErrMissingHostFeature", {"4", "ofxCore.h"}},
      {"kOfxStatErrUnsupported", {"5", "ofxCore.h"}},
      {"kOfxStatErrExists", {"6", "ofxCore.h"}},
      {"kOfxStatErrFormat", {"7", "ofxCore.h"}},
      {"kOfxStatErrMemory", {"8", "ofxCore.h"}},
      {"kOfxStatErrBadHandle", {"9", "ofxCore.h"}},
      {"kOfxStatErrBadIndex", {"10", "ofxCore.h"}},
      {"kOfxStatErrValue", {"11", "ofxCore.h"}},
      {"kOfxStatReplyYes", {"12", "ofxCore.h"}},
      {"kOfxStatReplyNo", {"13", "ofxCore.h"}},
      {"kOfxStatReplyDefault", {"14", "ofxCore.h"}},
      // ofxCore.h: the bundle's entry points
      {"kOfxGetNumberOfPluginsSymbol", {"OfxGetNumberOfPlugins", "ofxCore.h"}},
      {"kOfxGetPluginSymbol", {"OfxGetPlugin", "ofxCore.h"}},
      // ofxCore.h: actions and general properties
      {"kOfxActionLoad", {"OfxActionLoad", "ofxCore.h"}},
      {"kOfxActionUnload", {"OfxActionUnload", "ofxCore.h"}},
      {"kOfxActionDescribe", {"OfxActionDescribe", "ofxCore.h"}},
      {"kOfxActionCreateInstance", {"OfxActionCreateInstance", "ofxCore.h"}},
      {"kOfxActionDestroyInstance", {"OfxActionDestroyInstance", "ofxCore.h"}},
      {"kOfxActionPurgeCaches", {"OfxActionPurgeCaches", "ofxCore.h"}},
      {"kOfxActionInstanceChanged", {"OfxActionInstanceChanged", "ofxCore.h"}},
      {"kOfxPropName", {"OfxPropName", "ofxCore.h"}},
      {"kOfxPropType", {"OfxPropType", "ofxCore.h"}},
      {"kOfxPropLabel", {"OfxPropLabel", "ofxCore.h"}},
      {"kOfxPropTime", {"OfxPropTime", "ofxCore.h"}},
      {"kOfxPropInstanceData", {"OfxPropInstanceData", "ofxCore.h"}},
      {"kOfxPropPluginDescription", {"OfxPropPluginDescription", "ofxCore.h"}},
      {"kOfxBitDepthHalf", {"OfxBitDepthHalf", "ofxCore.h"}},
      {"kOfxBitDepthFloat", {"OfxBitDepthFloat", "ofxCore.h"}},
      // ofxProperty.h, ofxParam.h, ofxMessage.h, ofxImageEffect.h: suite names
      {"kOfxPropertySuite", {"OfxPropertySuite", "ofxProperty.h"}},
      {"kOfxParameterSuite", {"OfxParameterSuite", "ofxParam.h"}},
      {"kOfxMessageSuite", {"OfxMessageSuite", "ofxMessage.h"}},
      {"kOfxImageEffectSuite", {"OfxImageEffectSuite", "ofxImageEffect.h"}},
      // ofxMessage.h
      {"kOfxMessageError", {"OfxMessageError", "ofxMessage.h"}},
      {"kOfxMessageWarning", {"OfxMessageWarning", "ofxMessage.h"}},
      // ofxImageEffect.h: API, actions, contexts, clips
      {"kOfxImageEffectPluginApi", {"OfxImageEffectPluginAPI", "ofxImageEffect.h"}},
      {"kOfxImageEffectActionDescribeInContext",
       {"OfxImageEffectActionDescribeInContext", "ofxImageEffect.h"}},
      {"kOfxImageEffectActionGetFramesNeeded",
       {"OfxImageEffectActionGetFramesNeeded", "ofxImageEffect.h"}},
      {"kOfxImageEffectActionGetClipPreferences",
       {"OfxImageEffectActionGetClipPreferences", "ofxImageEffect.h"}},
      {"kOfxImageEffectActionRender", {"OfxImageEffectActionRender", "ofxImageEffect.h"}},
      {"kOfxImageEffectActionEndSequenceRender",
       {"OfxImageEffectActionEndSequenceRender", "ofxImageEffect.h"}},
      {"kOfxImageEffectContextFilter", {"OfxImageEffectContextFilter", "ofxImageEffect.h"}},
      {"kOfxImageEffectContextGeneral", {"OfxImageEffectContextGeneral", "ofxImageEffect.h"}},
      {"kOfxImageEffectSimpleSourceClipName", {"Source", "ofxImageEffect.h"}},
      {"kOfxImageEffectOutputClipName", {"Output", "ofxImageEffect.h"}},
      {"kOfxImageComponentRGBA", {"OfxImageComponentRGBA", "ofxImageEffect.h"}},
      {"kOfxImageComponentRGB", {"OfxImageComponentRGB", "ofxImageEffect.h"}},
      {"kOfxImageComponentAlpha", {"OfxImageComponentAlpha", "ofxImageEffect.h"}},
      {"kOfxImageComponentNone", {"OfxImageComponentNone", "ofxImageEffect.h"}},
      {"kOfxImageOpaque", {"OfxImageOpaque", "ofxImageEffect.h"}},
      {"kOfxImagePreMultiplied", {"OfxImageAlphaPremultiplied", "ofxImageEffect.h"}},
      {"kOfxImageUnPreMultiplied", {"OfxImageAlphaUnPremultiplied", "ofxImageEffect.h"}},
      {"kOfxImageFieldNone", {"OfxFieldNone", "ofxImageEffect.h"}},
      {"kOfxImageEffectRenderFullySafe", {"OfxImageEffectRenderFullySafe", "ofxImageEffect.h"}},
      {"kOfxTypeParameter", {"OfxTypeParameter", "ofxParam.h"}},
      // ofxImageEffect.h: properties
      {"kOfxImageEffectPropContext", {"OfxImageEffectPropContext", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportedContexts",
       {"OfxImageEffectPropSupportedContexts", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportedPixelDepths",
       {"OfxImageEffectPropSupportedPixelDepths", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportedComponents",
       {"OfxImageEffectPropSupportedComponents", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropTemporalClipAccess",
       {"OfxImageEffectPropTemporalClipAccess", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportsTiles", {"OfxImageEffectPropSupportsTiles", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportsMultiResolution",
       {"OfxImageEffectPropSupportsMultiResolution", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportsMultipleClipDepths",
       {"OfxImageEffectPropMultipleClipDepths", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropSupportsMultipleClipPARs",
       {"OfxImageEffectPropSupportsMultipleClipPARs", "ofxImageEffect.h"}},
      {"kOfxImageEffectInstancePropSequentialRender",
       {"OfxImageEffectInstancePropSequentialRender", "ofxImageEffect.h"}},
      {"kOfxImageEffectFrameVarying", {"OfxImageEffectFrameVarying", "ofxImageEffect.h"}},
      {"kOfxImageEffectPluginPropGrouping",
       {"OfxImageEffectPluginPropGrouping", "ofxImageEffect.h"}},
      {"kOfxImageEffectPluginPropHostFrameThreading",
       {"OfxImageEffectPluginPropHostFrameThreading", "ofxImageEffect.h"}},
      {"kOfxImageEffectPluginRenderThreadSafety",
       {"OfxImageEffectPluginRenderThreadSafety", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropFrameRange", {"OfxImageEffectPropFrameRange", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropRenderScale", {"OfxImageEffectPropRenderScale", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropRenderWindow", {"OfxImageEffectPropRenderWindow", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropFieldToRender",
       {"OfxImageEffectPropFieldToRender", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropPixelDepth", {"OfxImageEffectPropPixelDepth", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropComponents", {"OfxImageEffectPropComponents", "ofxImageEffect.h"}},
      {"kOfxImageEffectPropPreMultiplication",
       {"OfxImageEffectPropPreMultiplication", "ofxImageEffect.h"}},
      {"kOfxImageClipPropOptional", {"OfxImageClipPropOptional", "ofxImageEffect.h"}},
      {"kOfxImageClipPropConnected", {"OfxImageClipPropConnected", "ofxImageEffect.h"}},
      {"kOfxImageClipPropUnmappedComponents",
       {"OfxImageClipPropUnmappedComponents", "ofxImageEffect.h"}},
      {"kOfxImagePropPixelAspectRatio", {"OfxImagePropPixelAspectRatio", "ofxImageEffect.h"}},
      {"kOfxImagePropData", {"OfxImagePropData", "ofxImageEffect.h"}},
      {"kOfxImagePropBounds", {"OfxImagePropBounds", "ofxImageEffect.h"}},
      {"kOfxImagePropRowBytes", {"OfxImagePropRowBytes", "ofxImageEffect.h"}},
      // Named in the specification's action documentation by text (prefix + clip name).
      {"kOfxImageClipPropFrameRangePrefix",
       {"OfxImageClipPropFrameRange_", "kOfxImageEffectActionGetFramesNeeded"}},
      {"kOfxImageClipPropComponentsPrefix",
       {"OfxImageClipPropComponents_", "kOfxImageEffectActionGetClipPreferences"}},
      {"kOfxImageClipPropPARPrefix",
       {"OfxImageClipPropPAR_", "kOfxImageEffectActionGetClipPreferences"}},
      // ofxParam.h
      {"kOfxParamTypeDouble", {"OfxParamTypeDouble", "ofxParam.h"}},
      {"kOfxParamTypeInteger", {"OfxParamTypeInteger", "ofxParam.h"}},
      {"kOfxParamTypeBoolean", {"OfxParamTypeBoolean", "ofxParam.h"}},
      {"kOfxParamTypeChoice", {"OfxParamTypeChoice", "ofxParam.h"}},
      {"kOfxParamTypeString", {"OfxParamTypeString", "ofxParam.h"}},
      {"kOfxParamPropDefault", {"OfxParamPropDefault", "ofxParam.h"}},
      {"kOfxParamPropMin", {"OfxParamPropMin", "ofxParam.h"}},
      {"kOfxParamPropMax", {"OfxParamPropMax", "ofxParam.h"}},
      {"kOfxParamPropDisplayMin", {"OfxParamPropDisplayMin", "ofxParam.h"}},
      {"kOfxParamPropDisplayMax", {"OfxParamPropDisplayMax", "ofxParam.h"}},
      {"kOfxParamPropHint", {"OfxParamPropHint", "ofxParam.h"}},
      {"kOfxParamPropChoiceOption", {"OfxParamPropChoiceOption", "ofxParam.h"}},
      {"kOfxParamPropAnimates", {"OfxParamPropAnimates", "ofxParam.h"}},
      {"kOfxParamPropStringMode", {"OfxParamPropStringMode", "ofxParam.h"}},
      {"kOfxParamPropStringFilePathExists", {"OfxParamPropStringFilePathExists", "ofxParam.h"}},
      {"kOfxParamStringIsSingleLine", {"OfxParamStringIsSingleLine", "ofxParam.h"}},
      {"kOfxParamStringIsFilePath", {"OfxParamStringIsFilePath", "ofxParam.h"}},
  };
  return table;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every `#define kOfx... value` of ofx_abi.h: name -> value (quotes and casts removed).
std::map<std::string, std::string> headerDefines() {
  const std::string text = readText(fs::path(TAA_SOURCE_DIR) / "plugin/src/ofx/ofx_abi.h");
  std::map<std::string, std::string> defines;
  const std::regex define(R"re(#define\s+(kOfx\w+)\s+(?:\\\s*)?("([^"]*)"|(\d+)))re");
  for (std::sregex_iterator it(text.begin(), text.end(), define), end; it != end; ++it) {
    defines[(*it)[1]] = (*it)[3].matched ? (*it)[3].str() : (*it)[4].str();
  }
  return defines;
}

TEST(OfxAbiStrings, EveryDefineHasTheSpecificationsValue) {
  const auto defines = headerDefines();
  ASSERT_GT(defines.size(), 50u) << "ofx_abi.h was not found or not parsed";
  for (const auto& [name, value] : defines) {
    const auto spec = specification().find(name);
    if (spec == specification().end()) {
      ADD_FAILURE() << name << " (\"" << value
                    << "\") is not in this test's table: look its value up in the OpenFX "
                       "specification and add it here";
      continue;
    }
    EXPECT_EQ(value, spec->second.value)
        << name << " must be \"" << spec->second.value << "\" (" << spec->second.where << ")";
  }
}

// The two values the first host built on the official SDK tripped over, spelled out.
TEST(OfxAbiStrings, ValuesWhoseMacroNamesMislead) {
  const auto defines = headerDefines();
  EXPECT_EQ(defines.at("kOfxImagePreMultiplied"), "OfxImageAlphaPremultiplied");
  EXPECT_EQ(defines.at("kOfxImageUnPreMultiplied"), "OfxImageAlphaUnPremultiplied");
  EXPECT_EQ(defines.at("kOfxImageEffectPropSupportsMultipleClipDepths"),
            "OfxImageEffectPropMultipleClipDepths");
  EXPECT_EQ(defines.at("kOfxImageFieldNone"), "OfxFieldNone");
}

// No OpenFX string is spelled outside ofx_abi.h, so the check above covers every one of them.
TEST(OfxAbiStrings, PluginAndTestHostSpellNoOfxStringThemselves) {
  const std::regex literal(R"re("Ofx[A-Za-z_]*")re");
  for (const char* folder : {"plugin/src/ofx", "tests/ofx"}) {
    for (const auto& entry : fs::directory_iterator(fs::path(TAA_SOURCE_DIR) / folder)) {
      const fs::path& path = entry.path();
      if (path.filename() == "ofx_abi.h" || path.filename() == "ofx_abi_strings_test.cpp") {
        continue;
      }
      if (path.extension() != ".cpp" && path.extension() != ".h") continue;
      const std::string text = readText(path);
      std::smatch found;
      EXPECT_FALSE(std::regex_search(text, found, literal))
          << path << " spells " << found.str() << ": declare it in ofx_abi.h";
    }
  }
}

}  // namespace
