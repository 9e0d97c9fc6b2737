#include "yardstick/report.h"

#include <cmath>
#include <cstdio>
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

std::string row(const std::string& scene, const std::string& configuration, const Scores& s) {
  return "| " + scene + " | " + configuration + " | " + number(s.psnr, "%.2f") + " | " +
         number(s.ssim, "%.4f") + " | " + number(s.flicker, "%.3f") + " | " +
         number(s.ghosting, "%.3f") + " |\n";
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

std::string formatTable(const std::vector<ResultRow>& rows,
                        const std::vector<std::string>& configurationOrder) {
  std::string table =
      "| scene | configuration | PSNR (dB) | SSIM | flicker | ghosting |\n"
      "|---|---|---:|---:|---:|---:|\n";
  std::vector<std::string> scenes;
  for (const ResultRow& r : rows) {
    bool seen = false;
    for (const std::string& s : scenes) seen = seen || s == r.scene;
    if (!seen) scenes.push_back(r.scene);
  }
  std::map<std::string, Mean[4]> means;
  for (const std::string& scene : scenes) {
    for (const std::string& configuration : configurationOrder) {
      for (const ResultRow& r : rows) {
        if (r.scene != scene || r.configuration != configuration) continue;
        table += row(scene, configuration, r.scores);
        Mean* m = means[configuration];
        m[0].add(r.scores.psnr);
        m[1].add(r.scores.ssim);
        m[2].add(r.scores.flicker);
        m[3].add(r.scores.ghosting);
      }
    }
  }
  for (const std::string& configuration : configurationOrder) {
    const auto found = means.find(configuration);
    if (found == means.end()) continue;
    const Mean* m = found->second;
    table += row("**mean**", configuration,
                 {m[0].value(), m[1].value(), m[2].value(), m[3].value()});
  }
  return table;
}

std::string formatQualityPage(const RunDescription& run, const std::string& table) {
  std::string page;
  page += "# Quality\n\n";
  page += "Measured, not asserted (DESIGN.md section 7). Written by the quality yardstick\n"
          "(`tools/yardstick/`, scenes from `samples/scenegen/`); every change that moves a\n"
          "figure regenerates this page with the command below and commits it.\n\n";
  page += "- Command: `" + run.command + "`\n";
  page += "- Date: " + run.date + "\n";
  page += "- Machine: " + run.machine + "\n";
  char timing[160];
  std::snprintf(timing, sizeof timing,
                "%.0f s, of which %.0f s generating scenes (%d of %zu were cached)", run.seconds,
                run.generationSeconds, run.cachedScenes, run.scenes.size());
  page += "- Scenes: " + run.size + ", frames " + run.frames +
          ", jitter Halton(2,3) at index = frame (taatool's default); taatool reads "
          "beauty/depth/motion as separate files (`--depth`, `--motion`) and writes float. "
          "Run time: " + timing + ".\n";
  page += "- Warm-up: the first " + std::to_string(run.warmup) +
          " frames of every shot (the sequence's start, and the cut) are left out of every "
          "mean. Frames measured per scene:";
  for (std::size_t k = 0; k < run.measuredFrames.size(); ++k) {
    page += (k ? ", " : " ") + run.measuredFrames[k].first + " " +
            std::to_string(run.measuredFrames[k].second);
  }
  page += ".\n\n";
  page += "## Metrics\n\n"
          "All on Reinhard-tonemapped RGB, x/(1+x), against the truth (a box-filtered pixel "
          "average, adaptively supersampled from a 16x16 jittered grid, unjittered).\n\n"
          "- **PSNR**: peak 1.0, MSE over pixels and R, G, B; mean over measured frames.\n"
          "- **SSIM**: Gaussian window (sigma 1.5, 11x11, truncated and renormalised at the "
          "border), C1 = 0.01^2, C2 = 0.03^2, per R, G, B channel and averaged; mean over "
          "measured frames.\n"
          "- **flicker**: mean absolute change of the output from frame t-1 to t after "
          "warping t-1 to t with the exact motion (bilinear), over pixels whose surface was "
          "visible at its previous position (not disoccluded, on screen), pooled over measured "
          "frames, divided by the same figure for the truth. 1 = as stable as the truth; "
          "crawl and shimmer push it up, over-blur below 1. Where the truth barely changes "
          "(a static camera: moving_object_3d) every ratio is large; compare rows, not "
          "scenes.\n"
          "- **ghosting**: mean absolute error against the truth in pixels disoccluded within "
          "the last " + std::to_string(run.ghostFrames) +
          " frames (followed along the motion), pooled over measured frames, divided by the "
          "raw input's error there (so raw is 1). Below 1: the resolve cleans up revealed "
          "background faster than it smears; above 1: ghosts. '-' where a scene reveals "
          "nothing.\n\n";
  page += "## Configurations\n\n| name | taatool flags |\n|---|---|\n";
  page += "| raw | none: the jittered input itself |\n";
  for (const Configuration& c : run.configurations) {
    const std::string flags = c.flagsText.empty() ? "(none: defaults)" : "`" + c.flagsText + "`";
    page += "| " + c.name + " | " + flags + " |\n";
  }
  page += "\n## Scenes\n\n| scene | what |\n|---|---|\n";
  for (const auto& [name, description] : run.scenes) {
    page += "| " + name + " | " + description + " |\n";
  }
  page += "\n## Results\n\n" + table;
  return page;
}

}  // namespace taa::yardstick
