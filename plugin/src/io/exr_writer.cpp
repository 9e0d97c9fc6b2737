#include "io/exr_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <future>
#include <system_error>

#include <Imath/half.h>
#include <OpenImageIO/filesystem.h>

#include "io/scanline_bands.h"
#include "io/temporary_file.h"
#include "taa/error.h"

namespace taa::io {
namespace fs = std::filesystem;

namespace {

bool equalsIgnoringCase(const std::string& a, const std::string& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// Template attributes that describe the old file's layout, encoding or part structure rather
// than the picture. The output gets its own; copying these would describe a file we do not write.
bool describesOldLayout(const std::string& name) {
  static const char* const kLayoutAttributes[] = {
      "compression",          "BlenderMultiChannel",  "multiView",
      "name",                 "type",                 "version",
      "chunkCount",           "view",                 "tiles",
      "channels",             "planarconfig",         "textureformat",
      "wrapmodes",            "oiio:subimages",       "oiio:subimagename",
      "oiio:BitsPerSample",   "openexr:chunkCount",   "openexr:dwaCompressionLevel",
      "openexr:levelmode",    "openexr:roundingmode", "openexr:lineOrder",
  };
  for (const char* layoutName : kLayoutAttributes) {
    if (equalsIgnoringCase(name, layoutName)) return true;
  }
  return false;
}

bool isNumber(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && value >= 0.0;
}

// Stores `value` at `to` as the file's type of that channel.
inline unsigned char* storeAs(OIIO::TypeDesc type, float value, unsigned char* to) {
  if (type == OIIO::TypeHalf) {
    const Imath::half h(value);
    std::memcpy(to, &h, sizeof h);
    return to + sizeof h;
  }
  std::memcpy(to, &value, sizeof value);
  return to + sizeof value;
}

// RGBA followed by the extra channels, each in the file's type of that channel, a band of rows
// at a time (write_scanlines with TypeUnknown takes every channel in its own type): no copy of
// the whole frame is made, and OIIO converts nothing. The next band is packed on another thread
// while OpenEXR codes this one (its coding waits for whole bands; packing a render's every pass
// from the sums is a third of the writing's time, measured in docs/PERFORMANCE.md).
bool writeBands(OIIO::ImageOutput& output, const OIIO::ImageSpec& spec, const ImageView& rgba,
                const ExtraChannels& extra) {
  const std::size_t width = std::size_t(rgba.width);
  std::size_t pixelBytes = 0;
  for (int c = 0; c < spec.nchannels; ++c) pixelBytes += spec.channelformat(c).size();
  std::vector<OIIO::TypeDesc> types(std::size_t(spec.nchannels));
  for (int c = 0; c < spec.nchannels; ++c) types[std::size_t(c)] = spec.channelformat(c);
  const auto* halfColour = static_cast<const Imath::half*>(rgba.data);
  const auto* floatColour = static_cast<const float*>(rgba.data);
  const std::size_t extraCount = std::size_t(extra.image.channels);
  std::size_t packedBytes = 0;  // a pixel's packed extra channels (ExtraChannels::packed)
  for (int c = 4; c < spec.nchannels; ++c) packedBytes += spec.channelformat(c).size();
  // A band of rows at a time (io/scanline_bands): 32 rows of a render's every pass at 1920
  // pixels in their own types are 12 MB, where a frame interleaved as float would be 590.
  const int bandRows = rowsPerBand(spec);
  auto pack = [&](int y, unsigned char* band) {
    const int rows = std::min(bandRows, rgba.height - y);
    unsigned char* to = band;
    if (extra.packed.rows) {
      // Packed on demand (ExtraChannels::Packed::rows): straight into the band, after each
      // pixel's colour.
      extra.packed.rows(std::size_t(y) * width, std::size_t(rows) * width,
                        band + (pixelBytes - packedBytes), pixelBytes);
    }
    for (std::size_t i = std::size_t(y) * width, end = i + std::size_t(rows) * width; i < end;
         ++i) {
      for (std::size_t c = 0; c < 4; ++c) {
        const float v = rgba.type == SampleType::Half ? float(halfColour[4 * i + c])
                                                      : floatColour[4 * i + c];
        to = storeAs(types[c], v, to);
      }
      if (extra.isPacked()) {
        if (!extra.packed.rows) std::memcpy(to, &extra.packed.bytes[i * packedBytes], packedBytes);
        to += packedBytes;
        continue;
      }
      const float* more = &extra.image.pixels[i * extraCount];
      for (std::size_t c = 0; c < extraCount; ++c) to = storeAs(types[4 + c], more[c], to);
    }
  };
  std::array<std::vector<unsigned char>, 2> bands;
  for (auto& band : bands) band.resize(std::size_t(bandRows) * width * pixelBytes);
  pack(0, bands[0].data());
  for (int y = 0, k = 0; y < rgba.height; y += bandRows, ++k) {
    const int rows = std::min(bandRows, rgba.height - y);
    // The next band packed meanwhile (waited for before this function returns or throws).
    std::future<void> next;
    if (y + bandRows < rgba.height) {
      next = std::async(std::launch::async, pack, y + bandRows, bands[(k + 1) % 2].data());
    }
    const bool written = output.write_scanlines(spec.y + y, spec.y + y + rows, 0,
                                                OIIO::TypeUnknown, bands[k % 2].data());
    if (next.valid()) next.get();
    if (!written) return false;
  }
  return true;
}

// The compression attribute for OIIO: a bare zip or zips gets taa's default level.
std::string compressionAttribute(const std::string& compression) {
  if (compression == "zip" || compression == "zips") {
    return compression + ":" + std::to_string(kDefaultZipLevel);
  }
  return compression;
}

std::vector<std::string> colorNames(const WriteOptions& options) {
  if (options.rgbaNames.empty()) return {"R", "G", "B", "A"};
  return options.rgbaNames;
}

OIIO::TypeDesc colorFormat(const WriteOptions& options, const OIIO::ImageSpec& templateSpec,
                           bool hasTemplate) {
  switch (options.pixelType) {
    case PixelType::Half: return OIIO::TypeHalf;
    case PixelType::Float: return OIIO::TypeFloat;
    case PixelType::AsInput: break;
  }
  if (!hasTemplate) return OIIO::TypeFloat;
  const std::string first = colorNames(options).front();
  OIIO::TypeDesc format = templateSpec.format;
  for (int c = 0; c < templateSpec.nchannels; ++c) {
    if (templateSpec.channel_name(c) == first) format = templateSpec.channelformat(c);
  }
  return format == OIIO::TypeHalf ? OIIO::TypeHalf : OIIO::TypeFloat;
}

OIIO::ImageSpec makeOutputSpec(const ImageView& rgba, const OIIO::ImageSpec& templateSpec,
                               const WriteOptions& options, const ExtraChannels& extra) {
  const bool hasTemplate = templateSpec.width > 0 && templateSpec.height > 0;
  const OIIO::TypeDesc format = colorFormat(options, templateSpec, hasTemplate);
  OIIO::ImageSpec spec(rgba.width, rgba.height, 4 + int(extra.names.size()), format);
  spec.channelnames = colorNames(options);
  spec.channelnames.insert(spec.channelnames.end(), extra.names.begin(), extra.names.end());
  spec.alpha_channel = 3;
  if (!extra.formats.empty()) {
    spec.channelformats.assign(4, format);
    spec.channelformats.insert(spec.channelformats.end(), extra.formats.begin(),
                               extra.formats.end());
  }
  if (hasTemplate) {
    spec.x = templateSpec.x;
    spec.y = templateSpec.y;
    spec.full_x = templateSpec.full_x;
    spec.full_y = templateSpec.full_y;
    spec.full_width = templateSpec.full_width > 0 ? templateSpec.full_width : rgba.width;
    spec.full_height = templateSpec.full_height > 0 ? templateSpec.full_height : rgba.height;
    for (const OIIO::ParamValue& attribute : templateSpec.extra_attribs) {
      if (!describesOldLayout(attribute.name().string())) spec.extra_attribs.push_back(attribute);
    }
  }
  spec.attribute("compression", compressionAttribute(options.compression));
  if (!options.views.empty()) {
    std::vector<const char*> views;
    for (const std::string& view : options.views) views.push_back(view.c_str());
    spec.attribute("multiView", OIIO::TypeDesc(OIIO::TypeDesc::STRING, int(views.size())),
                   views.data());
  }
  return spec;
}

std::string firstDuplicate(const std::vector<std::string>& names) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (std::size_t j = i + 1; j < names.size(); ++j) {
      if (names[i] == names[j]) return names[i];
    }
  }
  return "";
}

// writeExrAtomic for either sample type.
void writeView(const std::string& path, const ImageView& rgba, const OIIO::ImageSpec& templateSpec,
               const WriteOptions& options, const ExtraChannels& extra) {
  const ErrorContext context{path, std::nullopt, ""};
  try {
    validateCompression(options.compression);
  } catch (const Error& error) {
    throw Error(error.description(), context);
  }
  if (rgba.channels != 4 || !rgba) {
    throw Error("the image to write must have 4 channels (RGBA) and pixels", context);
  }
  if (!extra.formats.empty() && extra.formats.size() != extra.names.size()) {
    throw Error("extra channel formats must match their names", context);
  }
  if (extra.isPacked()) {
    std::size_t pixelBytes = 0;
    for (const OIIO::TypeDesc& format : extra.formats) {
      if (format != OIIO::TypeHalf && format != OIIO::TypeFloat) {
        throw Error("packed extra channels must be half or float", context);
      }
      pixelBytes += format.size();
    }
    if (extra.formats.empty() || extra.packed.width != rgba.width ||
        extra.packed.height != rgba.height ||
        (!extra.packed.rows &&
         extra.packed.bytes.size() != pixelBytes * std::size_t(rgba.width) * rgba.height)) {
      throw Error("packed extra channels must match their formats and the image size", context);
    }
  } else if (!extra.names.empty() &&
             (int(extra.names.size()) != extra.image.channels ||
              extra.image.width != rgba.width || extra.image.height != rgba.height)) {
    throw Error("extra channels must match their names and the image size", context);
  }
  if (colorNames(options).size() != 4) {
    throw Error("the output needs 4 color channel names, " +
                    std::to_string(options.rgbaNames.size()) + " given",
                context);
  }
  std::vector<std::string> allNames = colorNames(options);
  allNames.insert(allNames.end(), extra.names.begin(), extra.names.end());
  if (const std::string twice = firstDuplicate(allNames); !twice.empty()) {
    throw Error("output channel " + twice + " is named twice", {path, std::nullopt, twice});
  }
  const bool hasTemplate = templateSpec.width > 0 && templateSpec.height > 0;
  if (hasTemplate && (rgba.width != templateSpec.width || rgba.height != templateSpec.height)) {
    throw Error("the image to write is " + std::to_string(rgba.width) + "x" +
                    std::to_string(rgba.height) + " but its template's data window is " +
                    std::to_string(templateSpec.width) + "x" +
                    std::to_string(templateSpec.height),
                context);
  }

  const fs::path finalPath(path);
  const fs::path folder = finalPath.parent_path().empty() ? fs::path(".") : finalPath.parent_path();
  std::error_code folderError;
  fs::create_directories(folder, folderError);
  if (folderError || !fs::is_directory(folder)) {
    const std::string reason = folderError ? folderError.message() : "not a folder";
    throw Error("cannot create the output folder " + folder.string() + ": " + reason, context);
  }

  TemporaryFile temporary(finalPath);
  const OIIO::ImageSpec spec = makeOutputSpec(rgba, templateSpec, options, extra);
  // Ask for the EXR writer by name: the final path's extension must not choose the format.
  auto output = OIIO::ImageOutput::create("openexr");
  if (!output) throw Error("cannot create an OpenEXR writer: " + OIIO::geterror(), context);
  const auto fail = [&](const std::string& what) {
    std::string reason = output->geterror();
    if (reason.empty()) reason = "unknown error";
    throw Error(what + ": " + reason, context);
  };
  // Through the file TemporaryFile opened: the writer never opens a path itself.
  OIIO::Filesystem::IOFile proxy(temporary.stream(), OIIO::Filesystem::IOProxy::Write);
  if (!output->supports("ioproxy") || !output->set_ioproxy(&proxy)) {
    fail("the OpenEXR writer cannot write through an open file");
  }
  if (!output->open(temporary.path().string(), spec)) fail("cannot open for writing");
  // Without extra channels the samples go to OIIO as they are (converted only into a file of
  // the other type); with them, each channel is packed in its own type, band by band.
  bool written = false;
  if (extra.names.empty()) {
    const OIIO::TypeDesc type = rgba.type == SampleType::Half ? OIIO::TypeHalf : OIIO::TypeFloat;
    written = output->write_image(type, rgba.data);
  } else {
    written = writeBands(*output, spec, rgba, extra);
  }
  if (!written) fail("cannot write pixels");
  if (!output->close() || output->has_error()) fail("cannot finish writing");
  output.reset();
  temporary.commitAs(finalPath);
}

}  // namespace

PixelType parsePixelType(const std::string& text) {
  if (text == "half") return PixelType::Half;
  if (text == "float") return PixelType::Float;
  if (text == "input") return PixelType::AsInput;
  throw Error("unknown pixel type \"" + text + "\" (expected half, float or input)");
}

void unpackExtraChannels(ExtraChannels& extra) {
  if (!extra.isPacked()) return;
  const std::size_t channels = extra.names.size();
  if (extra.packed.rows) {
    std::size_t pixelBytes = 0;
    for (const OIIO::TypeDesc& format : extra.formats) pixelBytes += format.size();
    const std::size_t pixels = std::size_t(extra.packed.width) * std::size_t(extra.packed.height);
    extra.packed.bytes.resize(pixels * pixelBytes);
    extra.packed.rows(0, pixels, extra.packed.bytes.data(), pixelBytes);
  }
  extra.image = Image(extra.packed.width, extra.packed.height, int(channels));
  const unsigned char* from = extra.packed.bytes.data();
  for (std::size_t i = 0, n = extra.image.pixels.size() / channels; i < n; ++i) {
    for (std::size_t c = 0; c < channels; ++c) {
      if (extra.formats[c] == OIIO::TypeHalf) {
        Imath::half h;
        std::memcpy(&h, from, sizeof h);
        extra.image.pixels[i * channels + c] = h;
        from += sizeof h;
      } else {
        std::memcpy(&extra.image.pixels[i * channels + c], from, sizeof(float));
        from += sizeof(float);
      }
    }
  }
  extra.packed = ExtraChannels::Packed();
}

void appendExtraChannels(ExtraChannels& extra, ExtraChannels more) {
  if (more.names.empty()) return;
  if (extra.names.empty()) {
    extra = std::move(more);
    return;
  }
  // Rare (pass-through or diagnostics beside packed passes): joined as float.
  unpackExtraChannels(extra);
  unpackExtraChannels(more);
  const int channels = extra.image.channels + more.image.channels;
  Image joined(extra.image.width, extra.image.height, channels);
  for (std::size_t i = 0, n = std::size_t(joined.width) * joined.height; i < n; ++i) {
    std::copy_n(&extra.image.pixels[i * extra.image.channels], extra.image.channels,
                &joined.pixels[i * channels]);
    std::copy_n(&more.image.pixels[i * more.image.channels], more.image.channels,
                &joined.pixels[i * channels + extra.image.channels]);
  }
  const bool typed = !extra.formats.empty() || !more.formats.empty();
  if (typed) {
    // An untyped side follows the color's type: written as float, the widest choice.
    if (extra.formats.empty()) extra.formats.assign(extra.names.size(), OIIO::TypeFloat);
    std::vector<OIIO::TypeDesc> moreFormats = more.formats;
    if (moreFormats.empty()) moreFormats.assign(more.names.size(), OIIO::TypeFloat);
    extra.formats.insert(extra.formats.end(), moreFormats.begin(), moreFormats.end());
  }
  extra.names.insert(extra.names.end(), more.names.begin(), more.names.end());
  extra.image = std::move(joined);
}

void validateCompression(const std::string& compression) {
  static const char* const kCompressions[] = {"none", "rle",   "zips", "zip",  "piz",
                                              "pxr24", "b44", "b44a", "dwaa", "dwab"};
  const std::size_t colon = compression.find(':');
  const std::string name = compression.substr(0, colon);
  const bool known = std::any_of(std::begin(kCompressions), std::end(kCompressions),
                                 [&](const char* candidate) { return name == candidate; });
  const std::string expected =
      " (expected none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa or dwab, "
      "optionally with :level for zip, zips, dwaa and dwab)";
  if (!known) throw Error("unknown EXR compression \"" + compression + "\"" + expected);
  if (colon == std::string::npos) return;
  const bool zip = name == "zip" || name == "zips";
  const bool takesLevel = zip || name == "dwaa" || name == "dwab";
  const std::string level = compression.substr(colon + 1);
  if (!takesLevel || !isNumber(level)) {
    throw Error("bad EXR compression level in \"" + compression + "\"" + expected);
  }
  // zlib knows levels 1 to 9 (0 would store uncompressed); DWA's level is a positive quality.
  const double value = std::strtod(level.c_str(), nullptr);
  const bool inRange = zip ? level.size() == 1 && value >= 1.0 && value <= 9.0
                           : value > 0.0 && std::isfinite(value);
  if (!inRange) {
    throw Error("EXR compression level out of range in \"" + compression + "\" (" +
                (zip ? "zip and zips take 1 to 9" : "dwaa and dwab take a level above 0") + ")");
  }
}

SampleType outputSampleType(const WriteOptions& options, const OIIO::ImageSpec& templateSpec) {
  const bool hasTemplate = templateSpec.width > 0 && templateSpec.height > 0;
  return colorFormat(options, templateSpec, hasTemplate) == OIIO::TypeHalf ? SampleType::Half
                                                                          : SampleType::Float;
}

void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options, const ExtraChannels& extra) {
  writeView(path, &rgba, templateSpec, options, extra);
}

void writeExrAtomic(const std::string& path, const TypedImage& rgba,
                    const OIIO::ImageSpec& templateSpec, const WriteOptions& options,
                    const ExtraChannels& extra) {
  writeView(path, &rgba, templateSpec, options, extra);
}

}  // namespace taa::io
