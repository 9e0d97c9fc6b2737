// The yardstick's results table (markdown) and the docs/QUALITY.md page around it.
#pragma once

#include <string>
#include <vector>

#include "yardstick/configurations.h"
#include "yardstick/sequence_score.h"

namespace taa::yardstick {

// The name of the raw-input row (the jittered beauty, no resolve).
inline const char* kRawRow = "raw";

struct ResultRow {
  std::string scene;
  std::string configuration;  // kRawRow or a configuration's name
  Scores scores;
};

// One row per scene and configuration in the given order, then one "mean" row per
// configuration (NaN figures are left out of the means and printed as "-").
std::string formatTable(const std::vector<ResultRow>& rows,
                        const std::vector<std::string>& configurationOrder);

// What the page records besides the table.
struct RunDescription {
  std::string command;       // the exact command that produced the table
  std::string date;          // UTC, ISO 8601
  std::string machine;       // GL renderer and CPU count
  std::string size;          // e.g. 320x180
  std::string frames;        // e.g. 1-24
  int warmup = 4;
  int ghostFrames = 4;
  std::vector<std::pair<std::string, int>> measuredFrames;  // scene -> frames in the means
  std::vector<std::pair<std::string, std::string>> scenes;  // scene -> description
  std::vector<Configuration> configurations;
  double seconds = 0.0;            // wall time of the whole run
  double generationSeconds = 0.0;  // of that, generating scenes
  int cachedScenes = 0;            // scenes found generated already
};

std::string formatQualityPage(const RunDescription& run, const std::string& table);

}  // namespace taa::yardstick
