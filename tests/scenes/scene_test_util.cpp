#include "scene_test_util.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "scenegen/scene_library.h"

namespace taa::scenes::test {

std::unique_ptr<LayeredScene> makeLayeredScene(const std::string& name, int width, int height) {
  std::unique_ptr<Scene> scene = makeScene(name, width, height);
  auto* layered = dynamic_cast<LayeredScene*>(scene.get());
  EXPECT_NE(layered, nullptr) << name << " is not a LayeredScene";
  if (!layered) return nullptr;
  scene.release();
  return std::unique_ptr<LayeredScene>(layered);
}

float bilinear(const Image& image, double x, double y, int c) {
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  auto texel = [&](int i, int j) {
    i = std::clamp(i, 0, image.width - 1);
    j = std::clamp(j, 0, image.height - 1);
    return double(image.at(i, j)[c]);
  };
  const double top = texel(x0, y0) * (1 - tx) + texel(x0 + 1, y0) * tx;
  const double bottom = texel(x0, y0 + 1) * (1 - tx) + texel(x0 + 1, y0 + 1) * tx;
  return float(top * (1 - ty) + bottom * ty);
}

Image gaussianBlur(const Image& image, double sigma) {
  const int radius = int(std::ceil(3.0 * sigma));
  std::vector<double> weights;
  double total = 0.0;
  for (int d = -radius; d <= radius; ++d) {
    weights.push_back(std::exp(-d * d / (2.0 * sigma * sigma)));
    total += weights.back();
  }
  for (double& weight : weights) weight /= total;
  // One pass along x or y; run twice.
  auto pass = [&](const Image& source, int stepX, int stepY) {
    Image result(source.width, source.height, source.channels);
    for (int j = 0; j < source.height; ++j) {
      for (int i = 0; i < source.width; ++i) {
        for (int c = 0; c < source.channels; ++c) {
          double sum = 0.0;
          for (int d = -radius; d <= radius; ++d) {
            const int x = std::clamp(i + d * stepX, 0, source.width - 1);
            const int y = std::clamp(j + d * stepY, 0, source.height - 1);
            sum += weights[d + radius] * source.at(x, y)[c];
          }
          result.at(i, j)[c] = float(sum);
        }
      }
    }
    return result;
  };
  return pass(pass(image, 1, 0), 0, 1);
}

glm::dvec4 channelMeans(const Image& image) {
  glm::dvec4 sum(0.0);
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      for (int c = 0; c < 4 && c < image.channels; ++c) sum[c] += image.at(i, j)[c];
    }
  }
  return sum / double(image.width) / double(image.height);
}

ExrPlanes readExr(const std::string& path) {
  ExrPlanes result;
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    ADD_FAILURE() << "cannot open " << path << ": " << OIIO::geterror();
    return result;
  }
  const OIIO::ImageSpec& spec = input->spec();
  result.width = spec.width;
  result.height = spec.height;
  result.compression = spec.get_string_attribute("compression");
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
      << input->geterror();
  for (int c = 0; c < spec.nchannels; ++c) {
    std::vector<float>& plane = result.planes[spec.channelnames[c]];
    plane.resize(std::size_t(spec.width) * spec.height);
    for (std::size_t k = 0; k < plane.size(); ++k) plane[k] = pixels[k * spec.nchannels + c];
  }
  return result;
}

std::string freshTempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(TAA_TEST_TMPDIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace taa::scenes::test
