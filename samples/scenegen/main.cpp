// taa-scenegen: renders a test scene as an EXR sequence with its truth (DESIGN.md section 7).
//   taa-scenegen --scene NAME --frames 1-24 --size 320x180 --layout separate|cycles --out DIR
//   taa-scenegen --list
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <iostream>
#include <stdexcept>
#include <optional>
#include <string>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "taa/error.h"
#include "util/number_text.h"

namespace {

using taa::scenes::OutputLayout;

struct Arguments {
  std::string scene;
  int firstFrame = 1;
  int lastFrame = 24;
  int width = 320;
  int height = 180;
  OutputLayout layout = OutputLayout::Separate;
  int truthSamples = 16;
  std::string outDir;
  bool list = false;
  bool help = false;
};

const char* kUsage =
    "usage: taa-scenegen --scene NAME --out DIR [--frames 1-24] [--size 320x180]\n"
    "                    [--layout separate|cycles] [--truth-samples 16]\n"
    "       taa-scenegen --list\n";

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

int parseInt(const std::string& text, const std::string& what) {
  const std::optional<int> value = taa::parseIntText(text);
  if (!value) fail("bad " + what + " '" + text + "'");
  return *value;
}

// "A-B" or "A"; A may be negative ("-5--1" is frames -5 to -1).
void parseFrames(const std::string& text, Arguments& args) {
  const std::size_t dash = text.find('-', 1);
  args.firstFrame = parseInt(text.substr(0, dash), "--frames");
  args.lastFrame =
      dash == std::string::npos ? args.firstFrame : parseInt(text.substr(dash + 1), "--frames");
  if (args.lastFrame < args.firstFrame) fail("--frames range is empty: " + text);
}

void parseSize(const std::string& text, Arguments& args) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) fail("bad --size '" + text + "' (want WxH)");
  args.width = parseInt(text.substr(0, x), "--size width");
  args.height = parseInt(text.substr(x + 1), "--size height");
  if (args.width <= 0 || args.height <= 0) fail("--size must be positive: " + text);
}

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--list") {
      args.list = true;
      continue;
    }
    if (flag == "--help" || flag == "-h") {
      args.help = true;
      continue;
    }
    if (k + 1 >= argc) fail("unknown argument or missing value: " + flag);
    const std::string value = argv[++k];
    if (flag == "--scene") {
      args.scene = value;
    } else if (flag == "--frames") {
      parseFrames(value, args);
    } else if (flag == "--size") {
      parseSize(value, args);
    } else if (flag == "--layout") {
      if (value == "separate") {
        args.layout = OutputLayout::Separate;
      } else if (value == "cycles") {
        args.layout = OutputLayout::Cycles;
      } else {
        fail("bad --layout '" + value + "' (want separate or cycles)");
      }
    } else if (flag == "--truth-samples") {
      args.truthSamples = parseInt(value, "--truth-samples");
      if (args.truthSamples < 1) fail("--truth-samples must be at least 1");
    } else if (flag == "--out") {
      args.outDir = value;
    } else {
      fail("unknown argument: " + flag);
    }
  }
  if (!args.list && !args.help) {
    if (args.scene.empty()) fail("--scene is required");
    if (args.outDir.empty()) fail("--out is required");
  }
  return args;
}

void listScenes() {
  for (const auto& info : taa::scenes::sceneList()) {
    std::printf("%-14s %s\n", info.name.c_str(), info.description.c_str());
  }
}

void generate(const Arguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const auto scene = taa::scenes::makeScene(args.scene, args.width, args.height);
  taa::scenes::RenderSettings settings;
  settings.truthSamplesPerAxis = args.truthSamples;
  // Each frame is written while the next one renders (compressing the EXRs is a few percent of
  // the time, on one thread); one write in flight at a time, its error rethrown here.
  std::future<void> writing;
  for (int frame = args.firstFrame; frame <= args.lastFrame; ++frame) {
    taa::scenes::SceneFrame rendered = scene->render(frame, settings);
    if (writing.valid()) writing.get();
    writing = std::async(std::launch::async, [&, rendered = std::move(rendered)] {
      taa::scenes::writeFrame(rendered, scene->name(), args.layout, args.outDir);
    });
  }
  if (writing.valid()) writing.get();
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::printf("taa-scenegen: %s, frames %d-%d, %dx%d -> %s (%.2f s)\n", scene->name().c_str(),
              args.firstFrame, args.lastFrame, args.width, args.height, args.outDir.c_str(),
              seconds.count());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Arguments args = parseArguments(argc, argv);
    if (args.help) {
      std::fputs(kUsage, stdout);
    } else if (args.list) {
      listScenes();
    } else {
      generate(args);
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "taa-scenegen ERROR: " << e.what() << "\n" << kUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "taa-scenegen ERROR: " << e.what() << "\n";
    return 1;
  }
}
