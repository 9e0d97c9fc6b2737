#include "yardstick/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>

namespace taa::yardstick {
namespace {

std::string number(double value, const char* format) {
  if (std::isnan(value)) return "-";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string sppText(double spp, int top) {
  if (std::isnan(spp)) return "-";
  if (spp <= 0.0) return "<1";
  if (std::isinf(spp)) return ">" + std::to_string(top);
  return number(spp, spp < 10.0 ? "%.1f" : "%.0f");
}

// Mean of the non-NaN values; NaN when there are none.
struct Mean {
  double sum = 0.0;
  int count = 0;
  void add(double v) {
    if (std::isnan(v)) return;
    sum += v;
    ++count;
  }
  double value() const { return count ? sum / count : std::nan(""); }
};

}  // namespace

double equivalentSpp(double psnr, const std::vector<std::pair<int, double>>& ladder) {
  if (ladder.empty() || std::isnan(psnr)) return std::nan("");
  if (psnr < ladder.front().second) return 0.0;
  for (std::size_t k = 0; k + 1 < ladder.size(); ++k) {
    const auto& [lowSpp, lowPsnr] = ladder[k];
    const auto& [highSpp, highPsnr] = ladder[k + 1];
    if (psnr <= highPsnr && highPsnr > lowPsnr) {
      const double t = (psnr - lowPsnr) / (highPsnr - lowPsnr);
      return std::exp2(std::log2(double(lowSpp)) +
                       t * (std::log2(double(highSpp)) - std::log2(double(lowSpp))));
    }
  }
  return psnr <= ladder.back().second ? double(ladder.back().first)
                                      : std::numeric_limits<double>::infinity();
}

std::string formatTable(const std::vector<ResultRow>& rows,
                        const std::vector<std::string>& configurationOrder) {
  bool withSpp = false;
  for (const ResultRow& r : rows) withSpp = withSpp || !std::isnan(r.equivalentSpp);
  auto line = [&](const std::string& scene, const std::string& configuration, const Scores& s,
                  const std::string& spp) {
    return "| " + scene + " | " + configuration + " | " + number(s.psnr, "%.2f") + " | " +
           number(s.ssim, "%.4f") + " | " + number(s.temporal, "%.4f") + " | " +
           number(s.flicker, "%.3f") + " | " + number(s.ghosting, "%.3f") + " |" +
           (withSpp ? " " + spp + " |" : "") + "\n";
  };
  std::string table =
      "| scene | configuration | PSNR (dB) | SSIM | temporal error | flicker | ghosting |";
  table += withSpp ? " spp equivalent |\n" : "\n";
  table += "|---|---|---:|---:|---:|---:|---:|";
  table += withSpp ? "---:|\n" : "\n";
  std::vector<std::string> scenes;
  for (const ResultRow& r : rows) {
    bool seen = false;
    for (const std::string& s : scenes) seen = seen || s == r.scene;
    if (!seen) scenes.push_back(r.scene);
  }
  int topRung = 0;
  for (const ResultRow& r : rows) {
    if (r.configuration.rfind("ssaa-", 0) == 0) {
      topRung = std::max(topRung, std::atoi(r.configuration.c_str() + 5));
    }
  }
  std::map<std::string, Mean[5]> means;
  std::map<std::string, Mean> logSpp;
  std::map<std::string, bool> sppFinite;
  for (const std::string& scene : scenes) {
    for (const std::string& configuration : configurationOrder) {
      for (const ResultRow& r : rows) {
        if (r.scene != scene || r.configuration != configuration) continue;
        table += line(scene, configuration, r.scores, sppText(r.equivalentSpp, topRung));
        Mean* m = means[configuration];
        m[0].add(r.scores.psnr);
        m[1].add(r.scores.ssim);
        m[2].add(r.scores.temporal);
        m[3].add(r.scores.flicker);
        m[4].add(r.scores.ghosting);
        const bool finite = r.equivalentSpp > 0.0 && std::isfinite(r.equivalentSpp);
        if (!sppFinite.count(configuration)) sppFinite[configuration] = true;
        sppFinite[configuration] = sppFinite[configuration] && finite;
        if (finite) logSpp[configuration].add(std::log2(r.equivalentSpp));
      }
    }
  }
  for (const std::string& configuration : configurationOrder) {
    const auto found = means.find(configuration);
    if (found == means.end()) continue;
    const Mean* m = found->second;
    // The geometric mean of the equivalent spp, when every scene has a finite one.
    const double spp = sppFinite[configuration] ? std::exp2(logSpp[configuration].value())
                                                : std::nan("");
    table += line("**mean**", configuration,
                  {m[0].value(), m[1].value(), m[2].value(), m[3].value(), m[4].value()},
                  sppText(spp, topRung));
  }
  return table;
}

std::string formatRegionTable(const std::vector<ResultRow>& rows,
                              const std::vector<std::string>& configurationOrder) {
  std::string table;
  std::vector<std::string> scenes;
  for (const ResultRow& r : rows) {
    if (std::isnan(r.scores.movingPsnr)) continue;
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
      scenes.push_back(r.scene);
    }
  }
  for (const std::string& scene : scenes) {
    for (const std::string& configuration : configurationOrder) {
      for (const ResultRow& r : rows) {
        if (r.scene != scene || r.configuration != configuration) continue;
        table += "| " + scene + " | " + configuration + " | " + number(r.scores.psnr, "%.2f") +
                 " | " + number(r.scores.movingPsnr, "%.2f") + " | " +
                 number(r.scores.shadowPsnr, "%.2f") + " |\n";
      }
    }
  }
  if (table.empty()) return table;
  return "| scene | configuration | PSNR (dB) | inside the moving object | inside its shadow |\n"
         "|---|---|---:|---:|---:|\n" + table;
}

std::string formatQualityPage(const RunDescription& run) {
  std::string page;
  page += "# Quality\n\n";
  page += "Measured, not asserted (DESIGN.md section 7). Written by the quality yardstick\n"
          "(`tools/yardstick/`; real renders from `samples/blender/`, analytic scenes from\n"
          "`samples/scenegen/`); every change that moves a figure regenerates this page with the\n"
          "command below and commits it.\n\n";
  page += "- Command: `" + run.command + "`\n";
  page += "- Date: " + run.date + "\n";
  page += "- Machine: " + run.machine + "\n";
  char timing[200];
  std::snprintf(timing, sizeof timing,
                "%.0f s, of which %.0f s making or checking scenes (%d of %d were made by this "
                "run, the others cached)",
                run.seconds, run.preparationSeconds, run.madeScenes, run.sceneCount);
  page += "- Sequences: " + run.size + ", frames " + run.frames +
          ", jitter Halton(2,3) at index = frame (taatool's default). Run time: " + timing +
          ".\n";
  page += "- Warm-up: the first " + std::to_string(run.warmup) +
          " frames of every shot (the sequence's start, and a cut) are left out of every "
          "mean.\n\n";
  page += "## Metrics\n\n"
          "All on Reinhard-tonemapped RGB, x/(1+x), against the truth (the box-filtered pixel "
          "average: many samples, unjittered).\n\n"
          "- **PSNR**: peak 1.0, MSE over pixels and R, G, B; mean over measured frames.\n"
          "- **SSIM**: Gaussian window (sigma 1.5, 11x11, truncated and renormalised at the "
          "border), C1 = 0.01^2, C2 = 0.03^2, per R, G, B channel and averaged; mean over "
          "measured frames.\n"
          "- **temporal error** (lower is better, 0 = the truth): the output's change from "
          "frame t-1 to t after warping t-1 to t with the exact motion (bilinear), minus the "
          "truth's change over the same warp, absolute, RGB mean, over pixels whose surface "
          "was visible in both frames, pooled over measured frames. Crawl, shimmer and "
          "lagging shading raise it; it stays meaningful on static shots, where the truth "
          "barely changes.\n"
          "- **flicker** (kept for comparison with earlier pages): the output's "
          "motion-compensated change divided by the truth's. 1 = as stable as the truth; "
          "where the truth barely changes (a static camera) every ratio is large, so "
          "criteria use the temporal error.\n"
          "- **ghosting**: mean absolute error against the truth in pixels disoccluded within "
          "the last " + std::to_string(run.ghostFrames) +
          " frames (followed along the motion), pooled over measured frames, divided by the "
          "raw input's error there (so raw is 1). Below 1: revealed background is cleaned up "
          "faster than it smears; above 1: ghosts. '-' where a scene reveals nothing.\n"
          "- **spp equivalent** (real renders): the samples per pixel of the SSAA-N reference "
          "with the same PSNR, interpolated in log2(N) between the rungs (raw input = 1 spp; "
          "'<1' below it, '>16' above SSAA-16); the mean row gives the geometric mean.\n\n";
  page += "## Configurations\n\n| name | taatool flags |\n|---|---|\n";
  page += "| raw | none: the jittered input itself |\n";
  for (const Configuration& c : run.configurations) {
    const std::string flags = c.flagsText.empty() ? "(none: defaults)" : "`" + c.flagsText + "`";
    page += "| " + c.name + " | " + flags + " |\n";
  }
  page += "\n";
  for (const ReportSection& section : run.sections) {
    page += "## " + section.title + "\n\n" + section.introduction + "\n";
    page += "| scene | what | frames measured | contact sheet |\n|---|---|---:|---|\n";
    for (const ReportSection::Scene& scene : section.scenes) {
      page += "| " + scene.name + " | " + scene.description + " | " +
              std::to_string(scene.measuredFrames) + " | " +
              (scene.sheet.empty() ? "-" : "[" + scene.sheetNote + "](" + scene.sheet + ")") + " |\n";
    }
    page += "\n" + section.table + "\n";
  }
  return page;
}

}  // namespace taa::yardstick
