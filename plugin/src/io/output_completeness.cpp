#include "io/output_completeness.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <system_error>
#include <vector>

namespace taa::io {

OutputCheck checkOutputComplete(const std::string& path, const std::string& expectedOptions) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {false, "missing"};
  // The OpenEXR reader only: taa writes nothing else, and other formats' readers need not run.
  auto input = OIIO::ImageInput::create("openexr");
  OIIO::ImageSpec first;
  if (!input || !input->open(path, first)) {
    const std::string reason = input ? input->geterror() : OIIO::geterror();
    return {false, "cannot open as OpenEXR: " + reason};
  }
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
