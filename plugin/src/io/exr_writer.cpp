#include "io/exr_writer.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

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

// Removes the temporary file unless the write was committed (renamed into place).
class TemporaryFile {
 public:
  explicit TemporaryFile(fs::path path) : path_(std::move(path)) {}
  ~TemporaryFile() {
    if (!committed_) {
      std::error_code ignored;
      fs::remove(path_, ignored);
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const fs::path& path() const { return path_; }
  void commit() { committed_ = true; }

 private:
  fs::path path_;
  bool committed_ = false;
};

// RGBA followed by the extra channels, interleaved per pixel as the writer wants them.
std::vector<float> interleave(const Image& rgba, const ExtraChannels& extra) {
  const int channels = 4 + extra.image.channels;
  std::vector<float> pixels(std::size_t(rgba.width) * rgba.height * channels);
  for (std::size_t i = 0, n = std::size_t(rgba.width) * rgba.height; i < n; ++i) {
    std::copy_n(&rgba.pixels[i * 4], 4, &pixels[i * channels]);
    std::copy_n(&extra.image.pixels[i * extra.image.channels], extra.image.channels,
                &pixels[i * channels + 4]);
  }
  return pixels;
}

// ".<name>.taa-tmp-<pid>-<n>.exr": hidden, unique per process and call, and ending in .exr.
fs::path temporaryPathFor(const fs::path& finalPath) {
  static std::atomic<unsigned> counter{0};
  // Shortened so that the suffix cannot push a long name past the file system's 255 bytes.
  const std::string base = finalPath.filename().string().substr(0, 200);
  const std::string name = "." + base + ".taa-tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++) + ".exr";
  return finalPath.parent_path() / name;
}

OIIO::ImageSpec makeOutputSpec(const Image& rgba, const OIIO::ImageSpec& templateSpec,
                               const WriteOptions& options, const ExtraChannels& extra) {
  const OIIO::TypeDesc format =
      options.pixelType == PixelType::Half ? OIIO::TypeHalf : OIIO::TypeFloat;
  OIIO::ImageSpec spec(rgba.width, rgba.height, 4 + int(extra.names.size()), format);
  spec.channelnames = {"R", "G", "B", "A"};
  spec.channelnames.insert(spec.channelnames.end(), extra.names.begin(), extra.names.end());
  spec.alpha_channel = 3;
  const bool hasTemplate = templateSpec.width > 0 && templateSpec.height > 0;
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
  spec.attribute("compression", options.compression);
  return spec;
}

}  // namespace

PixelType parsePixelType(const std::string& text) {
  if (text == "half") return PixelType::Half;
  if (text == "float") return PixelType::Float;
  throw Error("unknown pixel type \"" + text + "\" (expected half or float)");
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
  const bool takesLevel = name == "zip" || name == "zips" || name == "dwaa" || name == "dwab";
  if (!takesLevel || !isNumber(compression.substr(colon + 1))) {
    throw Error("bad EXR compression level in \"" + compression + "\"" + expected);
  }
}

void writeExrAtomic(const std::string& path, const Image& rgba, const OIIO::ImageSpec& templateSpec,
                    const WriteOptions& options, const ExtraChannels& extra) {
  const ErrorContext context{path, std::nullopt, ""};
  try {
    validateCompression(options.compression);
  } catch (const Error& error) {
    throw Error(error.description(), context);
  }
  if (rgba.channels != 4 || rgba.empty()) {
    throw Error("the image to write must have 4 channels (RGBA) and pixels", context);
  }
  if (!extra.names.empty() &&
      (int(extra.names.size()) != extra.image.channels || extra.image.width != rgba.width ||
       extra.image.height != rgba.height)) {
    throw Error("extra channels must match their names and the image size", context);
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

  TemporaryFile temporary(temporaryPathFor(finalPath));
  const OIIO::ImageSpec spec = makeOutputSpec(rgba, templateSpec, options, extra);
  // Ask for the EXR writer by name: the final path's extension must not choose the format.
  auto output = OIIO::ImageOutput::create("openexr");
  if (!output) throw Error("cannot create an OpenEXR writer: " + OIIO::geterror(), context);
  const auto fail = [&](const std::string& what) {
    std::string reason = output->geterror();
    if (reason.empty()) reason = "unknown error";
    throw Error(what + ": " + reason, context);
  };
  if (!output->open(temporary.path().string(), spec)) fail("cannot open for writing");
  const std::vector<float> withExtra = extra.names.empty() ? std::vector<float>()
                                                             : interleave(rgba, extra);
  const float* pixels = extra.names.empty() ? rgba.pixels.data() : withExtra.data();
  if (!output->write_image(OIIO::TypeFloat, pixels)) fail("cannot write pixels");
  if (!output->close() || output->has_error()) fail("cannot finish writing");
  output.reset();

  // rename() replaces an existing file atomically on POSIX: readers see old or new, never half.
  if (std::rename(temporary.path().c_str(), finalPath.c_str()) != 0) {
    const int renameErrno = errno;
    throw Error("cannot move the written file into place: " +
                    std::string(std::strerror(renameErrno)),
                context);
  }
  temporary.commit();
}

}  // namespace taa::io
