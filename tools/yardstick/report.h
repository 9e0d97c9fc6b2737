// The yardstick's results tables (markdown) and the docs/QUALITY.md page around them.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "yardstick/configurations.h"
#include "yardstick/sequence_score.h"

namespace taa::yardstick {

// The name of the raw-input row (the jittered beauty, no resolve).
inline const char* kRawRow = "raw";

struct ResultRow {
  std::string scene;
  std::string configuration;  // kRawRow, a fixed row ("ssaa-4") or a configuration's name
  Scores scores;
  double equivalentSpp = std::nan("");  // samples per pixel of equal PSNR (NaN: no ladder)
};

// The samples per pixel whose SSAA reference would score `psnr`: interpolated in log2(spp)
// between the rungs of `ladder` (spp -> PSNR, raw input = 1 spp, ascending spp). Below the
// first rung: 0 (shown "<1"); above the last: +inf (shown ">N").
double equivalentSpp(double psnr, const std::vector<std::pair<int, double>>& ladder);

// One row per scene and configuration in the given order, then one "mean" row per
// configuration (NaN figures are left out of the means and printed as "-"). The "spp" column
// appears when any row has an equivalent spp.
// The rows of scenes with a moving object and its shadow (Scores::movingPsnr, shadowPsnr),
// each scene's configurations in `configurationOrder`; empty when no row has them.
std::string formatRegionTable(const std::vector<ResultRow>& rows,
                              const std::vector<std::string>& configurationOrder);

std::string formatTable(const std::vector<ResultRow>& rows,
                        const std::vector<std::string>& configurationOrder);

// A part of the page: the real renders or the analytic scenes.
struct ReportSection {
  std::string title;
  std::string introduction;  // markdown paragraphs
  struct Scene {
    std::string name, description;
    std::string sheet;      // link to the contact sheet, relative to the page
    std::string sheetNote;  // which frame it shows
    int measuredFrames = 0;
  };
  std::vector<Scene> scenes;
  std::string table;
};

// What the page records besides the tables.
struct RunDescription {
  std::string command;       // the exact command that produced the tables
  std::string date;          // UTC, ISO 8601
  std::string machine;       // GL renderer and CPU count
  std::string size;          // e.g. 320x180
  std::string frames;        // e.g. 1-24
  int warmup = 4;
  int ghostFrames = 4;
  std::vector<Configuration> configurations;
  double seconds = 0.0;            // wall time of the whole run
  double preparationSeconds = 0.0;  // of that, generating and rendering scenes
  int madeScenes = 0;              // scenes generated or rendered by this run
  int sceneCount = 0;
  std::vector<ReportSection> sections;
};

std::string formatQualityPage(const RunDescription& run);

}  // namespace taa::yardstick
