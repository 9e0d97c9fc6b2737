// A scene made ready for measuring, whatever made it (taa-scenegen or Blender): how taatool
// reads it, the reference its outputs are scored against, and any fixed reference sequences
// (SSAA-N) that get rows of their own.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "util/image.h"
#include "yardstick/sequence_score.h"

namespace taa::yardstick {

struct PreparedScene {
  std::string name;
  std::string description;
  std::vector<std::string> taatoolInputs;  // the input pattern and the flags that read it
  Reference reference;
  // Rows besides raw and the configurations: name -> tonemapped frames ("ssaa-4", ...), each
  // with the samples per pixel it stands for.
  struct FixedRow {
    std::string name;
    int samplesPerPixel = 0;
    std::vector<Image> frames;
  };
  std::vector<FixedRow> fixedRows;
  bool made = false;     // generated or rendered by this run (else cached)
  double seconds = 0.0;  // spent making it
};

}  // namespace taa::yardstick
