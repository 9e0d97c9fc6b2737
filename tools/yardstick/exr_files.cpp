#include "yardstick/exr_files.h"

#include <OpenImageIO/imageio.h>

#include "taa/error.h"

namespace taa::yardstick {

ExrFile readExr(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw Error("cannot open EXR: " + OIIO::geterror(), {path});
  const OIIO::ImageSpec& spec = input->spec();
  ExrFile file;
  file.image = Image(spec.width, spec.height, spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                         file.image.pixels.data())) {
    throw Error("cannot read EXR: " + input->geterror(), {path});
  }
  file.shot = spec.get_int_attribute("taa:shot", 0);
  return file;
}

}  // namespace taa::yardstick
