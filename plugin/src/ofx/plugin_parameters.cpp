#include "ofx/plugin_parameters.h"

#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "color/ocio_bracket.h"
#include "ofx/host_suites.h"
#include "resolve/jitter.h"
#include "resolve/option_registry.h"

namespace taa::ofx {
namespace {

// Parameter names: stable, they are saved in hosts' scripts.
constexpr const char* kMode = "mode";
// The Mode choice's entries, as the option registry names them.
const char* const kModeNames[] = {"history", "window"};
constexpr const char* kWindowRadius = "window";
constexpr const char* kWindowNear = "windowNear";
constexpr const char* kWindowMoving = "windowMoving";
constexpr const char* kWindowSigma = "windowSigma";
constexpr const char* kWindowFalloff = "windowFalloff";
constexpr const char* kWindowTaper = "windowTaper";
constexpr const char* kWindowStrata = "windowStrata";
constexpr const char* kWindowTwoClusters = "windowTwoClusters";
constexpr const char* kWindowColourTolerance = "windowColourTolerance";
constexpr const char* kWindowStaticTolerance = "windowStaticTolerance";
constexpr const char* kWindowReconstructionWeight = "windowReconstructionWeight";
constexpr const char* kBlend = "blend";
constexpr const char* kRectify = "rectify";
// The Rectify choice's entries, as the option registry names them.
const char* const kRectifyNames[] = {"variance", "clip", "clamp", "none"};
constexpr const char* kDilateMotion = "dilateMotion";
constexpr const char* kJitter = "jitter";
constexpr const char* kJitterOffset = "jitterOffset";
constexpr const char* kJitterPeriod = "jitterPeriod";
constexpr const char* kMotionY = "motionY";
constexpr const char* kMotionTo = "motionTo";
constexpr const char* kMotionScale = "motionScale";
constexpr const char* kDepthNoHit = "depthNoHit";
constexpr const char* kHistoryFrames = "historyFrames";
constexpr const char* kOcioConfigSource = "ocioConfigSource";
constexpr const char* kOcioConfigFile = "ocioConfigFile";
constexpr const char* kColorspaceIn = "colorspaceIn";
constexpr const char* kBracket = "bracket";
constexpr const char* kColorspaceOut = "colorspaceOut";
constexpr const char* kPassKind = "passKind";

void check(OfxStatus status, const std::string& what) {
  if (status != kOfxStatOK) {
    throw std::runtime_error(what + " failed (OFX status " + std::to_string(status) + ")");
  }
}

OfxPropertySetHandle define(OfxParamSetHandle set, const char* type, const char* name,
                            const char* label, const char* hint) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = nullptr;
  check(s.parameters->paramDefine(set, type, name, &props), std::string("define ") + name);
  s.properties->propSetString(props, kOfxPropLabel, 0, label);
  s.properties->propSetString(props, kOfxParamPropHint, 0, hint);
  s.properties->propSetInt(props, kOfxParamPropAnimates, 0, 0);
  return props;
}

void defineDouble(OfxParamSetHandle set, const char* name, const char* label, const char* hint,
                  double value, double min, double max) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = define(set, kOfxParamTypeDouble, name, label, hint);
  s.properties->propSetDouble(props, kOfxParamPropDefault, 0, value);
  s.properties->propSetDouble(props, kOfxParamPropMin, 0, min);
  s.properties->propSetDouble(props, kOfxParamPropMax, 0, max);
  s.properties->propSetDouble(props, kOfxParamPropDisplayMin, 0, min);
  s.properties->propSetDouble(props, kOfxParamPropDisplayMax, 0, max);
}

void defineInt(OfxParamSetHandle set, const char* name, const char* label, const char* hint,
               int value, int min, int max) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = define(set, kOfxParamTypeInteger, name, label, hint);
  s.properties->propSetInt(props, kOfxParamPropDefault, 0, value);
  s.properties->propSetInt(props, kOfxParamPropMin, 0, min);
  s.properties->propSetInt(props, kOfxParamPropMax, 0, max);
}

void defineBoolean(OfxParamSetHandle set, const char* name, const char* label, const char* hint,
                   bool value) {
  OfxPropertySetHandle props = define(set, kOfxParamTypeBoolean, name, label, hint);
  suites().properties->propSetInt(props, kOfxParamPropDefault, 0, value ? 1 : 0);
}

void defineChoice(OfxParamSetHandle set, const char* name, const char* label, const char* hint,
                  const std::vector<const char*>& options, int defaultIndex = 0) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = define(set, kOfxParamTypeChoice, name, label, hint);
  for (int i = 0; i < int(options.size()); ++i) {
    s.properties->propSetString(props, kOfxParamPropChoiceOption, i, options[i]);
  }
  s.properties->propSetInt(props, kOfxParamPropDefault, 0, defaultIndex);
}

void defineString(OfxParamSetHandle set, const char* name, const char* label, const char* hint,
                  const std::string& value, bool filePath = false) {
  const HostSuites& s = suites();
  OfxPropertySetHandle props = define(set, kOfxParamTypeString, name, label, hint);
  s.properties->propSetString(props, kOfxParamPropDefault, 0, value.c_str());
  s.properties->propSetString(props, kOfxParamPropStringMode, 0,
                              filePath ? kOfxParamStringIsFilePath : kOfxParamStringIsSingleLine);
  if (filePath) s.properties->propSetInt(props, kOfxParamPropStringFilePathExists, 0, 1);
}

// Index of the library's default for a registry option among `names` (the host's choice order).
int registryDefaultIndex(const char* option, const char* const* names, int count) {
  const std::string value = taa::resolveOptionValue(taa::ResolveOptions{}, option);
  for (int i = 0; i < count; ++i) {
    if (value == names[i]) return i;
  }
  return 0;
}

OfxParamHandle handle(OfxParamSetHandle set, const char* name) {
  OfxParamHandle param = nullptr;
  check(suites().parameters->paramGetHandle(set, name, &param, nullptr),
        std::string("parameter ") + name);
  return param;
}

double getDouble(OfxParamSetHandle set, const char* name, OfxTime time) {
  double value = 0.0;
  check(suites().parameters->paramGetValueAtTime(handle(set, name), time, &value),
        std::string("value of ") + name);
  return value;
}

std::string getString(OfxParamSetHandle set, const char* name, OfxTime time) {
  char* value = nullptr;  // the host's; valid until the next call
  check(suites().parameters->paramGetValueAtTime(handle(set, name), time, &value),
        std::string("value of ") + name);
  return value ? value : "";
}

int getInt(OfxParamSetHandle set, const char* name, OfxTime time) {
  int value = 0;
  check(suites().parameters->paramGetValueAtTime(handle(set, name), time, &value),
        std::string("value of ") + name);
  return value;
}

void require(taa_node* node, taa_status status) {
  if (status != TAA_OK) throw std::runtime_error(taa_node_last_error(node));
}

}  // namespace

bool PluginSettings::operator==(const PluginSettings& o) const {
  auto tie = [](const PluginSettings& s) {
    return std::tie(s.mode, s.windowRadius, s.windowNear, s.windowMoving, s.windowSigma, s.windowFalloff, s.windowTaper,
                    s.windowStrata, s.windowTwoClusters,
                    s.windowColourTolerance, s.windowStaticTolerance,
                    s.windowReconstructionWeight, s.blend, s.rectify, s.dilateMotion, s.jitter,
                    s.jitterOffset, s.jitterPeriod, s.motionY, s.motionTo, s.motionScale,
                    s.depthNoHit, s.historyFrames, s.ocioConfigSource, s.ocioConfigFile,
                    s.colorspaceIn, s.bracket, s.colorspaceOut, s.passKind, s.passConnected,
                    s.passFactorConnected);
  };
  return tie(*this) == tie(o);
}

void defineParameters(OfxParamSetHandle set) {
  defineChoice(set, kMode, "Mode",
               "History: each frame blended into the history of the frames before it (render "
               "in order). Window: each frame rebuilt from the frames Window (K) before and "
               "after it, independent of the others (any order) (taatool --mode).",
               {"History", "Window"}, registryDefaultIndex("mode", kModeNames, 2));
  const taa::WindowOptions window;
  defineInt(set, kWindowRadius, "Window (K)",
            "Window mode: frames used on each side of the resolved frame at most; 2K+1 are kept "
            "in memory per render thread (taatool --window).",
            window.radius, 0, taa::kMaxWindowRadius);
  defineInt(set, kWindowNear, "Window Near",
            "Window mode: frames each side always used; each 32 px tile's window reaches "
            "farther, up to K, while those frames agree with the resolved one over the tile; 0 "
            "uses the whole window everywhere (taatool --window-near).",
            window.nearRadius, 0, taa::kMaxWindowRadius);
  defineInt(set, kWindowMoving, "Window Moving",
            "Window mode: frames each side whose moving samples count, and every sample of a "
            "pixel where the resolved frame has a moving one; 0: the whole window (taatool "
            "--window-moving).",
            window.movingRadius, 0, taa::kMaxWindowRadius);
  defineDouble(set, kWindowSigma, "Window Sigma",
               "Window mode: pixels, the Gaussian weighting a sample by its distance to the pixel "
               "centre; smaller is sharper and noisier (taatool --window-sigma).",
               double(window.sigma), 0.05, 4.0);
  defineDouble(set, kWindowFalloff, "Window Falloff",
               "Window mode: frames, weight exp(-(distance/falloff)^2) by distance in time; 0 "
               "weighs every frame alike (taatool --window-falloff).",
               double(window.falloff), 0.0, 1000.0);
  defineBoolean(set, kWindowTaper, "Window Taper",
                "Window mode: also weigh frames by a Hann taper over the window, so that frames "
                "enter and leave it gently (taatool --window-taper).",
                window.taper);
  defineBoolean(set, kWindowStrata, "Window Strata",
                "Window mode: average the means of the four quadrants around the pixel centre "
                "(samples land at random). Pass effects weigh their samples as the beauty's "
                "mean does: set it alike on the Source's effect and theirs, so the passes add "
                "up to the beauty (taatool --window-strata).",
                window.strata);
  defineBoolean(set, kWindowTwoClusters, "Window Two Clusters",
                "Window mode: where a pixel's own samples span two depths, average the near "
                "surface's samples and the far one's apart and mix them by the near one's "
                "coverage, so edges and wires keep their width. Pass effects follow it, as "
                "Window Strata (taatool --window-two-clusters).",
                window.twoClusters);
  defineDouble(set, kWindowColourTolerance, "Window Colour Tolerance",
               "Window mode: how far outside the frame's own colour box a sample may be; 0 turns "
               "the test off (taatool --window-colour-tolerance).",
               double(window.colourTolerance), 0.0, 1000.0);
  defineDouble(set, kWindowStaticTolerance, "Window Static Tolerance",
               "Window mode: pixels within which a sample's vector must agree with the camera "
               "for camera reprojection (taatool --window-static-tolerance).",
               double(window.staticTolerance), 0.0, 1000.0);
  defineDouble(set, kWindowReconstructionWeight, "Window Reconstruction Weight",
               "Window mode: weight of the frame's own filtered reconstruction, the fallback of "
               "pixels that gather little (taatool --window-reconstruction-weight).",
               double(window.reconstructionWeight), 0.0, 1000.0);
  defineDouble(set, kBlend, "Blend",
               "Weight of the current frame in the exponential blend (taatool --blend).",
               double(taa::ResolveOptions{}.blend),
               0.001, 1.0);
  defineChoice(set, kRectify, "Rectify",
               "How history is brought into the current neighbourhood's colour box (none only "
               "to diagnose ghosts).",
               {"Variance Clip", "Clip", "Clamp", "None"},
               registryDefaultIndex("rectify", kRectifyNames, 4));
  defineBoolean(set, kDilateMotion, "Dilate Motion",
                "Take motion from the closest-depth pixel of the 3x3 neighbourhood.", true);
  defineChoice(set, kJitter, "Jitter", "How the renderer offset each frame's samples.",
               {"Halton", "None"});
  defineInt(set, kJitterOffset, "Jitter Offset", "Halton index = frame + offset.", 0, -1000000,
            1000000);
  defineInt(set, kJitterPeriod, "Jitter Period",
            "The Halton index cycles through 1..period (0: no cycle).", 0, 0, 1024);
  defineChoice(set, kMotionY, "Motion Y",
               "Direction of the motion vectors' y values (not of the image rows).",
               {"Down", "Up"});
  defineChoice(set, kMotionTo, "Motion Points To",
               "Whether vectors point to the previous or the next frame.",
               {"Previous", "Next"});
  defineDouble(set, kMotionScale, "Motion Scale",
               "Multiplies motion vectors (given in full-resolution pixels).", 1.0, -1000.0,
               1000.0);
  defineDouble(set, kDepthNoHit, "Depth No-Hit", "Depth at or above this means no hit.", 1e9,
               0.0, 1e30);
  defineInt(set, kHistoryFrames, "History Frames",
            "0: every frame is resolved from the clip's first frame, exactly as taatool. "
            "N: from at most N frames back (faster for random access, approximate).",
            0, 0, 100000);
  defineChoice(set, kOcioConfigSource, "OCIO Config",
               "Config of the input and output colorspaces: the one $OCIO names when it is set, "
               "else taa's shipped one (as taatool); the one $OCIO names; or a file. The "
               "brackets taa_reinhard and taa_log2 are taa's own and work in any config.",
               {"Automatic ($OCIO, else taa's)", "$OCIO", "File"});
  defineString(set, kOcioConfigFile, "OCIO Config File",
               "The OCIO config when OCIO Config is File (taatool --ocio-config).", "", true);
  const taa::ColorOptions color;
  defineString(set, kColorspaceIn, "Input Colorspace",
               "Colorspace or role of the Source clip's colour (taatool --colorspace-in).",
               color.colorspaceIn);
  defineString(set, kBracket, "Bracket",
               "Working space of the resolve: taa_reinhard or taa_log2 (taa's own, in any "
               "config), a colorspace or named transform of the config, or none (taatool "
               "--bracket). A name the config lacks is reported with the names it offers.",
               color.bracket);
  defineString(set, kColorspaceOut, "Output Colorspace",
               "Colorspace or role of the output (empty: the input's; taatool --colorspace-out).",
               color.colorspaceOut);
  defineChoice(set, kPassKind, "Pass Kind",
               "What the Pass clip holds (window mode; taatool --aov's kinds). Light: summed "
               "with the Source's weights, with Pass Factor (its colour pass) as Cycles' DiffDir "
               "with DiffCol, so that light x colour adds up. Factor: a colour pass, summed. "
               "Average: UV, position. Normal: averaged, XYZ renormalised. Nearest: depth, IDs, "
               "vectors: the frame's own value, never a blend. Cryptomatte: one rank layer "
               "(float), its IDs re-weighed.",
               {"Light", "Factor", "Average", "Normal", "Nearest", "Cryptomatte"});
}

bool isColorParameter(const std::string& name) {
  for (const char* color : {kOcioConfigSource, kOcioConfigFile, kColorspaceIn, kBracket,
                            kColorspaceOut}) {
    if (name == color) return true;
  }
  return false;
}

taa::ColorOptions colorOptions(const PluginSettings& s) {
  taa::ColorOptions color;
  switch (s.ocioConfigSource) {
    case 0: color.ocioConfig.clear(); break;
    case 1: color.ocioConfig = color::kOcioEnvironmentConfig; break;
    case 2:
      if (s.ocioConfigFile.empty()) {
        throw std::runtime_error("OCIO Config is File, but OCIO Config File is empty");
      }
      color.ocioConfig = s.ocioConfigFile;
      break;
    default: throw std::runtime_error("OCIO Config choice out of range");
  }
  color.colorspaceIn = s.colorspaceIn;
  color.bracket = s.bracket;
  color.colorspaceOut = s.colorspaceOut;
  return color;
}

void frameJitter(const PluginSettings& s, int frame, RenderScale scale, float jitter[2]) {
  taa::JitterOptions options;
  options.source = s.jitter == 1 ? taa::JitterSource::None : taa::JitterSource::Halton;
  options.indexOffset = s.jitterOffset;
  options.period = s.jitterPeriod;
  const glm::vec2 offset = taa::frameJitter(frame, options);
  jitter[0] = float(scale.x) * offset.x;
  jitter[1] = float(scale.y) * offset.y;
}

PluginSettings readSettings(OfxImageEffectHandle effect, OfxTime time) {
  OfxParamSetHandle set = nullptr;
  check(suites().effects->getParamSet(effect, &set), "getParamSet");
  PluginSettings s;
  s.mode = getInt(set, kMode, time);
  s.windowRadius = getInt(set, kWindowRadius, time);
  s.windowNear = getInt(set, kWindowNear, time);
  s.windowMoving = getInt(set, kWindowMoving, time);
  s.windowSigma = getDouble(set, kWindowSigma, time);
  s.windowFalloff = getDouble(set, kWindowFalloff, time);
  s.windowTaper = getInt(set, kWindowTaper, time) != 0;
  s.windowStrata = getInt(set, kWindowStrata, time) != 0;
  s.windowTwoClusters = getInt(set, kWindowTwoClusters, time) != 0;
  s.windowColourTolerance = getDouble(set, kWindowColourTolerance, time);
  s.windowStaticTolerance = getDouble(set, kWindowStaticTolerance, time);
  s.windowReconstructionWeight = getDouble(set, kWindowReconstructionWeight, time);
  s.blend = getDouble(set, kBlend, time);
  s.rectify = getInt(set, kRectify, time);
  s.dilateMotion = getInt(set, kDilateMotion, time) != 0;
  s.jitter = getInt(set, kJitter, time);
  s.jitterOffset = getInt(set, kJitterOffset, time);
  s.jitterPeriod = getInt(set, kJitterPeriod, time);
  s.motionY = getInt(set, kMotionY, time);
  s.motionTo = getInt(set, kMotionTo, time);
  s.motionScale = getDouble(set, kMotionScale, time);
  s.depthNoHit = getDouble(set, kDepthNoHit, time);
  s.historyFrames = getInt(set, kHistoryFrames, time);
  s.ocioConfigSource = getInt(set, kOcioConfigSource, time);
  s.ocioConfigFile = getString(set, kOcioConfigFile, time);
  s.colorspaceIn = getString(set, kColorspaceIn, time);
  s.bracket = getString(set, kBracket, time);
  s.colorspaceOut = getString(set, kColorspaceOut, time);
  s.passKind = getInt(set, kPassKind, time);
  return s;
}

void applySettings(taa_node* node, const PluginSettings& s, RenderScale scale) {
  if (s.mode != kModeHistory && s.mode != kModeWindow) {
    throw std::runtime_error("mode choice out of range");
  }
  require(node, taa_node_set_string(node, "mode", kModeNames[s.mode]));
  require(node, taa_node_set_int(node, "window", s.windowRadius));
  require(node, taa_node_set_int(node, "window-near", s.windowNear));
  require(node, taa_node_set_int(node, "window-moving", s.windowMoving));
  require(node, taa_node_set_float(node, "window-sigma", float(s.windowSigma)));
  require(node, taa_node_set_float(node, "window-falloff", float(s.windowFalloff)));
  require(node, taa_node_set_string(node, "window-taper", s.windowTaper ? "on" : "off"));
  require(node, taa_node_set_string(node, "window-strata", s.windowStrata ? "on" : "off"));
  require(node, taa_node_set_string(node, "window-two-clusters",
                                    s.windowTwoClusters ? "on" : "off"));
  require(node, taa_node_set_float(node, "window-colour-tolerance",
                                   float(s.windowColourTolerance)));
  require(node, taa_node_set_float(node, "window-static-tolerance",
                                   float(s.windowStaticTolerance)));
  require(node, taa_node_set_float(node, "window-reconstruction-weight",
                                   float(s.windowReconstructionWeight)));
  require(node, taa_node_set_float(node, "blend", float(s.blend)));
  if (s.rectify < 0 || s.rectify > 3) throw std::runtime_error("rectify choice out of range");
  require(node, taa_node_set_string(node, "rectify", kRectifyNames[s.rectify]));
  require(node, taa_node_set_string(node, "motion-dilation", s.dilateMotion ? "box" : "centre"));
  require(node, taa_node_set_string(node, "motion-y", s.motionY == 1 ? "up" : "down"));
  require(node, taa_node_set_string(node, "motion-to", s.motionTo == 1 ? "next" : "previous"));
  // A render at scale s gets images s times the size of the render the vectors were made for:
  // they are in that render's pixels.
  require(node, taa_node_set_float(node, "motion-scale", float(s.motionScale * scale.x)));
  require(node, taa_node_set_float(node, "depth-nohit", float(s.depthNoHit)));
  const taa::ColorOptions color = colorOptions(s);
  require(node, taa_node_set_string(node, "ocio-config", color.ocioConfig.c_str()));
  require(node, taa_node_set_string(node, "colorspace-in", color.colorspaceIn.c_str()));
  require(node, taa_node_set_string(node, "bracket", color.bracket.c_str()));
  require(node, taa_node_set_string(node, "colorspace-out", color.colorspaceOut.c_str()));
}

}  // namespace taa::ofx
