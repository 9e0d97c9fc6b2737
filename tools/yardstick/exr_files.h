// Reading the yardstick's EXR files (generated scenes, taatool's output) into images.
#pragma once

#include <string>

#include "util/image.h"

namespace taa::yardstick {

struct ExrFile {
  Image image;  // every channel, in file order
  int shot = 0;  // the "taa:shot" attribute (0 when absent)
};

// Reads a whole EXR as float; throws taa::Error naming the file.
ExrFile readExr(const std::string& path);

}  // namespace taa::yardstick
