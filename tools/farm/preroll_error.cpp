// taa-preroll-error: how far history-mode farm chunks are from one run over the shot, per
// pre-roll length (README "Render farm"). Runs the real taatool once over the shot and the real
// `taa-farm run` for every chunk and pre-roll, then compares the frames on the yardstick's
// display values (Reinhard x/(1+x), RGB; DESIGN.md section 7).
//
//   taa-preroll-error --chunk 6 --prerolls 0,4,8,16 --work DIR [--label NAME] -- TAATOOL_ARGS
//
// TAATOOL_ARGS: the shot as taatool takes it, with --frames and without -o. Prints one Markdown
// table row per pre-roll: max and mean absolute difference over every frame and pixel, PSNR over
// all of them (peak 1), the worst frame's PSNR, and how many frames differ at all.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "io/sequence_pattern.h"
#include "taa/error.h"
#include "util/number_text.h"
#include "yardstick/exr_files.h"
#include "yardstick/metrics.h"
#include "yardstick/process.h"

namespace {

namespace fs = std::filesystem;
using namespace taa;

struct Arguments {
  int chunk = 0;
  std::vector<int> prerolls;
  fs::path work;
  std::string label = "shot";
  std::vector<std::string> taatoolArgs;
};

Arguments parse(int argc, char** argv) {
  Arguments args;
  int i = 1;
  for (; i < argc && std::string(argv[i]) != "--"; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw Error(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--chunk") {
      args.chunk = parseIntText(value).value_or(0);
    } else if (flag == "--prerolls") {
      for (int frame : io::parseFrameRange(value)) args.prerolls.push_back(frame);
    } else if (flag == "--work") {
      args.work = value;
    } else if (flag == "--label") {
      args.label = value;
    } else {
      throw Error("unknown option " + flag);
    }
  }
  for (++i; i < argc; ++i) args.taatoolArgs.push_back(argv[i]);
  if (args.chunk < 1 || args.prerolls.empty() || args.work.empty() || args.taatoolArgs.empty()) {
    throw Error("usage: taa-preroll-error --chunk N --prerolls 0,4,8 --work DIR [--label NAME] "
                "-- TAATOOL_ARGS (with --frames, without -o)");
  }
  return args;
}

// The shot's frames, from its --frames.
std::vector<int> shotFrames(const std::vector<std::string>& args) {
  const auto at = std::find(args.begin(), args.end(), "--frames");
  if (at == args.end() || at + 1 == args.end()) throw Error("TAATOOL_ARGS need --frames");
  return io::parseFrameRange(*(at + 1));
}

void run(std::vector<std::string> argv, const fs::path& log) {
  if (yardstick::runProcess(argv, log.string()) != 0) {
    throw Error("failed: " + yardstick::commandLine(argv) + " (log: " + log.string() + ")");
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Arguments args = parse(argc, argv);
    const std::vector<int> frames = shotFrames(args.taatoolArgs);
    const int tasks = int((frames.size() + std::size_t(args.chunk) - 1) / std::size_t(args.chunk));
    fs::create_directories(args.work);
    const fs::path log = args.work / "log.txt";
    auto withOutput = [&](std::vector<std::string> command, const fs::path& folder) {
      command.insert(command.end(), args.taatoolArgs.begin(), args.taatoolArgs.end());
      command.insert(command.end(), {"-o", (folder / "r.####.exr").string(), "-q"});
      return command;
    };
    const fs::path whole = args.work / "whole";
    fs::remove_all(whole);
    run(withOutput({TAA_TAATOOL}, whole), log);

    for (int preroll : args.prerolls) {
      const fs::path chunked = args.work / ("preroll" + std::to_string(preroll));
      fs::remove_all(chunked);
      for (int task = 0; task < tasks; ++task) {
        run(withOutput({TAA_FARM, "run", "--chunk", std::to_string(args.chunk), "--task",
                        std::to_string(task), "--preroll", std::to_string(preroll)},
                       chunked),
            log);
      }
      constexpr double kInfinity = std::numeric_limits<double>::infinity();
      double maxAbs = 0, sumAbs = 0, sumSquares = 0, worstPsnr = kInfinity;
      long long values = 0;
      int differing = 0;
      auto displayValues = [](const fs::path& folder, int frame) {
        const std::string path = io::expandFramePattern((folder / "r.####.exr").string(), frame);
        return yardstick::tonemap(yardstick::readExr(path).image);
      };
      for (int frame : frames) {
        const Image a = displayValues(whole, frame), b = displayValues(chunked, frame);
        double frameMax = 0;
        for (std::size_t i = 0; i < a.pixels.size(); ++i) {
          const double d = std::abs(double(a.pixels[i]) - b.pixels[i]);
          frameMax = std::max(frameMax, d);
          sumAbs += d;
          sumSquares += d * d;
        }
        values += (long long)a.pixels.size();
        maxAbs = std::max(maxAbs, frameMax);
        if (frameMax > 0) ++differing;
        worstPsnr = std::min(worstPsnr, yardstick::psnr(a, b));
      }
      const double mse = sumSquares / double(values);
      const double psnr = mse > 0 ? 10 * std::log10(1 / mse) : kInfinity;
      std::printf("| %s | %d | %.5f | %.7f | %.1f | %.1f | %d of %zu |\n", args.label.c_str(),
                  preroll, maxAbs, sumAbs / double(values), psnr, worstPsnr, differing,
                  frames.size());
      std::fflush(stdout);
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "taa-preroll-error ERROR: " << e.what() << "\n";
    return 1;
  }
}
