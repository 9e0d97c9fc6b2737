#include "io/frame_reader.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <memory>
#include <system_error>

#include "io/sequence_pattern.h"
#include "taa/error.h"

namespace taa::io {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

std::string joinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string describeWindow(const OIIO::ImageSpec& spec) {
  return std::to_string(spec.width) + "x" + std::to_string(spec.height) + " at (" +
         std::to_string(spec.x) + ", " + std::to_string(spec.y) + ")";
}

// An open EXR file, shared by every AOV that lives in it.
struct OpenExr {
  std::string path;
  std::unique_ptr<OIIO::ImageInput> input;
};

// Opens `path` and insists that OIIO read it as OpenEXR: a PNG named .exr must not slip through.
OpenExr openExr(const std::string& path, const std::string& aovName, int frame) {
  const ErrorContext context{path, frame, ""};
  std::error_code ignored;
  if (!std::filesystem::exists(path, ignored)) {
    throw Error("cannot find the " + aovName + " file", context);
  }
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    // OIIO keeps the reason in its global error state when open() fails.
    throw Error("cannot read the " + aovName + " file as OpenEXR: " + OIIO::geterror(), context);
  }
  const std::string format = input->format_name();
  if (format != "openexr") {
    throw Error("the " + aovName + " file is not an OpenEXR file (it reads as " + format + ")",
                context);
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.deep) throw Error("deep EXR files are not supported", context);
  if (spec.depth != 1) throw Error("volume (3D) EXR files are not supported", context);
  return {path, std::move(input)};
}

// Reads `names` from subimage 0, in the order asked. EXR sorts channels by name, so the file
// order differs from the asked order: one read covers the smallest contiguous range holding
// every asked channel, then the asked ones are picked out.
Image readChannels(OpenExr& file, const std::vector<std::string>& names,
                   const std::string& aovName, int frame) {
  const OIIO::ImageSpec& spec = file.input->spec();
  std::vector<int> indices;
  std::vector<std::string> missing;
  for (const std::string& name : names) {
    const auto found = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    if (found == spec.channelnames.end()) {
      missing.push_back(name);
    } else {
      indices.push_back(static_cast<int>(found - spec.channelnames.begin()));
    }
  }
  if (!missing.empty()) {
    throw Error("the " + aovName + " file lacks channel" + (missing.size() > 1 ? "s " : " ") +
                    joinNames(missing) + "; channels available: " +
                    joinNames(spec.channelnames),
                {file.path, frame, joinNames(missing)});
  }

  const int channelBegin = *std::min_element(indices.begin(), indices.end());
  const int channelEnd = *std::max_element(indices.begin(), indices.end()) + 1;
  const int stride = channelEnd - channelBegin;
  const std::size_t pixelCount = std::size_t(spec.width) * spec.height;
  std::vector<float> buffer(pixelCount * stride);
  // OIIO may report a failure only through its error state, so check both.
  const bool ok = file.input->read_image(0, 0, channelBegin, channelEnd, OIIO::TypeFloat,
                                         buffer.data());
  if (!ok || file.input->has_error()) {
    std::string reason = file.input->geterror();
    if (reason.empty()) reason = "unknown error";
    throw Error("cannot read the " + aovName + " pixels (truncated or corrupt file?): " + reason,
                {file.path, frame, joinNames(names)});
  }

  Image image(spec.width, spec.height, static_cast<int>(names.size()));
  for (std::size_t pixel = 0; pixel < pixelCount; ++pixel) {
    for (std::size_t c = 0; c < indices.size(); ++c) {
      image.pixels[pixel * indices.size() + c] =
          buffer[pixel * stride + std::size_t(indices[c] - channelBegin)];
    }
  }
  return image;
}

// Opens files once per frame, however many AOVs share them.
class FileSet {
 public:
  explicit FileSet(int frame) : frame_(frame) {}

  OpenExr& get(const std::string& path, const std::string& aovName) {
    for (OpenExr& file : files_) {
      if (file.path == path) return file;
    }
    files_.push_back(openExr(path, aovName, frame_));
    return files_.back();
  }

 private:
  int frame_;
  std::deque<OpenExr> files_;  // a deque keeps references valid as files are added
};

void requireChannelCount(const AovSource& source, std::size_t low, std::size_t high,
                         const std::string& aovName, int frame) {
  const std::size_t count = source.channels.size();
  if (count < low || count > high) {
    const std::string wanted = low == high ? std::to_string(low)
                                           : std::to_string(low) + " or " + std::to_string(high);
    throw Error("the " + aovName + " needs " + wanted + " channels, " + std::to_string(count) +
                    " given",
                {"", frame, joinNames(source.channels)});
  }
}

// Every AOV must cover exactly the color's pixels; resampling is not taa's job.
void requireSameWindow(const OpenExr& file, const OIIO::ImageSpec& colorSpec,
                       const std::string& aovName, int frame) {
  const OIIO::ImageSpec& spec = file.input->spec();
  if (spec.x != colorSpec.x || spec.y != colorSpec.y || spec.width != colorSpec.width ||
      spec.height != colorSpec.height) {
    throw Error("the " + aovName + " data window " + describeWindow(spec) +
                    " differs from the color data window " + describeWindow(colorSpec),
                {file.path, frame, ""});
  }
}

std::string aovPath(const AovSource& source, const std::string& colorPath, int frame) {
  return source.pattern.empty() ? colorPath : expandFramePattern(source.pattern, frame);
}

Image toRgba(const Image& color, int& nonFiniteCount, Image& nonFiniteMask) {
  Image rgba(color.width, color.height, 4);
  nonFiniteMask = Image(color.width, color.height, 1);
  const std::size_t pixelCount = std::size_t(color.width) * color.height;
  for (std::size_t pixel = 0; pixel < pixelCount; ++pixel) {
    float* out = &rgba.pixels[pixel * 4];
    const float* in = &color.pixels[pixel * color.channels];
    out[3] = 1.0f;  // a color without alpha is opaque
    for (int c = 0; c < color.channels; ++c) {
      if (std::isfinite(in[c])) {
        out[c] = in[c];
      } else {
        out[c] = 0.0f;
        ++nonFiniteCount;
        nonFiniteMask.pixels[pixel] = 1.0f;
      }
    }
  }
  return rgba;
}

void convertDepth(Image& depth, const DepthConvention& convention) {
  for (float& value : depth.pixels) {
    // NaN and -inf carry no distance either: treat them as "no hit" too.
    if (!std::isfinite(value) || value >= convention.noHitAbove) value = kInfinity;
  }
}

void convertMotion(Image& motion, const MotionConvention& convention) {
  const float xFactor = convention.scale * (convention.toPrevious ? 1.0f : -1.0f);
  const float yFactor = xFactor * (convention.yUp ? -1.0f : 1.0f);
  for (std::size_t i = 0; i + 1 < motion.pixels.size(); i += 2) {
    const float x = motion.pixels[i] * xFactor;
    const float y = motion.pixels[i + 1] * yFactor;
    motion.pixels[i] = std::isfinite(x) ? x : 0.0f;
    motion.pixels[i + 1] = std::isfinite(y) ? y : 0.0f;
  }
}

// The header's camera, if it has both matrices. EXR matrices act on row vectors (p' = p M) and
// are stored row by row; read as GLM's column-major storage, that is exactly the transpose,
// which acts on column vectors as GLM expects.
std::optional<FrameCamera> headerCamera(const OIIO::ImageSpec& spec) {
  const OIIO::ParamValue* toCamera = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
  const OIIO::ParamValue* toNdc = spec.find_attribute("worldToNDC", OIIO::TypeMatrix44);
  if (!toCamera || !toNdc) return std::nullopt;
  FrameCamera camera;
  camera.worldToCamera = glm::dmat4(glm::make_mat4(static_cast<const float*>(toCamera->data())));
  camera.worldToNdc = glm::dmat4(glm::make_mat4(static_cast<const float*>(toNdc->data())));
  return camera;
}

}  // namespace

FrameData readFrame(const AovLayout& layout, int frame) {
  if (layout.color.pattern.empty()) {
    throw Error("no color file pattern given", {"", frame, ""});
  }
  requireChannelCount(layout.color, 3, 4, "color", frame);
  if (layout.depth) requireChannelCount(*layout.depth, 1, 1, "depth", frame);
  if (layout.motion) requireChannelCount(*layout.motion, 2, 2, "motion", frame);

  FrameData data;
  data.frame = frame;
  data.colorPath = expandFramePattern(layout.color.pattern, frame);

  FileSet files(frame);
  OpenExr& colorFile = files.get(data.colorPath, "color");
  data.colorSpec = colorFile.input->spec();
  data.color = toRgba(readChannels(colorFile, layout.color.channels, "color", frame),
                      data.nonFiniteColorValues, data.nonFiniteMask);
  data.camera = headerCamera(data.colorSpec);
  data.window = {data.colorSpec.x - data.colorSpec.full_x, data.colorSpec.y - data.colorSpec.full_y,
                 data.colorSpec.full_width > 0 ? data.colorSpec.full_width : data.colorSpec.width,
                 data.colorSpec.full_height > 0 ? data.colorSpec.full_height
                                                : data.colorSpec.height};

  if (layout.depth) {
    OpenExr& file = files.get(aovPath(*layout.depth, data.colorPath, frame), "depth");
    requireSameWindow(file, data.colorSpec, "depth", frame);
    data.depth = readChannels(file, layout.depth->channels, "depth", frame);
    convertDepth(data.depth, layout.depthConvention);
  }
  if (layout.motion) {
    OpenExr& file = files.get(aovPath(*layout.motion, data.colorPath, frame), "motion");
    requireSameWindow(file, data.colorSpec, "motion", frame);
    data.motion = readChannels(file, layout.motion->channels, "motion", frame);
    convertMotion(data.motion, layout.motionConvention);
  }
  return data;
}

}  // namespace taa::io
