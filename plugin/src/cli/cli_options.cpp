#include "cli/cli_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "cli/input_report.h"
#include "cli/option_effects.h"
#include "cli/view_selection.h"
#include "color/ocio_bracket.h"
#include "io/nearest_files.h"
#include "io/renderer_presets.h"
#include "io/sequence_pattern.h"
#include "io/sequence_scan.h"
#include "resolve/option_registry.h"
#include "taa/error.h"
#include "util/number_text.h"

namespace taa::cli {
namespace {

float parseFloat(const std::string& option, const std::string& text) {
  const std::optional<float> value = parseFloatText(text);
  if (!value) throw Error(option + " expects a number, got \"" + text + "\"");
  return *value;
}

std::string choice(const std::string& option, const std::string& text,
                   const std::vector<std::string>& choices) {
  for (const auto& c : choices) {
    if (text == c) return text;
  }
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  throw Error(option + " expects one of " + list + ", got \"" + text + "\"");
}

// "inf" or a number (for --depth-far with reversed-Z).
double parseDistance(const std::string& option, const std::string& text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  const float value = parseFloat(option, text);
  if (value <= 0.0f) throw Error(option + " expects a positive distance, got \"" + text + "\"");
  return value;
}

template <typename Enum>
Enum named(const std::string& option, const std::string& text,
           const std::vector<std::pair<std::string, Enum>>& names) {
  std::vector<std::string> choices;
  for (const auto& [name, value] : names) {
    if (text == name) return value;
    choices.push_back(name);
  }
  choice(option, text, choices);  // throws, listing the choices
  return names.front().second;
}

// Channel, file and part choices for an AOV, applied after all options are read so that
// their order on the command line does not matter.
struct AovArgs {
  std::optional<std::string> pattern, channels, part;
};

// Sets the job's jitter source from --jitter: header:ATTR and sidecar are job-level sources;
// anything else is the resolve option (halton, none).
void setJitter(SequenceJob& job, const std::string& value) {
  const std::string header = "header:";
  if (value.rfind(header, 0) == 0 && value.size() > header.size()) {
    job.jitterSource = JobJitterSource::HeaderAttribute;
    job.jitterAttribute = value.substr(header.size());
  } else if (value == "sidecar") {
    job.jitterSource = JobJitterSource::Sidecar;
  } else {
    try {
      setResolveOption(job.resolve, "jitter", value);
    } catch (const Error& e) {
      throw Error(e.description() + " (or header:ATTRIBUTE, sidecar)");
    }
    job.jitterSource = JobJitterSource::Options;
  }
}

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  CommandLine cl;
  io::AovLayout& layout = cl.job.layout;
  std::optional<std::string> colorChannels, colorPart;
  AovArgs depth, motion;
  std::string preset, layer = "ViewLayer";
  std::vector<std::string> positional;
  // Convention flags edit the layout after the preset, so they always win over it.
  using LayoutEdit = std::function<void(io::AovLayout&)>;
  std::vector<LayoutEdit> edits;
  std::vector<io::ChannelKindRule> aovRules;  // --aov, in the order given
  auto edit = [&](LayoutEdit e) { edits.push_back(std::move(e)); };

  using Handler = std::function<void(const std::string&)>;
  const std::map<std::string, Handler> withValue = {
      {"--frames", [&](const std::string& v) { cl.framesText = v; }},
      {"--color", [&](const std::string& v) { positional.push_back(v); }},
      {"--depth", [&](const std::string& v) { depth.pattern = v; }},
      {"--motion", [&](const std::string& v) { motion.pattern = v; }},
      {"--color-ch", [&](const std::string& v) { colorChannels = v; }},
      {"--depth-ch", [&](const std::string& v) { depth.channels = v; }},
      {"--motion-ch", [&](const std::string& v) { motion.channels = v; }},
      {"--color-part", [&](const std::string& v) { colorPart = v; }},
      {"--depth-part", [&](const std::string& v) { depth.part = v; }},
      {"--motion-part", [&](const std::string& v) { motion.part = v; }},
      {"--preset",
       [&](const std::string& v) {
         io::presetLayout(v, "check");  // throws for an unknown name, listing the known ones
         preset = v;
       }},
      {"--layer", [&](const std::string& v) { layer = v; }},
      {"--view", [&](const std::string& v) { cl.viewText = v; }},
      {"--motion-y",
       [&](const std::string& v) {
         const bool up = choice("--motion-y", v, {"up", "down"}) == "up";
         edit([up](io::AovLayout& l) { l.motionConvention.yUp = up; });
       }},
      {"--motion-to",
       [&](const std::string& v) {
         const bool previous = choice("--motion-to", v, {"previous", "next"}) == "previous";
         edit([previous](io::AovLayout& l) { l.motionConvention.toPrevious = previous; });
       }},
      {"--motion-scale",
       [&](const std::string& v) {
         const float scale = parseFloat("--motion-scale", v);
         edit([scale](io::AovLayout& l) { l.motionConvention.scale = scale; });
       }},
      {"--motion-units",
       [&](const std::string& v) {
         const auto units = named<io::MotionUnits>("--motion-units", v,
                                                   {{"pixels", io::MotionUnits::Pixels},
                                                    {"ndc", io::MotionUnits::Ndc},
                                                    {"uv", io::MotionUnits::Uv}});
         edit([units](io::AovLayout& l) { l.motionConvention.units = units; });
       }},
      {"--motion-encoding",
       [&](const std::string& v) {
         const auto encoding = named<io::MotionEncoding>(
             "--motion-encoding", v,
             {{"signed", io::MotionEncoding::Signed}, {"centred", io::MotionEncoding::Centred}});
         edit([encoding](io::AovLayout& l) { l.motionConvention.encoding = encoding; });
       }},
      {"--motion-max",
       [&](const std::string& v) {
         const float max = parseFloat("--motion-max", v);
         edit([max](io::AovLayout& l) { l.motionConvention.centredMax = max; });
       }},
      {"--depth-kind",
       [&](const std::string& v) {
         const auto kind = named<io::DepthKind>("--depth-kind", v,
                                                {{"planar", io::DepthKind::Planar},
                                                 {"radial", io::DepthKind::Radial},
                                                 {"ndc", io::DepthKind::Ndc},
                                                 {"reversed-z", io::DepthKind::ReversedZ},
                                                 {"inverse", io::DepthKind::Inverse}});
         edit([kind](io::AovLayout& l) { l.depthConvention.kind = kind; });
       }},
      {"--depth-near",
       [&](const std::string& v) {
         const double nearPlane = parseDistance("--depth-near", v);
         edit([nearPlane](io::AovLayout& l) { l.depthConvention.nearPlane = nearPlane; });
       }},
      {"--depth-far",
       [&](const std::string& v) {
         const double farPlane = parseDistance("--depth-far", v);
         edit([farPlane](io::AovLayout& l) { l.depthConvention.farPlane = farPlane; });
       }},
      {"--depth-fov",
       [&](const std::string& v) {
         const float fov = parseFloat("--depth-fov", v);
         if (fov <= 0.0f || fov >= 180.0f) {
           throw Error("--depth-fov expects degrees in (0, 180), got \"" + v + "\"");
         }
         edit([fov](io::AovLayout& l) { l.depthConvention.horizontalFovDegrees = fov; });
       }},
      {"--depth-nohit",
       [&](const std::string& v) {
         const float noHit = parseFloat("--depth-nohit", v);
         edit([noHit](io::AovLayout& l) { l.depthConvention.noHitAbove = noHit; });
       }},
      {"--ndc",
       [&](const std::string& v) {
         cl.job.ndc = named<NdcConvention>(
             "--ndc", v,
             {{"zero-one-y-down", NdcConvention::ZeroOneYDown},
              {"minus-one-one-y-up", NdcConvention::MinusOneOneYUp}});
       }},
      {"--camera-sidecar", [&](const std::string& v) { cl.job.cameraSidecar = v; }},
      {"--jitter", [&](const std::string& v) { setJitter(cl.job, v); }},
      {"--out-ch", [&](const std::string& v) { cl.job.outputChannels = io::parseChannelList(v); }},
      {"--passthrough",
       [&](const std::string& v) {
         for (const std::string& p : io::parseChannelList(v)) layout.passthrough.push_back(p);
       }},
      {"--aov", [&](const std::string& v) { aovRules.push_back(io::parseChannelKindRule(v)); }},
      {"--reset-frames",
       [&](const std::string& v) {
         for (int frame : io::parseFrameRange(v)) cl.job.resetFrames.insert(frame);
       }},
      {"-o", [&](const std::string& v) { cl.job.outputPattern = v; }},
      {"-d", [&](const std::string& v) { cl.job.write.pixelType = io::parsePixelType(v); }},
      {"--compression",
       [&](const std::string& v) {
         io::validateCompression(v);
         cl.job.write.compression = v;
       }},
      {"--gl", [&](const std::string& v) { cl.job.backend = gl::parseBackend(v); }},
      {"--threads",
       [&](const std::string& v) {
         // Each frame in flight holds its AOVs in memory: more than a few buy nothing.
         const std::optional<int> threads = parseIntText(v);
         if (!threads || *threads < 0 || *threads > kMaxIoThreads) {
           throw Error("--threads expects an integer from 0 to " + std::to_string(kMaxIoThreads) +
                       ", got \"" + v + "\"");
         }
         cl.job.ioThreads = *threads;
       }},
  };
  const std::map<std::string, std::function<void()>> flags = {
      {"--help", [&] { cl.help = true; }},
      {"-h", [&] { cl.help = true; }},
      {"--info", [&] { cl.info = true; }},
      {"--list-brackets", [&] { cl.listBrackets = true; }},
      {"--list-options", [&] { cl.listOptions = true; }},
      {"-v", [&] { cl.verbosity = Verbosity::Verbose; }},
      {"-q", [&] { cl.verbosity = Verbosity::Quiet; }},
      {"--debug-layers", [&] { cl.job.debugLayers = true; }},
      {"--skip-missing", [&] { cl.skipMissing = true; }},
      {"--strict", [&] { cl.strict = true; }},
  };

  std::set<std::string> typed;  // the options on the command line, for requireOptionsTakeEffect
  for (const auto& flag : flags) {
    if (!isSwitchOption(flag.first)) throw std::logic_error("switch " + flag.first + " unlisted");
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() > 1 && arg[0] == '-') typed.insert(arg);
    if (auto flag = flags.find(arg); flag != flags.end()) {
      flag->second();
    } else if (auto option = withValue.find(arg); option != withValue.end()) {
      if (i + 1 >= args.size()) throw Error("option " + arg + " needs a value");
      option->second(args[++i]);
    } else if (arg.rfind("--", 0) == 0 && isResolveOption(arg.substr(2))) {
      if (i + 1 >= args.size()) throw Error("option " + arg + " needs a value");
      setResolveOption(cl.job.resolve, arg.substr(2), args[++i]);
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw Error("unknown option " + arg + " (see taatool --help)");
    } else {
      positional.push_back(arg);
    }
  }
  if (cl.help || cl.info || cl.listBrackets || cl.listOptions) return cl;

  if (positional.empty()) throw Error("no color input given (see taatool --help)");
  if (positional.size() > 1) {
    throw Error("more than one color input given: \"" + positional[0] + "\" and \"" +
                positional[1] + "\"");
  }

  const std::vector<std::string> passthrough = layout.passthrough;
  if (!preset.empty()) {
    layout = io::presetLayout(preset, positional[0], layer);
    layout.passthrough = passthrough;
  } else {
    layout.color = {positional[0], {"R", "G", "B", "A"}, ""};
  }
  if (colorChannels) layout.color.channels = io::parseChannelList(*colorChannels);
  if (colorPart) layout.color.part = *colorPart;
  // Explicit flags override the preset field by field.
  auto applyAov = [](std::optional<io::AovSource>& aov, const AovArgs& given,
                     const char* defaultChannels) {
    if (!given.pattern && !given.channels && !given.part) return;
    if (!aov) aov = io::AovSource{"", io::parseChannelList(defaultChannels), ""};
    if (given.pattern) aov->pattern = *given.pattern;
    if (given.channels) aov->channels = io::parseChannelList(*given.channels);
    if (given.part) aov->part = *given.part;
  };
  applyAov(layout.depth, depth, "Z");
  applyAov(layout.motion, motion, "X,Y");
  for (const LayoutEdit& e : edits) e(layout);
  if (layout.color.channels.size() < 3 || layout.color.channels.size() > 4) {
    throw Error("--color-ch expects 3 or 4 channel names, got " + colorChannels.value_or(""));
  }
  if (layout.depth && layout.depth->channels.size() != 1) {
    throw Error("--depth-ch expects 1 channel name");
  }
  if (layout.motion && layout.motion->channels.size() != 2) {
    throw Error("--motion-ch expects 2 channel names (x, y)");
  }
  if (!cl.job.outputChannels.empty() && cl.job.outputChannels.size() != 4) {
    throw Error("--out-ch expects 4 channel names (R, G, B, A)");
  }
  // Every channel of the colour part beside the colour is resolved by its kind in the window
  // mode (issue 21); the history mode writes the colour alone and refuses to be asked for more.
  layout.passRules = aovRules;
  if (cl.job.resolve.mode == ResolveMode::Window) {
    layout.passes = true;
  } else if (!aovRules.empty()) {
    throw Error("--aov: passes are resolved beside the colour by the window mode only "
                "(--mode window); the history mode writes the colour alone");
  }
  requireOptionsTakeEffect(typed, preset, cl.job);
  return cl;
}

bool isSwitchOption(const std::string& option) {
  static const std::set<std::string> switches = {
      "--help", "-h",  "--info", "--list-brackets", "--list-options", "-v",
      "-q",     "--debug-layers", "--skip-missing", "--strict"};
  return switches.count(option) > 0;
}

void resolveFrameList(CommandLine& cl) {
  const std::string& pattern = cl.job.layout.color.pattern;
  if (!cl.framesText.empty()) {
    cl.job.frames = io::parseFrameRange(cl.framesText);
    if (cl.skipMissing && io::hasFramePlaceholder(pattern)) {
      // Frames asked for whose colour file is not there are skipped too, and reported.
      std::vector<int> present;
      cl.missingFrames.clear();
      for (int frame : cl.job.frames) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(io::expandFramePattern(pattern, frame), ec);
        (exists ? present : cl.missingFrames).push_back(frame);
      }
      if (present.empty()) {
        throw Error("none of the frames " + cl.framesText + " exists", {pattern});
      }
      cl.job.frames = std::move(present);
    }
  } else if (io::hasFramePlaceholder(pattern)) {
    cl.job.frames = io::scanExistingFrames(pattern);
    if (cl.job.frames.empty()) {
      throw Error("no frames found for the color pattern: " + io::patternMissText(pattern),
                  {pattern});
    }
    cl.missingFrames.clear();
    for (std::size_t i = 1; i < cl.job.frames.size(); ++i) {
      for (int f = cl.job.frames[i - 1] + 1; f < cl.job.frames[i]; ++f) {
        cl.missingFrames.push_back(f);
      }
    }
    // A gap changes the result (history restarts after it) and is usually a render that failed:
    // not silently, as oiiotool's --skip-bad-frames is not silent either.
    if (!cl.missingFrames.empty() && !cl.skipMissing) {
      const int first = cl.missingFrames.front();
      throw Error(std::to_string(cl.missingFrames.size()) + " frame" +
                      (cl.missingFrames.size() == 1 ? "" : "s") + " missing from the sequence " +
                      std::to_string(cl.job.frames.front()) + "-" +
                      std::to_string(cl.job.frames.back()) + ": " +
                      frameListText(cl.missingFrames) +
                      " (--skip-missing resolves around them, history restarting after each gap)",
                  {io::expandFramePattern(pattern, first), first, ""});
    }
  } else {
    // A single file is the frame its name carries (shot.0001.exr: frame 1, for its Halton
    // jitter and its sidecar entry), else 0; --frames says otherwise.
    cl.job.frames = {io::frameNumberInFileName(pattern).value_or(0)};
  }
  // The window resolve reads the frames around each resolved one that exist on disk.
  if (cl.job.resolve.mode == ResolveMode::Window && io::hasFramePlaceholder(pattern)) {
    cl.job.availableFrames = availableInputFrames(cl.job.layout);
  }
  selectViews(cl);
}

// `words` wrapped to lines of at most `width` columns, each after `indent` spaces.
std::string wrapped(const std::string& words, std::size_t indent, std::size_t width) {
  std::string text, line;
  std::istringstream in(words);
  for (std::string word; in >> word;) {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      text += std::string(indent, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) text += std::string(indent, ' ') + line + "\n";
  return text;
}

// The resolve options' part of --help, grouped by topic, from the option registry.
std::string resolveOptionsHelp() {
  constexpr std::size_t kColumn = 27, kWidth = 100;
  std::string text, topic;
  for (const OptionInfo& o : resolveOptionList()) {
    if (o.topic != topic) {
      topic = o.topic;
      text += (text.empty() ? "" : "\n") + topic + ":\n";
    }
    const std::string head = "  --" + o.name + " " + o.values;
    const std::string help = o.help + " (default " +
                             (o.defaultValue.empty() ? "\"\"" : o.defaultValue) + ")";
    std::string body = wrapped(help, kColumn, kWidth);
    if (head.size() < kColumn) {
      body.replace(0, head.size(), head);
    } else {
      body = head + "\n" + body;
    }
    text += body;
  }
  return text + "\n";
}

std::string optionsMarkdownTable() {
  auto escaped = [](std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) {
      text.replace(at, 1, "\\|");
    }
    return text;
  };
  std::string table = "| option | values | default | what it does and trades |\n|---|---|---|---|\n";
  for (const OptionInfo& o : resolveOptionList()) {
    table += "| `--" + o.name + "` | " + escaped(o.values) + " | " +
             (o.defaultValue.empty() ? "(empty)" : escaped(o.defaultValue)) + " | " +
             escaped(o.help) + " |\n";
  }
  return table;
}

std::string helpText() {
  std::string text = R"help(taatool -- temporal anti-aliasing resolve for EXR AOV sequences (taa )help"
         TAA_VERSION_STRING R"help()

Usage:
  taatool [options] COLOR_PATTERN -o OUTPUT_PATTERN
  taatool --info [--gl auto|egl|osmesa]

Sequences:
  COLOR_PATTERN            the jittered beauty sequence. Frame placeholders: '#' (4 digits),
                           '####' or '@@@@' (one digit per character), '%04d'
  --frames RANGE           frames to resolve, ascending: 1-48, 1-48x2, 1-10,20-30 (default:
                           all found; a gap among them is an error unless --skip-missing)
  --skip-missing           resolve around frames missing from the sequence found on disk
                           (history restarts after each gap; reported with the frames)
  -o PATTERN               output sequence (written atomically: temp file, then rename)

AOVs and channels:
  --color-ch R,G,B,A       color channel names, 3 or 4 (default R,G,B,A; missing A reads as 1)
  --depth PATTERN          depth files (default: none; the color file if --depth-ch is given)
  --depth-ch NAME          depth channel (default Z)
  --motion PATTERN         motion-vector files (default: none; the color file if --motion-ch)
  --motion-ch X,Y          motion channel names (default X,Y)
  --color-part NAME        multi-part EXR: the part holding color (default: the first part
                           that has the channels)
  --depth-part NAME        multi-part EXR: the part holding depth (likewise)
  --motion-part NAME       multi-part EXR: the part holding motion (likewise)
  --preset NAME            a renderer's channel names and conventions, NAME one of
                           @PRESETS@.
                           Every channel or convention flag overrides the preset field by
                           field; README "Renderer presets" says what is verified.
                           Example: --preset cycles --layer RL
  --layer NAME             render layer name for --preset cycles (default ViewLayer)
  --view NAME|all          a multi-view (stereo) EXR's views to resolve (default all): each
                           as if alone, written back as one multi-view file; the channels of
                           view V are the layout's with V before their last component
                           (ViewLayer.Combined.left.R), or the part whose view is V

Conventions (internal: motion in pixels, y down, pointing to the previous frame; depth planar):
  --motion-units pixels|ndc|uv  units of the motion AOV: pixels; ndc ([-1, 1] across the display
                           window); uv ([0, 1] across it) (default pixels)
  --motion-encoding signed|centred  centred: 0.5 = no motion, value = 0.5 + motion / (2 max)
  --motion-max M           centred: the motion (in --motion-units) a value of 1 stands for (1)
  --motion-y up|down       y axis direction of the motion AOV (default down; cycles: up)
  --motion-to previous|next  where the vectors point (default previous; next: forward in time)
  --motion-scale S         multiply vectors by S (default 1)
  --depth-kind KIND        planar | radial (distance along the ray) | ndc (0 near, 1 far) |
                           reversed-z (1 near, 0 far) | inverse (1/z) (default planar)
  --depth-near N           near plane for ndc and reversed-z depth (default 0.1)
  --depth-far F            far plane for ndc and reversed-z depth; reversed-z takes inf (1e4)
  --depth-fov DEGREES      radial depth without camera matrices: horizontal field of view of a
                           centred pinhole camera over the display window
  --depth-nohit V          planar depth at or above V means nothing was hit (default 1e9)

Camera and jitter:
  (default: each frame's camera and jitter from the color header's camera note, the string
  attribute Note that taa's Blender add-on writes, where it has one; else the header's
  worldToCamera/worldToNDC and the --jitter option's Halton(2,3); -v says which)
  --ndc zero-one-y-down|minus-one-one-y-up  NDC of the headers' worldToNDC (default
                           zero-one-y-down: RenderMan's NDC, (0, 0) top left)
  --camera-sidecar FILE    JSON per frame: view and projection (OpenGL, column-major) and
                           jitter (px, y down); replaces header matrices and the camera
                           note's (docs/ARCHITECTURE.md)
  --jitter header:ATTR     each frame's jitter from the color header's float[2] attribute ATTR
                           in pixels, y down (e.g. header:taa:jitter)
  --jitter sidecar         each frame's jitter from --camera-sidecar, every entry must have one
                           (without --jitter: the sidecar entry's jitter where it has one, else
                           the camera note's, else Halton; --jitter halton|none ignores both)

@RESOLVE_OPTIONS@
Sequences and cuts:
  --reset-frames LIST      frames that start a new history (cuts): 1040,1100-1101
  --debug-layers           add layers debug.historyWeight, debug.rejection (0 kept, 1 none,
                           2 off-screen, 3 disoccluded), debug.velocity.x/y, debug.nonFinite

Output (channel names, windows and metadata of the color input are kept, plus taa:version and
taa:options, the resolve options used):
  -d half|float|input      output pixel type (default input: the color input's)
  --out-ch R,G,B,A         output color channel names (default: the color input's names)
  --passthrough PATTERNS   copy channels of the color file (part) whose names match these
                           comma-separated globs untouched into the output: 'ViewLayer.*,*.Z'
  --aov PATTERN=KIND       (window mode) the kind of the channels matching a glob, first match
                           wins: light, factor, average, normal, nearest, cryptomatte, copy,
                           drop. Without it every channel of the color part beside the color
                           is resolved by the kind its pass name has (light passes with the
                           beauty's weights, data never blended); '*=drop' writes the color
                           alone
  --compression NAME       none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab (default zip);
                           zip and zips are zlib level 1 (fast), zip:N picks level N (1-9)

Input checks (reported on stderr with counts at the end of a run):
  --strict                 make each report an error, before anything of its frame is written:
                           NaN/Inf colour or motion set to 0, float colour clamped to a half
                           output's range, a change of image size, frames skipped

GL and diagnostics:
  --gl auto|egl|osmesa     OpenGL back end (default auto: EGL, falling back to OSMesa)
  --threads N              frames read ahead and written behind while the GPU resolves
                           (default 2; when the window resolve carries passes, none read
                           ahead, each holding ~0.4 GB at 1080p with every pass, and the
                           write beside the pass draws, taking them band by band; 0: one
                           step after another; at most 16). Output is identical.
  --info                   print GL vendor/renderer/version, OCIO and OIIO versions
  --list-brackets          list the tonemap brackets the active OCIO config offers
  --list-options           the resolve options as a Markdown table
  -v                       one line per frame on stdout, with the rate and time left
  -q                       errors only (default: progress on stderr, one line rewritten on a
                           terminal, a line per frame otherwise, with the rate and time left)
  -h, --help               this text

Errors are printed as "taatool ERROR: <what> : <file> (frame N, channel C)"; exit status 1.
SIGINT or SIGTERM stops the run after the frames in flight are written (a second one at once);
exit status 130 or 143. Temporary files of runs that died (SIGKILL) are removed by the next run
over the same output.
)help";
  text.replace(text.find("@RESOLVE_OPTIONS@"), 17, resolveOptionsHelp());
  text.replace(text.find("@PRESETS@"), 9, io::presetNames());
  return text;
}

}  // namespace taa::cli
