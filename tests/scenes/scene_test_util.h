// Helpers shared by the scene generator tests.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "scenegen/layered_scene.h"
#include "scenegen/scene.h"

namespace taa::scenes::test {

// The named scene as a LayeredScene (all scenes are layered for now); fails the test if not.
std::unique_ptr<LayeredScene> makeLayeredScene(const std::string& name, int width, int height);

// Bilinear sample of channel c at continuous raster position (x, y) (pixel centres at +0.5),
// clamped to the image.
float bilinear(const Image& image, double x, double y, int c);

// Separable Gaussian blur of every channel, edges clamped.
Image gaussianBlur(const Image& image, double sigma);

// Mean of each of the first four channels over the whole image.
glm::dvec4 channelMeans(const Image& image);

// A read-back EXR: channel name -> plane of width * height values, rows top first.
struct ExrPlanes {
  int width = 0;
  int height = 0;
  std::map<std::string, std::vector<float>> planes;
  std::string compression;
};
ExrPlanes readExr(const std::string& path);

// A fresh, empty folder under the test's temporary directory.
std::string freshTempDir(const std::string& name);

}  // namespace taa::scenes::test
