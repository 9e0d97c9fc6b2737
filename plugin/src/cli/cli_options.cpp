#include "cli/cli_options.h"

#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "io/sequence_pattern.h"
#include "io/sequence_scan.h"
#include "resolve/option_registry.h"
#include "taa/error.h"

namespace taa::cli {
namespace {

float parseFloat(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  float value = 0.0f;
  try {
    value = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value)) {
    throw Error(option + " expects a number, got \"" + text + "\"");
  }
  return value;
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

// Channel and file choices for depth/motion, applied after all options are read so that
// their order on the command line does not matter.
struct AovArgs {
  std::optional<std::string> pattern, channels;
};

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  CommandLine cl;
  io::AovLayout& layout = cl.job.layout;
  std::string colorChannels = "R,G,B,A";
  AovArgs depth, motion;
  std::string preset, layer = "ViewLayer";
  std::vector<std::string> positional;

  using Handler = std::function<void(const std::string&)>;
  const std::map<std::string, Handler> withValue = {
      {"--frames", [&](const std::string& v) { cl.framesText = v; }},
      {"--color", [&](const std::string& v) { positional.push_back(v); }},
      {"--depth", [&](const std::string& v) { depth.pattern = v; }},
      {"--motion", [&](const std::string& v) { motion.pattern = v; }},
      {"--color-ch", [&](const std::string& v) { colorChannels = v; }},
      {"--depth-ch", [&](const std::string& v) { depth.channels = v; }},
      {"--motion-ch", [&](const std::string& v) { motion.channels = v; }},
      {"--preset", [&](const std::string& v) { preset = choice("--preset", v, {"cycles"}); }},
      {"--layer", [&](const std::string& v) { layer = v; }},
      {"--motion-y",
       [&](const std::string& v) {
         layout.motionConvention.yUp = choice("--motion-y", v, {"up", "down"}) == "up";
       }},
      {"--motion-to",
       [&](const std::string& v) {
         layout.motionConvention.toPrevious =
             choice("--motion-to", v, {"previous", "next"}) == "previous";
       }},
      {"--motion-scale",
       [&](const std::string& v) { layout.motionConvention.scale = parseFloat("--motion-scale", v); }},
      {"--depth-nohit",
       [&](const std::string& v) {
         layout.depthConvention.noHitAbove = parseFloat("--depth-nohit", v);
       }},
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
  };

  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
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

  if (preset == "cycles") {
    const io::AovLayout cycles = io::cyclesLayout(positional[0], layer);
    layout.color = cycles.color;
    layout.depth = cycles.depth;
    layout.motion = cycles.motion;
    layout.motionConvention = cycles.motionConvention;
    layout.depthConvention = cycles.depthConvention;
  } else {
    layout.color = {positional[0], io::parseChannelList(colorChannels)};
  }
  // Explicit flags override the preset field by field.
  auto applyAov = [](std::optional<io::AovSource>& aov, const AovArgs& given,
                     const char* defaultChannels) {
    if (!given.pattern && !given.channels) return;
    if (!aov) aov = io::AovSource{"", io::parseChannelList(defaultChannels)};
    if (given.pattern) aov->pattern = *given.pattern;
    if (given.channels) aov->channels = io::parseChannelList(*given.channels);
  };
  applyAov(layout.depth, depth, "Z");
  applyAov(layout.motion, motion, "X,Y");
  if (layout.color.channels.size() < 3 || layout.color.channels.size() > 4) {
    throw Error("--color-ch expects 3 or 4 channel names, got " + colorChannels);
  }
  if (layout.depth && layout.depth->channels.size() != 1) {
    throw Error("--depth-ch expects 1 channel name");
  }
  if (layout.motion && layout.motion->channels.size() != 2) {
    throw Error("--motion-ch expects 2 channel names (x, y)");
  }
  return cl;
}

void resolveFrameList(CommandLine& cl) {
  const std::string& pattern = cl.job.layout.color.pattern;
  if (!cl.framesText.empty()) {
    cl.job.frames = io::parseFrameRange(cl.framesText);
  } else if (io::hasFramePlaceholder(pattern)) {
    cl.job.frames = io::scanExistingFrames(pattern);
    if (cl.job.frames.empty()) throw Error("no frames found for the color pattern", {pattern});
  } else {
    cl.job.frames = {0};  // a single file: frame number 0 for jitter unless --frames says
  }
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
  --frames RANGE           frames to resolve: 1-48, 1-48x2, 1-10,20-30 (default: all found)
  -o PATTERN               output sequence (written atomically: temp file, then rename)

AOVs and channels:
  --color-ch R,G,B,A       color channel names, 3 or 4 (default R,G,B,A; missing A reads as 1)
  --depth PATTERN          depth files (default: none; the color file if --depth-ch is given)
  --depth-ch NAME          depth channel (default Z)
  --motion PATTERN         motion-vector files (default: none; the color file if --motion-ch)
  --motion-ch X,Y          motion channel names (default X,Y)
  --preset cycles          Blender Cycles multi-layer EXR: <layer>.Combined.RGBA,
                           <layer>.Depth.Z, <layer>.Vector.XY, all in the color file
  --layer NAME             render layer name for --preset (default ViewLayer)

Conventions (internal: motion in pixels, y down, pointing to the previous frame):
  --motion-y up|down       y axis direction of the motion AOV (default down; cycles: up)
  --motion-to previous|next  where the vectors point (default previous)
  --motion-scale S         multiply vectors by S (default 1)
  --depth-nohit V          depth at or above V means nothing was hit (default 1e9)

@RESOLVE_OPTIONS@
Sequences and cuts:
  --reset-frames LIST      frames that start a new history (cuts): 1040,1100-1101
  --debug-layers           add layers debug.historyWeight, debug.rejection (0 kept, 1 none,
                           2 off-screen, 3 disoccluded), debug.velocity.x/y, debug.nonFinite

Output:
  -d half|float            output pixel type (default half)
  --compression NAME       none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab (default zip)

GL and diagnostics:
  --gl auto|egl|osmesa     OpenGL back end (default auto: EGL, falling back to OSMesa)
  --info                   print GL vendor/renderer/version, OCIO and OIIO versions
  --list-brackets          list the tonemap brackets the active OCIO config offers
  --list-options           the resolve options as a Markdown table
  -v                       one line per frame
  -q                       errors only
  -h, --help               this text

Errors are printed as "taatool ERROR: <what> : <file> (frame N, channel C)"; exit status 1.
)help";
  text.replace(text.find("@RESOLVE_OPTIONS@"), 17, resolveOptionsHelp());
  return text;
}

}  // namespace taa::cli
