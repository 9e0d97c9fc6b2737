#include "io/output_completeness.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <system_error>
#include <vector>

namespace taa::io {

OutputCheck checkOutputComplete(const std::string& path, const std::string& expectedOptions) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {false, "missing"};
  auto input = OIIO::ImageInput::open(path);
  if (!input) return {false, "cannot open: " + OIIO::geterror()};
  if (std::string(input->format_name()) != "openexr") return {false, "not an OpenEXR file"};
  const OIIO::ImageSpec first = input->spec();
  if (first.get_string_attribute("taa:version").empty()) {
    return {false, "no taa:version attribute (not written by taa)"};
  }
  const std::string options = first.get_string_attribute("taa:options");
  if (options.empty()) return {false, "no taa:options attribute"};
  if (!expectedOptions.empty() && options != expectedOptions) {
    return {false, "resolved with other options (taa:options differs)"};
  }
  std::vector<float> pixels;
  for (int part = 0; input->seek_subimage(part, 0); ++part) {
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.deep) return {false, "deep part " + std::to_string(part) + " (taa writes none)"};
    pixels.resize(spec.image_pixels() * std::size_t(spec.nchannels));
    // OIIO may report a failure only through its error state, so check both.
    if (!input->read_image(part, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels.data()) ||
        input->has_error()) {
      std::string reason = input->geterror();
      if (reason.empty()) reason = "unknown error";
      return {false, "cannot read the pixels of part " + std::to_string(part) +
                         " (truncated or corrupt): " + reason};
    }
  }
  return {true, ""};
}

}  // namespace taa::io
