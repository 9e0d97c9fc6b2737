// Reading the yardstick's EXR files (generated scenes, taatool's output) into images.
#pragma once

#include <string>
#include <vector>

#include "util/image.h"

namespace taa::yardstick {

struct ExrFile {
  Image image;  // every channel, in file order
  int shot = 0;  // the "taa:shot" attribute (0 when absent)
};

// Reads a whole EXR as float; throws taa::Error naming the file.
ExrFile readExr(const std::string& path);

// Reads the named channels of an EXR's first part as float, in the order given (a multilayer
// file's "ViewLayer.Depth.Z", say); throws taa::Error naming the file and a missing channel.
Image readExrChannels(const std::string& path, const std::vector<std::string>& channels);

}  // namespace taa::yardstick
