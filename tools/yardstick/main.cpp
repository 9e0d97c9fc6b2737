// taa-yardstick: generates the quality scenes (cached), runs taatool on each with named
// configurations, scores raw input and outputs against the truth, prints the table and can
// write docs/QUALITY.md (DESIGN.md section 7). `taa-yardstick --help` lists the options.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "scenegen/scenes_3d.h"
#include "taa/error.h"
#include "yardstick/configurations.h"
#include "yardstick/exr_files.h"
#include "yardstick/metrics.h"
#include "yardstick/process.h"
#include "yardstick/report.h"
#include "yardstick/scene_cache.h"
#include "yardstick/sequence_score.h"
#include "util/number_text.h"

namespace {

namespace fs = std::filesystem;
using namespace taa::yardstick;

const char* kUsage = R"(usage: taa-yardstick [options]
  --scenes a,b           scenes to measure (default: the seven 3D scenes)
  --configs a,b          configurations from the file to run (default: all of them)
  --config name="flags"  an ad-hoc configuration (repeatable), run after --configs
  --configurations FILE  the named configurations (default: tools/yardstick/configurations.txt)
  --frames A-B           frames to generate and resolve (default 1-24)
  --size WxH             scene size (default 320x180)
  --truth-samples N      truth grid per axis before refinement (default 16; less: tests only)
  --warmup N             frames left out of the means at the start of each shot (default 4)
  --work DIR             generated scenes (cached) and outputs (default: ./yardstick-work)
  --doc FILE             also write the page (docs/QUALITY.md) there
  --command TEXT         the command recorded in the page (default: this command line)
  --taatool PATH, --scenegen PATH   the binaries to run (default: the ones built with this)
)";

struct Arguments {
  std::vector<std::string> scenes;
  std::vector<std::string> configNames;
  std::vector<Configuration> adHoc;
  std::string configurationsFile = TAA_YARDSTICK_CONFIGURATIONS;
  int firstFrame = 1, lastFrame = 24;
  int width = 320, height = 180;
  int warmup = 4;
  int truthSamples = 16;
  std::string work = "yardstick-work";
  std::string doc;
  std::string command;
  std::string taatool = TAA_YARDSTICK_TAATOOL;
  std::string scenegen = TAA_YARDSTICK_SCENEGEN;
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

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
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
    } else if (flag == "--command") {
      args.command = value;
    } else if (flag == "--taatool") {
      args.taatool = value;
    } else if (flag == "--scenegen") {
      args.scenegen = value;
    } else {
      fail("unknown argument: " + flag);
    }
  }
  if (args.scenes.empty()) {
    for (const auto& info : taa::scenes::scene3dList()) args.scenes.push_back(info.name);
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

std::string framePath(const fs::path& dir, const std::string& stem, int frame) {
  return taa::scenes::framePath(dir.string(), stem, frame);
}

taa::yardstick::Reference loadReference(const fs::path& dir, const Arguments& args,
                                        const ScoreOptions& options) {
  std::vector<ReferenceFrame> frames;
  for (int f = args.firstFrame; f <= args.lastFrame; ++f) {
    ReferenceFrame frame;
    frame.frame = f;
    const ExrFile truth = readExr(framePath(dir, "truth", f));
    frame.shot = truth.shot;
    frame.truth = tonemap(truth.image);
    frame.raw = tonemap(readExr(framePath(dir, "beauty", f)).image);
    frame.flow = readExr(framePath(dir, "flow", f)).image;
    frame.disocclusion = readExr(framePath(dir, "disocclusion", f)).image;
    frames.push_back(std::move(frame));
  }
  return prepareReference(std::move(frames), options);
}

// Runs taatool with one configuration on a generated scene; returns the output folder.
fs::path resolveScene(const Arguments& args, const fs::path& sceneDir, const fs::path& outDir,
                      const Configuration& config, const std::string& logPath) {
  std::error_code ec;
  fs::remove_all(outDir, ec);
  fs::create_directories(outDir, ec);
  std::vector<std::string> command = {
      args.taatool, (sceneDir / "beauty.####.exr").string(),
      "--depth", (sceneDir / "depth.####.exr").string(),
      "--motion", (sceneDir / "motion.####.exr").string(),
      "--frames", std::to_string(args.firstFrame) + "-" + std::to_string(args.lastFrame),
      "-o", (outDir / "resolved.####.exr").string(), "-d", "float", "-q"};
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

int run(const Arguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Configuration> configurations = selectConfigurations(args);
  const fs::path work = fs::absolute(args.work);
  fs::create_directories(work);
  const ScoreOptions options{args.warmup, 4};

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

  std::vector<std::string> order = {kRawRow};
  for (const Configuration& c : configurations) order.push_back(c.name);
  std::vector<ResultRow> rows;
  for (const std::string& scene : args.scenes) {
    for (const auto& info : taa::scenes::sceneList()) {
      if (info.name == scene) description.scenes.emplace_back(scene, info.description);
    }
    const fs::path sceneDir = work / "scenes" / scene;
    const std::string log = (work / (scene + ".log")).string();
    fs::remove(log);
    const auto generateStart = std::chrono::steady_clock::now();
    const bool generated = ensureScene(
        args.scenegen,
        {scene, args.firstFrame, args.lastFrame, args.width, args.height, args.truthSamples},
        sceneDir.string(), log);
    const std::chrono::duration<double> generateSeconds =
        std::chrono::steady_clock::now() - generateStart;
    std::printf("%s: %s (%.1f s)\n", scene.c_str(), generated ? "generated" : "cached",
                generateSeconds.count());
    description.generationSeconds += generateSeconds.count();
    description.cachedScenes += generated ? 0 : 1;
    std::fflush(stdout);

    const Reference reference = loadReference(sceneDir, args, options);
    description.measuredFrames.emplace_back(scene, reference.measuredFrames);
    std::vector<taa::Image> raw;
    for (const ReferenceFrame& frame : reference.frames) raw.push_back(frame.raw);
    rows.push_back({scene, kRawRow, score(reference, raw)});

    for (const Configuration& config : configurations) {
      const auto resolveStart = std::chrono::steady_clock::now();
      const fs::path outDir =
          resolveScene(args, sceneDir, work / "runs" / scene / config.name, config, log);
      std::vector<taa::Image> output;
      for (int f = args.firstFrame; f <= args.lastFrame; ++f) {
        output.push_back(tonemap(readExr(framePath(outDir, "resolved", f)).image));
      }
      rows.push_back({scene, config.name, score(reference, output)});
      const std::chrono::duration<double> seconds =
          std::chrono::steady_clock::now() - resolveStart;
      std::printf("%s: %s resolved and scored (%.1f s)\n", scene.c_str(), config.name.c_str(),
                  seconds.count());
      std::fflush(stdout);
    }
  }
  const std::string table = formatTable(rows, order);
  std::printf("\n%s", table.c_str());
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  description.seconds = seconds.count();
  if (!args.doc.empty()) {
    std::ofstream page(args.doc);
    page << formatQualityPage(description, table);
    if (!page) throw taa::Error("cannot write the page", {args.doc});
    std::printf("\nwrote %s\n", args.doc.c_str());
  }
  std::printf("taa-yardstick: %zu scenes, %zu configurations, %.0f s\n", args.scenes.size(),
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
