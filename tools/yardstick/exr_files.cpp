#include "yardstick/exr_files.h"

#include <OpenImageIO/imageio.h>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

// Every channel of the first part as float, and the part's header.
Image readAll(const std::string& path, OIIO::ImageSpec& spec) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw Error("cannot open EXR: " + OIIO::geterror(), {path});
  spec = input->spec();
  Image image(spec.width, spec.height, spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    throw Error("cannot read EXR: " + input->geterror(), {path});
  }
  return image;
}

}  // namespace

ExrFile readExr(const std::string& path) {
  OIIO::ImageSpec spec;
  ExrFile file;
  file.image = readAll(path, spec);
  file.shot = spec.get_int_attribute("taa:shot", 0);
  return file;
}

Image readExrChannels(const std::string& path, const std::vector<std::string>& channels) {
  OIIO::ImageSpec spec;
  const Image all = readAll(path, spec);
  Image image(all.width, all.height, int(channels.size()));
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const int index = spec.channelindex(channels[c]);
    if (index < 0) throw Error("missing channel", {path, std::nullopt, channels[c]});
    for (std::size_t p = 0; p < std::size_t(all.width) * all.height; ++p) {
      image.pixels[p * channels.size() + c] = all.pixels[p * all.channels + index];
    }
  }
  return image;
}

}  // namespace taa::yardstick
