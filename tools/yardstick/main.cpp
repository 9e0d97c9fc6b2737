// taa-yardstick: makes the quality scenes (Blender Cycles renders and analytic scenes, both
// cached), runs taatool on each with named configurations, scores raw input, reference rows
// and outputs against the truth, prints the tables, writes contact sheets and can write
// docs/QUALITY.md (DESIGN.md section 7). `taa-yardstick --help` lists the options.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "scenegen/scenes_3d.h"
#include "taa/error.h"
#include "util/number_text.h"
#include "yardstick/analytic_scenes.h"
#include "yardstick/blender_scenes.h"
#include "yardstick/configurations.h"
#include "yardstick/contact_sheet.h"
#include "yardstick/exr_files.h"
#include "yardstick/metrics.h"
#include "yardstick/process.h"
#include "yardstick/report.h"

namespace {

namespace fs = std::filesystem;
using namespace taa::yardstick;

const char* kUsage = R"(usage: taa-yardstick [options]
  --scenes a,b           scenes to measure: names, "real" (the Blender renders) or "analytic"
                         (the seven 3D analytic scenes); default: real,analytic
  --configs a,b          configurations from the file to run (default: all of them)
  --config name="flags"  an ad-hoc configuration (repeatable), run after --configs
  --configurations FILE  the named configurations (default: tools/yardstick/configurations.txt)
  --frames A-B           frames to make and resolve (default 1-24)
  --size WxH             sequence size (default 320x180)
  --warmup N             frames left out of the means at the start of each shot (default 4)
  --work DIR             analytic scenes (cached), outputs, logs (default: ./yardstick-work)
  --doc FILE             also write the page (docs/QUALITY.md) there, contact sheets beside it
                         in quality/
  --sheets DIR           where contact sheets go (default: beside --doc, else <work>/sheets)
  --command TEXT         the command recorded in the page (default: this command line)
analytic scenes:
  --truth-samples N      truth grid per axis before refinement (default 16; less: tests only)
  --taatool PATH, --scenegen PATH   the binaries to run (default: the ones built with this)
real renders (Blender Cycles, samples/blender/render_scene.py):
  --blender PATH         Blender (default: blender on PATH)
  --render-cache DIR     where renders are cached (default: $TAA_RENDER_CACHE, else
                         ~/.cache/taa/blender)
  --blender-samples N    samples per pixel of the truth (default 1024)
  --ssaa a,b             SSAA-N reference rows (default 2,4,8,16)
)";

struct Arguments {
  std::vector<std::string> scenes = {"real", "analytic"};
  std::vector<std::string> configNames;
  std::vector<Configuration> adHoc;
  std::string configurationsFile = TAA_YARDSTICK_CONFIGURATIONS;
  int firstFrame = 1, lastFrame = 24;
  int width = 320, height = 180;
  int warmup = 4;
  int truthSamples = 16;
  std::string work = "yardstick-work";
  std::string doc;
  std::string sheets;
  std::string command;
  std::string taatool = TAA_YARDSTICK_TAATOOL;
  std::string scenegen = TAA_YARDSTICK_SCENEGEN;
  BlenderSettings blender;
};

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

int parseInt(const std::string& text, const std::string& what) {
  const std::optional<int> value = taa::parseIntText(text);
  if (!value) fail("bad " + what + " '" + text + "'");
  return *value;
}

std::string defaultRenderCache() {
  if (const char* cache = std::getenv("TAA_RENDER_CACHE"); cache && *cache) return cache;
  const char* home = std::getenv("HOME");
  return (fs::path(home && *home ? home : "/tmp") / ".cache" / "taa" / "blender").string();
}

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  args.blender.script = TAA_YARDSTICK_BLENDER_SCRIPT;
  args.blender.cache = defaultRenderCache();
  std::vector<std::string> all(argv, argv + argc);
  args.command = commandLine(all);
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (k + 1 >= argc) fail("unknown argument or missing value: " + flag);
    const std::string value = argv[++k];
    if (flag == "--scenes") {
      args.scenes = splitList(value);
    } else if (flag == "--configs") {
      args.configNames = splitList(value);
    } else if (flag == "--config") {
      args.adHoc.push_back(parseAdHocConfiguration(value));
    } else if (flag == "--configurations") {
      args.configurationsFile = value;
    } else if (flag == "--frames") {
      const auto dash = value.find('-', 1);
      if (dash == std::string::npos) fail("--frames expects A-B, got " + value);
      args.firstFrame = parseInt(value.substr(0, dash), "--frames");
      args.lastFrame = parseInt(value.substr(dash + 1), "--frames");
      if (args.lastFrame <= args.firstFrame) fail("--frames needs at least two frames");
    } else if (flag == "--size") {
      const auto x = value.find('x');
      if (x == std::string::npos) fail("--size expects WxH, got " + value);
      args.width = parseInt(value.substr(0, x), "--size");
      args.height = parseInt(value.substr(x + 1), "--size");
      if (args.width < 8 || args.height < 8) fail("--size must be at least 8x8");
    } else if (flag == "--warmup") {
      args.warmup = parseInt(value, "--warmup");
      if (args.warmup < 1) fail("--warmup must be at least 1 (flicker needs a previous frame)");
    } else if (flag == "--truth-samples") {
      args.truthSamples = parseInt(value, "--truth-samples");
      if (args.truthSamples < 1) fail("--truth-samples must be at least 1");
    } else if (flag == "--work") {
      args.work = value;
    } else if (flag == "--doc") {
      args.doc = value;
    } else if (flag == "--sheets") {
      args.sheets = value;
    } else if (flag == "--command") {
      args.command = value;
    } else if (flag == "--taatool") {
      args.taatool = value;
    } else if (flag == "--scenegen") {
      args.scenegen = value;
    } else if (flag == "--blender") {
      args.blender.blender = value;
    } else if (flag == "--render-cache") {
      args.blender.cache = value;
    } else if (flag == "--blender-samples") {
      args.blender.truthSamples = parseInt(value, "--blender-samples");
      if (args.blender.truthSamples < 1) fail("--blender-samples must be at least 1");
    } else if (flag == "--ssaa") {
      args.blender.ssaa.clear();
      for (const std::string& n : splitList(value)) {
        args.blender.ssaa.push_back(parseInt(n, "--ssaa"));
        if (args.blender.ssaa.back() < 2) fail("--ssaa counts must be at least 2");
      }
      std::sort(args.blender.ssaa.begin(), args.blender.ssaa.end());
    } else {
      fail("unknown argument: " + flag);
    }
  }
  if (args.sheets.empty()) {
    args.sheets = args.doc.empty() ? (fs::path(args.work) / "sheets").string()
                                   : (fs::path(args.doc).parent_path() / "quality").string();
  }
  return args;
}

std::vector<Configuration> selectConfigurations(const Arguments& args) {
  const std::vector<Configuration> known = readConfigurations(args.configurationsFile);
  std::vector<Configuration> chosen;
  if (args.configNames.empty() && args.adHoc.empty()) return known;
  for (const std::string& name : args.configNames) {
    bool found = false;
    for (const Configuration& c : known) {
      if (c.name == name) {
        chosen.push_back(c);
        found = true;
      }
    }
    if (!found) fail("no configuration named " + name + " in " + args.configurationsFile);
  }
  for (const Configuration& c : args.adHoc) {
    for (const Configuration& other : chosen) {
      if (other.name == c.name) fail("configuration " + c.name + " given twice");
    }
    chosen.push_back(c);
  }
  return chosen;
}

// The scenes to measure, each marked real (Blender) or analytic, in the order given; "real"
// and "analytic" expand to their sets. Blender is asked for its scenes only when needed.
struct SceneChoice {
  std::string name, description;
  bool real = false;
};

std::vector<SceneChoice> chooseScenes(const Arguments& args, const std::string& log) {
  std::vector<std::pair<std::string, std::string>> analytic, real;
  for (const auto& info : taa::scenes::sceneList()) analytic.emplace_back(info.name, info.description);
  bool needBlender = false;
  for (const std::string& name : args.scenes) {
    const bool isAnalytic = name == "analytic" ||
                            std::any_of(analytic.begin(), analytic.end(),
                                        [&](const auto& s) { return s.first == name; });
    needBlender = needBlender || !isAnalytic;
  }
  if (needBlender) real = listBlenderScenes(args.blender, log);
  std::vector<SceneChoice> chosen;
  for (const std::string& name : args.scenes) {
    if (name == "analytic") {
      for (const auto& info : taa::scenes::scene3dList()) {
        chosen.push_back({info.name, info.description, false});
      }
    } else if (name == "real") {
      for (const auto& [scene, description] : real) chosen.push_back({scene, description, true});
    } else if (auto a = std::find_if(analytic.begin(), analytic.end(),
                                     [&](const auto& s) { return s.first == name; });
               a != analytic.end()) {
      chosen.push_back({a->first, a->second, false});
    } else if (auto r = std::find_if(real.begin(), real.end(),
                                     [&](const auto& s) { return s.first == name; });
               r != real.end()) {
      chosen.push_back({r->first, r->second, true});
    } else {
      fail("unknown scene " + name);
    }
  }
  return chosen;
}

// Runs taatool with one configuration on a prepared scene; returns the output folder.
fs::path resolveScene(const Arguments& args, const PreparedScene& scene, const fs::path& outDir,
                      const Configuration& config, const std::string& logPath) {
  std::error_code ec;
  fs::remove_all(outDir, ec);
  fs::create_directories(outDir, ec);
  std::vector<std::string> command = {args.taatool};
  command.insert(command.end(), scene.taatoolInputs.begin(), scene.taatoolInputs.end());
  command.insert(command.end(),
                 {"--frames", std::to_string(args.firstFrame) + "-" + std::to_string(args.lastFrame),
                  "-o", (outDir / "resolved.####.exr").string(), "-d", "float", "-q"});
  command.insert(command.end(), config.flags.begin(), config.flags.end());
  std::ofstream(logPath, std::ios::app) << "$ " << commandLine(command) << "\n";
  if (runProcess(command, logPath) != 0) {
    throw taa::Error("taatool failed for configuration " + config.name + " (see " + logPath +
                     "): " + commandLine(command));
  }
  return outDir;
}

std::string glRenderer(const Arguments& args, const fs::path& work) {
  const std::string log = (work / "taatool-info.log").string();
  std::error_code ec;
  fs::remove(log, ec);
  runProcess({args.taatool, "--info"}, log);
  std::ifstream file(log);
  std::string line;
  while (std::getline(file, line)) {
    const auto colon = line.find(':');
    if (line.rfind("GL renderer", 0) == 0 && colon != std::string::npos) {
      return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown GL renderer";
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

// Scores one sequence, adds its row, and keeps the contact sheet's frame of it.
struct SceneRows {
  std::vector<ResultRow> rows;
  std::vector<SheetTile> tiles;
  std::vector<std::pair<int, double>> ladder;  // spp -> PSNR: raw and the SSAA rows
  std::size_t sheetFrame = 0;
};

void addRow(SceneRows& out, const PreparedScene& scene, const std::string& name,
            const std::vector<taa::Image>& frames) {
  ResultRow row{scene.name, name, score(scene.reference, frames)};
  if (!out.ladder.empty()) row.equivalentSpp = equivalentSpp(row.scores.psnr, out.ladder);
  out.rows.push_back(row);
  out.tiles.push_back({name, frames[out.sheetFrame]});
}

// The contact sheet's frame: two thirds in, where history has settled and motion is fast.
std::size_t sheetFrameOf(const Reference& reference) {
  std::size_t k = reference.frames.size() * 2 / 3;
  while (k + 1 < reference.frames.size() && !reference.measured[k]) ++k;
  return k;
}

int run(const Arguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Configuration> configurations = selectConfigurations(args);
  const fs::path work = fs::absolute(args.work);
  fs::create_directories(work);
  const ScoreOptions options{args.warmup, 4};
  const std::vector<SceneChoice> scenes = chooseScenes(args, (work / "blender.log").string());

  RunDescription description;
  description.command = args.command;
  description.date = utcNow();
  description.machine = glRenderer(args, work) + ", " +
                        std::to_string(std::thread::hardware_concurrency()) + " CPU threads";
  description.size = std::to_string(args.width) + "x" + std::to_string(args.height);
  description.frames = std::to_string(args.firstFrame) + "-" + std::to_string(args.lastFrame);
  description.warmup = args.warmup;
  description.ghostFrames = options.ghostFrames;
  description.configurations = configurations;
  description.sceneCount = int(scenes.size());

  std::string counts;
  for (int n : args.blender.ssaa) counts += (counts.empty() ? "" : ", ") + std::to_string(n);
  ReportSection realSection{
      "Real renders (Blender Cycles)",
      "Rendered by Debian's Blender with Cycles on the CPU by `samples/blender/render_scene.py` "
      "(procedural scenes, no assets; `samples/README.md`, \"Blender scenes\"), cached in `" +
          std::string("$TAA_RENDER_CACHE") +
          "` (default `~/.cache/taa/blender`). The input is what Cycles writes: one multilayer EXR a frame (half "
          "`ViewLayer.Combined`, float `Depth` and `Vector`), 1 sample per pixel with a BOX "
          "filter of width 1 at the frame's Halton jitter (a lens shift), rendered through "
          "taa's Blender add-on (`plugin/blender`: each frame's camera and jitter in its "
          "header's Note) and read by taatool with `--preset cycles` and no other flag. "
          "Truth: " + std::to_string(args.blender.truthSamples) +
          " samples per pixel, unjittered. ssaa-N rows: the mean of N 1-spp renders at the "
          "Halton offsets 1..N (N = " + counts +
          "), the supersampling a resolve is read against. Emission and direct light only (no "
          "bounces, radius-0 lights), so aliasing is the only error, except cycles_contact: "
          "3 bounces, each frame's own noise (an animated seed), its moving box and contact "
          "shadow measured apart (the table after the main one: PSNR inside the box, where "
          "the aux render's object index says it is, and inside its shadow, where the truth "
          "is at most 70% of a render without the box).\n",
      {}, {}};
  ReportSection analyticSection{
      "Analytic scenes",
      "Ray-cast on the CPU by `taa-scenegen` (`samples/scenegen/`) with exact depth, motion and "
      "disocclusion; truth adaptively supersampled from a " + std::to_string(args.truthSamples) +
          "x" + std::to_string(args.truthSamples) +
          " jittered grid per pixel. taatool reads beauty, depth and motion as separate files "
          "(`--depth`, `--motion`).\n",
      {}, {}};
  std::vector<ResultRow> realRows, analyticRows;
  std::vector<std::string> realOrder = {kRawRow}, analyticOrder = {kRawRow};
  for (int n : args.blender.ssaa) realOrder.push_back("ssaa-" + std::to_string(n));
  for (const Configuration& c : configurations) {
    realOrder.push_back(c.name);
    analyticOrder.push_back(c.name);
  }

  for (const SceneChoice& choice : scenes) {
    const std::string log = (work / (choice.name + ".log")).string();
    fs::remove(log);
    const PreparedScene scene =
        choice.real
            ? prepareBlenderScene(args.blender,
                                  {choice.name, args.firstFrame, args.lastFrame, args.width,
                                   args.height},
                                  choice.description, log, options)
            : prepareAnalyticScene(args.scenegen,
                                   {choice.name, args.firstFrame, args.lastFrame, args.width,
                                    args.height, args.truthSamples},
                                   (work / "scenes" / choice.name).string(), log, options);
    std::printf("%s: %s (%.1f s)\n", scene.name.c_str(),
                scene.made ? (choice.real ? "rendered" : "generated") : "cached", scene.seconds);
    std::fflush(stdout);
    description.preparationSeconds += scene.seconds;
    description.madeScenes += scene.made ? 1 : 0;

    SceneRows out;
    out.sheetFrame = sheetFrameOf(scene.reference);
    std::vector<taa::Image> raw, truth;
    for (const ReferenceFrame& frame : scene.reference.frames) {
      raw.push_back(frame.raw);
      truth.push_back(frame.truth);
    }
    if (!scene.fixedRows.empty()) out.ladder.push_back({1, score(scene.reference, raw).psnr});
    for (const auto& fixed : scene.fixedRows) {
      out.ladder.push_back({fixed.samplesPerPixel, score(scene.reference, fixed.frames).psnr});
    }
    addRow(out, scene, kRawRow, raw);
    for (const auto& fixed : scene.fixedRows) addRow(out, scene, fixed.name, fixed.frames);
    for (const Configuration& config : configurations) {
      const auto resolveStart = std::chrono::steady_clock::now();
      const fs::path outDir =
          resolveScene(args, scene, work / "runs" / scene.name / config.name, config, log);
      std::vector<taa::Image> output;
      for (int f = args.firstFrame; f <= args.lastFrame; ++f) {
        output.push_back(
            tonemap(readExr(taa::scenes::framePath(outDir.string(), "resolved", f)).image));
      }
      addRow(out, scene, config.name, output);
      const std::chrono::duration<double> seconds =
          std::chrono::steady_clock::now() - resolveStart;
      std::printf("%s: %s resolved and scored (%.1f s)\n", scene.name.c_str(),
                  config.name.c_str(), seconds.count());
      std::fflush(stdout);
    }

    // The contact sheet: every row's frame, the truth, and the default's (else the last
    // configuration's) error.
    const taa::Image& truthFrame = truth[out.sheetFrame];
    const SheetTile* heatOf = &out.tiles.back();
    for (const SheetTile& tile : out.tiles) heatOf = tile.label == "default" ? &tile : heatOf;
    std::vector<SheetTile> tiles = out.tiles;
    tiles.push_back({"truth", truthFrame});
    tiles.push_back({"|" + heatOf->label + " - truth| x10", errorHeatMap(heatOf->image, truthFrame, 0.1f)});
    const Crop crop = worstWindow(raw[out.sheetFrame], truthFrame, (args.width + 1) / 2,
                                  (args.height + 1) / 2);
    const fs::path sheet = fs::path(args.sheets) / (scene.name + ".png");
    const std::string warning = writeContactSheet(sheet.string(), tiles, crop, 6);
    if (!warning.empty()) std::fprintf(stderr, "taa-yardstick: %s\n", warning.c_str());

    ReportSection& section = choice.real ? realSection : analyticSection;
    const std::string link =
        args.doc.empty() ? sheet.string()
                         : fs::relative(sheet, fs::absolute(args.doc).parent_path()).string();
    section.scenes.push_back({scene.name, scene.description, link,
                              "frame " + std::to_string(scene.reference.frames[out.sheetFrame].frame),
                              scene.reference.measuredFrames});
    std::vector<ResultRow>& rows = choice.real ? realRows : analyticRows;
    rows.insert(rows.end(), out.rows.begin(), out.rows.end());
  }
  std::string tables;
  if (!realRows.empty()) {
    realSection.table = formatTable(realRows, realOrder);
    if (const std::string regions = formatRegionTable(realRows, realOrder); !regions.empty()) {
      realSection.table += "\nThe moving object and its shadow:\n\n" + regions;
    }
    tables += "\nReal renders\n" + realSection.table;
    description.sections.push_back(realSection);
  }
  if (!analyticRows.empty()) {
    analyticSection.table = formatTable(analyticRows, analyticOrder);
    tables += "\nAnalytic scenes\n" + analyticSection.table;
    description.sections.push_back(analyticSection);
  }
  std::printf("%s", tables.c_str());
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  description.seconds = seconds.count();
  if (!args.doc.empty()) {
    std::ofstream page(args.doc);
    page << formatQualityPage(description);
    if (!page) throw taa::Error("cannot write the page", {args.doc});
    std::printf("\nwrote %s\n", args.doc.c_str());
  }
  std::printf("contact sheets in %s\n", args.sheets.c_str());
  std::printf("taa-yardstick: %zu scenes, %zu configurations, %.0f s\n", scenes.size(),
              configurations.size(), seconds.count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseArguments(argc, argv));
  } catch (const std::invalid_argument& e) {
    std::cerr << "taa-yardstick ERROR: " << e.what() << "\n" << kUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "taa-yardstick ERROR: " << e.what() << "\n";
    return 1;
  }
}
