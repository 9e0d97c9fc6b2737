#include "farm_files.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

namespace taa::test {
namespace {

struct Part {
  OIIO::ImageSpec spec;
  std::vector<unsigned char> pixels;  // native types, as stored
};

std::vector<Part> readParts(const std::string& path, std::string& error) {
  std::vector<Part> parts;
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = "cannot open " + path + ": " + OIIO::geterror();
    return parts;
  }
  for (int p = 0; in->seek_subimage(p, 0); ++p) {
    Part part{in->spec(), {}};
    part.pixels.resize(part.spec.image_bytes(true));
    if (!in->read_image(p, 0, 0, part.spec.nchannels, OIIO::TypeUnknown, part.pixels.data())) {
      error = "cannot read " + path + ": " + in->geterror();
      return {};
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::string attributes(const OIIO::ImageSpec& spec) {
  std::string text;
  for (const OIIO::ParamValue& p : spec.extra_attribs) {
    if (p.name() == "DateTime") continue;
    text += p.name().string() + "=" + p.get_string(1 << 20) + "\n";
  }
  return text;
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

std::string frameDifference(const std::string& a, const std::string& b) {
  const std::string bytesA = bytesOf(a);
  if (!bytesA.empty() && bytesA == bytesOf(b)) return "";
  std::string error;
  const std::vector<Part> pa = readParts(a, error), pb = readParts(b, error);
  if (!error.empty()) return error;
  if (pa.size() != pb.size()) return "part counts differ";
  for (std::size_t p = 0; p < pa.size(); ++p) {
    const OIIO::ImageSpec &sa = pa[p].spec, &sb = pb[p].spec;
    if (sa.channelnames != sb.channelnames) return "channel names differ";
    if (sa.channelformats != sb.channelformats || sa.format != sb.format) {
      return "pixel types differ";
    }
    if (sa.x != sb.x || sa.y != sb.y || sa.width != sb.width || sa.height != sb.height ||
        sa.full_x != sb.full_x || sa.full_y != sb.full_y || sa.full_width != sb.full_width ||
        sa.full_height != sb.full_height) {
      return "windows differ";
    }
    if (attributes(sa) != attributes(sb)) {
      return "attributes differ:\n" + attributes(sa) + "vs\n" + attributes(sb);
    }
    if (pa[p].pixels != pb[p].pixels) return "pixels differ in part " + std::to_string(p);
  }
  return "";  // the same frame; the files differ in DateTime or in how they are laid out
}

ToneDifference toneDifference(const std::string& a, const std::string& b) {
  auto rgb = [](const std::string& path) {
    std::vector<float> pixels;
    auto in = OIIO::ImageInput::open(path);
    if (!in) return pixels;
    const OIIO::ImageSpec& spec = in->spec();
    pixels.resize(spec.image_pixels() * 3);
    in->read_image(0, 0, 0, 3, OIIO::TypeFloat, pixels.data());
    return pixels;
  };
  const std::vector<float> x = rgb(a), y = rgb(b);
  ToneDifference d;
  if (x.empty() || x.size() != y.size()) {
    d.maxAbs = d.meanAbs = std::numeric_limits<double>::infinity();
    return d;
  }
  auto tone = [](float v) { return v > 0 ? double(v) / (1.0 + v) : 0.0; };
  double sum = 0, squares = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double e = std::abs(tone(x[i]) - tone(y[i]));
    d.maxAbs = std::max(d.maxAbs, e);
    sum += e;
    squares += e * e;
  }
  d.meanAbs = sum / double(x.size());
  const double mse = squares / double(x.size());
  d.psnr = mse > 0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  return d;
}

std::vector<std::string> linesStartingWith(const std::string& text, const std::string& prefix) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
  }
  return lines;
}

}  // namespace taa::test
