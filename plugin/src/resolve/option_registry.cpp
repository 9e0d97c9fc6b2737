#include "resolve/option_registry.h"

#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <utility>

#include "taa/error.h"
#include "util/number_text.h"

namespace taa {
namespace {

using Setter = std::function<void(ResolveOptions&, const std::string&)>;
using Getter = std::function<std::string(const ResolveOptions&)>;

struct Entry {
  OptionInfo info;
  Setter set;
  Getter get;
};

[[noreturn]] void reject(const std::string& name, const std::string& value,
                         const std::string& accepts) {
  throw Error("option " + name + " expects " + accepts + ", got \"" + value + "\"");
}

float parseNumber(const std::string& name, const std::string& value, float lo, float hi) {
  const std::optional<float> number = parseFloatText(value);
  std::ostringstream range;
  range << "a number in [" << lo << ", " << hi << "]";
  if (!number || !(*number >= lo && *number <= hi)) reject(name, value, range.str());
  return *number;
}

int parseInteger(const std::string& name, const std::string& value, int lo) {
  const std::optional<int> number = parseIntText(value);
  if (!number || *number < lo) {
    reject(name, value, lo == INT32_MIN ? "an integer" : "an integer >= " + std::to_string(lo));
  }
  return *number;
}

std::string formatNumber(float v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

// An option whose value is one of a fixed list of names, each mapped to an enum value.
template <typename Enum>
Entry enumOption(OptionInfo info, std::vector<std::pair<std::string, Enum>> names,
                 Enum ResolveOptions::*field) {
  std::string accepted;
  for (const auto& [text, value] : names) accepted += (accepted.empty() ? "" : "|") + text;
  info.values = accepted;
  Entry e{info, {}, {}};
  e.set = [names, field, accepted, name = info.name](ResolveOptions& o, const std::string& v) {
    for (const auto& [text, value] : names) {
      if (text == v) {
        o.*field = value;
        return;
      }
    }
    reject(name, v, "one of " + accepted);
  };
  e.get = [names, field](const ResolveOptions& o) {
    for (const auto& [text, value] : names) {
      if (o.*field == value) return text;
    }
    return std::string("?");
  };
  return e;
}

Entry numberOption(OptionInfo info, float lo, float hi, float ResolveOptions::*field) {
  info.values = formatNumber(lo) + ".." + (std::isinf(hi) ? std::string("") : formatNumber(hi));
  Entry e{info, {}, {}};
  e.set = [field, lo, hi, name = info.name](ResolveOptions& o, const std::string& v) {
    o.*field = parseNumber(name, v, lo, hi);
  };
  e.get = [field](const ResolveOptions& o) { return formatNumber(o.*field); };
  return e;
}

// A number of the window resolve's settings (ResolveOptions::window).
Entry windowNumberOption(OptionInfo info, float lo, float hi, float WindowOptions::*field) {
  info.values = formatNumber(lo) + ".." + (std::isinf(hi) ? std::string("") : formatNumber(hi));
  Entry e{info, {}, {}};
  e.set = [field, lo, hi, name = info.name](ResolveOptions& o, const std::string& v) {
    o.window.*field = parseNumber(name, v, lo, hi);
  };
  e.get = [field](const ResolveOptions& o) { return formatNumber(o.window.*field); };
  return e;
}

// A count of frames each side, 0..24, of the window resolve (ResolveOptions::window).
Entry windowIntegerOption(OptionInfo info, int most, int WindowOptions::*field) {
  Entry e{info, {}, {}};
  e.set = [field, most, name = info.name](ResolveOptions& o, const std::string& v) {
    const int k = parseInteger(name, v, 0);
    if (k > most) reject(name, v, "an integer in [0, " + std::to_string(most) + "]");
    o.window.*field = k;
  };
  e.get = [field](const ResolveOptions& o) { return std::to_string(o.window.*field); };
  return e;
}

// An on|off setting; `flag(options)` is the bool it sets (a generic lambda: it is called on
// const options too).
template <typename Flag>
Entry onOffOption(OptionInfo info, Flag flag) {
  info.values = "on|off";
  Entry e{info, {}, {}};
  e.set = [flag, name = info.name](ResolveOptions& o, const std::string& v) {
    if (v == "on" || v == "1") {
      flag(o) = true;
    } else if (v == "off" || v == "0") {
      flag(o) = false;
    } else {
      reject(name, v, "on or off");
    }
  };
  e.get = [flag](const ResolveOptions& o) { return std::string(flag(o) ? "on" : "off"); };
  return e;
}

// An on|off setting of the window resolve (ResolveOptions::window).
Entry windowSwitchOption(OptionInfo info, bool WindowOptions::*field) {
  return onOffOption(std::move(info), [field](auto& o) -> auto& { return o.window.*field; });
}

Entry switchOption(OptionInfo info, bool ResolveOptions::*field) {
  return onOffOption(std::move(info), [field](auto& o) -> auto& { return o.*field; });
}

Entry textOption(OptionInfo info, std::string ColorOptions::*field) {
  info.values = "name";
  Entry e{info, {}, {}};
  e.set = [field](ResolveOptions& o, const std::string& v) { o.color.*field = v; };
  e.get = [field](const ResolveOptions& o) { return o.color.*field; };
  return e;
}

const float kNoLimit = INFINITY;

std::vector<Entry> makeEntries() {
  std::vector<Entry> entries;
  entries.push_back(enumOption<ResolveMode>(
      {"mode", "Mode", "", "", "history: each frame blended into a reprojected history "
       "(recursive, game-engine TAA); window: each frame rebuilt from the raw samples of frames "
       "t-K..t+K carried along their own motion (offline; frames independent, any chunking "
       "gives the same frames)"},
      {{"history", ResolveMode::History}, {"window", ResolveMode::Window}},
      &ResolveOptions::mode));
  entries.push_back(windowIntegerOption(
      {"window", "Mode", "0..24", "", "window mode: K, the frames used on each side of the "
       "resolved frame at most (2K+1 kept in memory); stops at the shot's ends"},
      kMaxWindowRadius, &WindowOptions::radius));
  entries.push_back(windowIntegerOption(
      {"window-near", "Mode", "0..24", "", "window mode: frames each side used unless a fifth "
       "of a 32 px tile rejects them (the nearest always); each tile's window reaches farther "
       "(up to --window) while those frames agree with t over the tile (0: the whole window "
       "everywhere)"},
      kMaxWindowRadius, &WindowOptions::nearRadius));
  entries.push_back(windowIntegerOption(
      {"window-moving", "Mode", "0..24", "", "window mode: frames each side whose moving "
       "samples count, and every sample of a pixel where t has a moving one (0: the whole "
       "window)"},
      kMaxWindowRadius, &WindowOptions::movingRadius));
  entries.push_back(windowIntegerOption(
      {"window-thin-search", "Mode", "0..8", "", "window mode: pixels each way around a pixel "
       "searched for a thin feature (a wire) its own 3x3 samples missed, whose samples the "
       "other frames are then asked for too (0 or 1: the 3x3 alone)"},
      WindowOptions::kMaxThinSearch, &WindowOptions::thinSearchRadius));
  entries.push_back(windowNumberOption(
      {"window-sigma", "Mode", "", "", "window mode: pixels, the Gaussian weighting a carried "
       "sample by its distance to the pixel centre; smaller is sharper and noisier"},
      0.05f, 4.0f, &WindowOptions::sigma));
  entries.push_back(windowNumberOption(
      {"window-falloff", "Mode", "", "", "window mode: frames, weight exp(-(distance/falloff)^2) "
       "by distance in time (0: every frame alike)"},
      0.0f, kNoLimit, &WindowOptions::falloff));
  entries.push_back(windowSwitchOption(
      {"window-taper", "Mode", "", "", "window mode: weigh frames by a Hann taper over the "
       "window, so frames enter and leave it gently (steadier output)"},
      &WindowOptions::taper));
  entries.push_back(windowNumberOption(
      {"window-colour-tolerance", "Mode", "", "", "window mode: standard deviations a carried "
       "sample may stray from what the pixel gathered from nearer frames; smaller keeps moving "
       "shadows and lights sharp, larger keeps more samples (0: off)"},
      0.0f, kNoLimit, &WindowOptions::colourTolerance));
  entries.push_back(windowNumberOption(
      {"window-region-tolerance", "Mode", "", "", "window mode: standard errors the luma mean "
       "of a frame's static samples over 6x6 pixels may stray from the resolved frame's own before "
       "that frame is left out there: keeps contact and moving shadows "
       "(0: off; off with passes)"},
      0.0f, kNoLimit, &WindowOptions::regionTolerance));
  entries.push_back(windowNumberOption(
      {"window-region-near-moving", "Mode", "", "", "window mode: the region test's standard "
       "errors near a moving object (within 16 px at 320x180, 96 at 1080p), where its contact "
       "shadow moves with it"},
      0.0f, kNoLimit, &WindowOptions::regionToleranceNearMoving));
  entries.push_back(windowNumberOption(
      {"window-settle", "Mode", "", "", "window mode: a pixel whose own samples and nearest "
       "four frames' agree within this fraction stops gathering: flat colour takes a fraction of "
       "the time (0: off)"},
      0.0f, 1.0f, &WindowOptions::settle));
  entries.push_back(windowNumberOption(
      {"window-own-fallback", "Mode", "", "", "window mode: near a moving object, weight of a "
       "pixel's own 3x3 samples of its surface under a 1 px Gaussian where it gathered little "
       "from other frames (a contact shadow moving with the object): less of the render's noise "
       "(0: off)"},
      0.0f, kNoLimit, &WindowOptions::ownFallback));
  entries.push_back(windowNumberOption(
      {"window-static-tolerance", "Mode", "", "", "window mode: pixels within which a sample's "
       "vector must agree with the camera for exact camera reprojection; others follow their "
       "vectors"},
      0.0f, kNoLimit, &WindowOptions::staticTolerance));
  entries.push_back(windowNumberOption(
      {"window-reconstruction-weight", "Mode", "", "", "window mode: weight of the frame's own "
       "filtered reconstruction, the fallback of pixels that gather little"},
      0.0f, kNoLimit, &WindowOptions::reconstructionWeight));
  entries.push_back(windowSwitchOption(
      {"window-linear", "Mode", "", "", "window mode: sum the samples in linear light (the "
       "colour tests still decide on a compressed luma) instead of the bracket's working space"},
      &WindowOptions::linear));
  entries.push_back(windowSwitchOption(
      {"window-opaque-moving", "Mode", "", "", "window mode: hide static samples that land "
       "inside a moving object at the resolved frame (a box on the floor stays opaque)"},
      &WindowOptions::opaqueMoving));
  entries.push_back(windowSwitchOption(
      {"window-strata", "Mode", "", "", "window mode: average the means of the four quadrants "
       "around the pixel centre, not every sample alike (samples land at random; every pass "
       "weighed alike)"},
      &WindowOptions::strata));
  entries.push_back(windowSwitchOption(
      {"window-two-clusters", "Mode", "", "", "window mode: where a pixel's own samples span "
       "two depths, average the near surface's samples and the far one's apart and mix them "
       "by the near one's coverage (edges and wires keep their width; every pass weighed "
       "alike)"},
      &WindowOptions::twoClusters));
  entries.push_back(windowSwitchOption(
      {"window-adaptive", "Mode", "", "", "window mode: end each side of a pixel's window at "
       "the first frame whose samples disagree with the nearer frames'"},
      &WindowOptions::adaptive));
  entries.push_back(enumOption<Reconstruction>(
      {"reconstruction", "Unjitter", "", "", "filter rebuilding each frame at pixel centres: "
       "blackman-harris is soft, lanczos2 sharper with slight ringing, centre takes the pixel's "
       "own sample"},
      {{"blackman-harris", Reconstruction::BlackmanHarris},
       {"lanczos2", Reconstruction::Lanczos2},
       {"centre", Reconstruction::Centre}},
      &ResolveOptions::reconstruction));
  entries.push_back(switchOption({"anti-ringing", "Unjitter", "", "",
                                  "keep the reconstruction within its 3x3 samples' range: no "
                                  "halos or negative values beside bright edges, a little softer"},
                                 &ResolveOptions::antiRinging));
  {
    Entry e{{"jitter", "Unjitter", "halton|none", "", "the renderer's per-frame sample offset: "
             "Halton(2,3) indexed by frame number, or none"}, {}, {}};
    e.set = [](ResolveOptions& o, const std::string& v) {
      if (v == "halton") {
        o.jitter.source = JitterSource::Halton;
      } else if (v == "none") {
        o.jitter.source = JitterSource::None;
      } else {
        reject("jitter", v, "one of halton|none");
      }
    };
    e.get = [](const ResolveOptions& o) {
      return std::string(o.jitter.source == JitterSource::Halton ? "halton" : "none");
    };
    entries.push_back(e);
  }
  {
    Entry e{{"jitter-offset", "Unjitter", "integer", "", "Halton index = frame + offset"}, {}, {}};
    e.set = [](ResolveOptions& o, const std::string& v) {
      o.jitter.indexOffset = parseInteger("jitter-offset", v, INT32_MIN);
    };
    e.get = [](const ResolveOptions& o) { return std::to_string(o.jitter.indexOffset); };
    entries.push_back(e);
  }
  {
    Entry e{{"jitter-period", "Unjitter", "integer >= 0", "",
             "0: the index grows; P: it cycles through 1..P (engines use 8 or 16)"}, {}, {}};
    e.set = [](ResolveOptions& o, const std::string& v) {
      o.jitter.period = parseInteger("jitter-period", v, 0);
    };
    e.get = [](const ResolveOptions& o) { return std::to_string(o.jitter.period); };
    entries.push_back(e);
  }
  {
    Entry e{{"jitter-scale", "Unjitter", "0..", "",
             "image pixels per render pixel: Halton offsets are in the renderer's pixels, so "
             "images scaled after rendering need them scaled alike (0.5 at half size)"}, {}, {}};
    e.set = [](ResolveOptions& o, const std::string& v) {
      o.jitter.scale = parseNumber("jitter-scale", v, 0.0f, kNoLimit);
    };
    e.get = [](const ResolveOptions& o) { return formatNumber(o.jitter.scale); };
    entries.push_back(e);
  }
  entries.push_back(enumOption<MotionDilation>(
      {"motion-dilation", "Reprojection", "", "", "take motion from the closest-depth pixel of "
       "the 3x3 (box) or plus neighbourhood, so edges carry the foreground's motion; needs depth"},
      {{"box", MotionDilation::Box3x3}, {"plus", MotionDilation::Plus},
       {"centre", MotionDilation::Centre}},
      &ResolveOptions::motionDilation));
  entries.push_back(enumOption<CameraMotion>(
      {"camera-motion", "Reprojection", "", "", "motion from depth and camera matrices: fill "
       "uses it where vectors are missing or zero on the sky, prefer wherever it agrees with the "
       "vector, camera everywhere, vectors never"},
      {{"fill", CameraMotion::Fill}, {"prefer", CameraMotion::PreferCamera},
       {"camera", CameraMotion::Camera}, {"vectors", CameraMotion::Vectors}},
      &ResolveOptions::cameraMotion));
  entries.push_back(numberOption({"camera-agreement", "Reprojection", "", "",
                                  "pixels within which camera-motion prefer trusts the camera"},
                                 0.0f, kNoLimit, &ResolveOptions::cameraAgreement));
  entries.push_back(enumOption<HistoryFilter>(
      {"history-filter", "History", "", "", "resampling of history: catmull-rom stays sharp "
       "under motion, bilinear blurs a little more every frame"},
      {{"catmull-rom", HistoryFilter::CatmullRom}, {"bilinear", HistoryFilter::Bilinear}},
      &ResolveOptions::historyFilter));
  entries.push_back(numberOption({"depth-tolerance", "Validation", "", "",
                                  "relative depth change that rejects history as disoccluded "
                                  "(0: off); lower rejects more"},
                                 0.0f, kNoLimit, &ResolveOptions::depthTolerance));
  entries.push_back(enumOption<Rectify>(
      {"rectify", "Validation", "", "", "bring history into the neighbourhood's colour box: "
       "variance clip (tightest), clip toward the filtered colour, clamp per component, none "
       "(ghosts)"},
      {{"variance", Rectify::VarianceClip}, {"clip", Rectify::Clip}, {"clamp", Rectify::Clamp},
       {"none", Rectify::None}},
      &ResolveOptions::rectify));
  entries.push_back(enumOption<BoxSpace>(
      {"box-space", "Validation", "", "", "colour space of the neighbourhood box"},
      {{"ycocg", BoxSpace::YCoCg}, {"rgb", BoxSpace::RGB}}, &ResolveOptions::boxSpace));
  entries.push_back(enumOption<Neighbourhood>(
      {"neighbourhood", "Validation", "", "", "pixels forming the colour box: 3x3 (9) or plus (5)"},
      {{"9", Neighbourhood::Box9}, {"5", Neighbourhood::Plus5}}, &ResolveOptions::neighbourhood));
  entries.push_back(numberOption({"variance-gamma", "Validation", "", "",
                                  "width of the variance box in standard deviations; smaller "
                                  "ghosts less and flickers more"},
                                 0.01f, kNoLimit, &ResolveOptions::varianceGamma));
  entries.push_back(numberOption({"thin-hold", "Validation", "", "",
                                  "keep this much unrectified history where depth confirms the "
                                  "surface and motion is slow: saves sub-pixel wires, may ghost "
                                  "shading changes"},
                                 0.0f, 1.0f, &ResolveOptions::thinFeatureHold));
  entries.push_back(numberOption({"thin-hold-speed", "Validation", "", "",
                                  "pixels per frame at which the thin-feature hold fades out"},
                                 0.01f, kNoLimit, &ResolveOptions::thinFeatureHoldSpeed));
  entries.push_back(numberOption({"blend", "Blend", "", "",
                                  "weight of the current frame; smaller is smoother and slower "
                                  "to react"},
                                 0.001f, 1.0f, &ResolveOptions::blend));
  entries.push_back(numberOption({"velocity-blend", "Blend", "", "",
                                  "weight of the current frame at high speed (<= blend: off): "
                                  "sharper moving pixels, less accumulation there"},
                                 0.0f, 1.0f, &ResolveOptions::velocityBlend));
  entries.push_back(numberOption({"velocity-scale", "Blend", "", "",
                                  "pixels per frame at which velocity-blend is reached"},
                                 0.01f, kNoLimit, &ResolveOptions::velocityScale));
  entries.push_back(numberOption({"anti-flicker", "Blend", "", "",
                                  "where history and current luma agree, lower the current "
                                  "weight by this fraction: steadier, slower to settle"},
                                 0.0f, 1.0f, &ResolveOptions::antiFlicker));
  entries.push_back(switchOption({"luma-weighting", "Blend", "", "",
                                  "weight samples by 1/(1+luma) against HDR fireflies; dims "
                                  "highlights' contribution"},
                                 &ResolveOptions::lumaWeighting));
  entries.push_back(switchOption({"sample-count", "Blend", "", "",
                                  "current weight at least 1/samples: new and disoccluded "
                                  "pixels converge at once"},
                                 &ResolveOptions::sampleCount));
  entries.push_back(numberOption({"cut-detection", "Cuts", "", "",
                                  "history mode: fraction of rejected pixels that marks a cut "
                                  "and resets history (0: off; needs depth). Window mode "
                                  "takes cuts from --reset-frames"},
                                 0.0f, 1.0f, &ResolveOptions::cutDetection));
  entries.push_back(numberOption({"sharpen", "Output", "", "",
                                  "unsharp mask on the output only, limited to the neighbours' "
                                  "range"},
                                 0.0f, kNoLimit, &ResolveOptions::sharpen));
  entries.push_back(textOption({"ocio-config", "Tonemap bracket", "", "",
                                "OCIO config of the input and output colorspaces; empty: the "
                                "one $OCIO names when set, else taa's shipped config"},
                               &ColorOptions::ocioConfig));
  entries.push_back(textOption({"colorspace-in", "Tonemap bracket", "", "",
                                "colorspace or role of the input colour (e.g. ACEScg)"},
                               &ColorOptions::colorspaceIn));
  entries.push_back(textOption({"bracket", "Tonemap bracket", "", "",
                                "working space of the resolve: taa_reinhard or taa_log2 (taa's "
                                "own, in any config: applied to its scene_linear), a colorspace "
                                "or named transform of the config, or none"},
                               &ColorOptions::bracket));
  entries.push_back(textOption({"colorspace-out", "Tonemap bracket", "", "",
                                "colorspace or role of the output (empty: the input's)"},
                               &ColorOptions::colorspaceOut));
  const ResolveOptions defaults;
  for (Entry& e : entries) e.info.defaultValue = e.get(defaults);
  return entries;
}

const std::vector<Entry>& entries() {
  static const std::vector<Entry> all = makeEntries();
  return all;
}

const Entry* findEntry(const std::string& name) {
  for (const Entry& e : entries()) {
    if (e.info.name == name) return &e;
  }
  return nullptr;
}

}  // namespace

const std::vector<OptionInfo>& resolveOptionList() {
  static const std::vector<OptionInfo> list = [] {
    std::vector<OptionInfo> infos;
    for (const Entry& e : entries()) infos.push_back(e.info);
    return infos;
  }();
  return list;
}

bool isResolveOption(const std::string& name) { return findEntry(name) != nullptr; }

void setResolveOption(ResolveOptions& options, const std::string& name, const std::string& value) {
  const Entry* entry = findEntry(name);
  if (!entry) throw Error("unknown resolve option \"" + name + "\"");
  entry->set(options, value);
}

std::string resolveOptionValue(const ResolveOptions& options, const std::string& name) {
  const Entry* entry = findEntry(name);
  if (!entry) throw Error("unknown resolve option \"" + name + "\"");
  return entry->get(options);
}

}  // namespace taa
