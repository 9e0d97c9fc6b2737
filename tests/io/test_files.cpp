#include "test_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace taa::test {
namespace fs = std::filesystem;

std::string scratchFolderIn(const std::string& root) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder =
      fs::path(root) / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder.string();
}

OIIO::ImageSpec makeSpec(int width, int height, const std::vector<std::string>& channels) {
  OIIO::ImageSpec spec(width, height, static_cast<int>(channels.size()), OIIO::TypeFloat);
  spec.channelnames = channels;
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  return spec;
}

void writeImage(const std::string& path, const OIIO::ImageSpec& spec,
                const std::vector<float>& pixels) {
  if (pixels.size() != std::size_t(spec.width) * spec.height * spec.nchannels) {
    throw std::runtime_error("writeImage: pixel count does not match the spec");
  }
  auto output = OIIO::ImageOutput::create(path);
  if (!output) throw std::runtime_error("writeImage: " + OIIO::geterror());
  if (!output->open(path, spec) || !output->write_image(OIIO::TypeFloat, pixels.data()) ||
      !output->close()) {
    throw std::runtime_error("writeImage: " + output->geterror());
  }
}

std::vector<float> readImage(const std::string& path, OIIO::ImageSpec& spec) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw std::runtime_error("readImage: " + OIIO::geterror());
  spec = input->spec();
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels.data())) {
    throw std::runtime_error("readImage: " + input->geterror());
  }
  return pixels;
}

void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  if (!file) throw std::runtime_error("writeTextFile: cannot write " + path);
}

std::vector<std::string> listFolder(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

Error errorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "expected a taa::Error";
  return Error("no error");
}

}  // namespace taa::test
