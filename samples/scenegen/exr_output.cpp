#include "scenegen/exr_output.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "taa/error.h"

namespace taa::scenes {
namespace {

// What Cycles writes for "no hit" in its depth pass.
constexpr float kCyclesNoHitDepth = 1e10f;

struct ExrImage {
  std::vector<std::string> channelNames;
  std::vector<float> pixels;  // interleaved in channelNames order, rows top first
};

// Interleaves `channels` of the images into one buffer; each entry picks image + channel and
// maps the value (so conventions can be converted on the way out).
struct ChannelSource {
  std::string name;
  const Image* image;
  int channel;
  float (*convert)(float);
};

float identity(float v) { return v; }
float negate(float v) { return -v; }
float cyclesDepth(float v) { return std::isinf(v) ? kCyclesNoHitDepth : v; }

ExrImage interleave(const std::vector<ChannelSource>& sources, int width, int height) {
  ExrImage out;
  const std::size_t nc = sources.size();
  out.pixels.resize(std::size_t(width) * height * nc);
  for (const ChannelSource& source : sources) out.channelNames.push_back(source.name);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float* dst = &out.pixels[(std::size_t(y) * width + x) * nc];
      for (std::size_t c = 0; c < nc; ++c) {
        dst[c] = sources[c].convert(sources[c].image->at(x, y)[sources[c].channel]);
      }
    }
  }
  return out;
}

void writeExr(const std::string& path, const ExrImage& image, int width, int height,
              const SceneFrame& frame, const std::string& sceneName) {
  OIIO::ImageSpec spec(width, height, int(image.channelNames.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channelNames;
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = image.channelNames[c];
    if (name == "A" || name == "ViewLayer.Combined.A") spec.alpha_channel = c;
    if (name == "Z" || name == "ViewLayer.Depth.Z") spec.z_channel = c;
  }
  spec.attribute("compression", "zip");
  spec.attribute("taa:jitter", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::VEC2),
                 &frame.jitter.x);
  spec.attribute("taa:scene", sceneName);
  spec.attribute("taa:frame", frame.frame);
  spec.attribute("taa:shot", frame.shot);
  if (frame.hasCamera) {
    // A column-vector GLM matrix laid out column by column is, float for float, the row-vector
    // Imath M44f that OpenEXR stores row by row: no transpose on either side.
    spec.attribute("worldToCamera", OIIO::TypeMatrix44, &frame.camera.worldToCamera[0][0]);
    spec.attribute("worldToNDC", OIIO::TypeMatrix44, &frame.camera.worldToNDC[0][0]);
  }

  auto output = OIIO::ImageOutput::create(path);
  if (!output) {
    throw Error("cannot create EXR writer: " + OIIO::geterror(), {path, frame.frame, ""});
  }
  if (!output->open(path, spec) ||
      !output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !output->close()) {
    throw Error("cannot write EXR: " + output->geterror(), {path, frame.frame, ""});
  }
}

}  // namespace

std::string framePath(const std::string& dir, const std::string& stem, int frame) {
  char number[16];
  std::snprintf(number, sizeof number, "%04d", frame);
  return (std::filesystem::path(dir) / (stem + "." + number + ".exr")).string();
}

void writeFrame(const SceneFrame& frame, const std::string& sceneName, OutputLayout layout,
                const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create output folder: " + ec.message(), {dir, frame.frame, ""});

  const int w = frame.color.width, h = frame.color.height;
  auto write = [&](const std::string& stem, const std::vector<ChannelSource>& sources) {
    writeExr(framePath(dir, stem, frame.frame), interleave(sources, w, h), w, h, frame, sceneName);
  };
  const Image* color = &frame.color;
  const Image* truth = &frame.truth;
  write("truth", {{"R", truth, 0, identity},
                  {"G", truth, 1, identity},
                  {"B", truth, 2, identity},
                  {"A", truth, 3, identity}});
  // The yardstick's references, in internal conventions whatever the layout.
  if (!frame.flow.empty()) {
    write("flow", {{"X", &frame.flow, 0, identity}, {"Y", &frame.flow, 1, identity}});
  }
  if (!frame.disocclusion.empty()) write("disocclusion", {{"D", &frame.disocclusion, 0, identity}});

  if (layout == OutputLayout::Separate) {
    write("beauty", {{"R", color, 0, identity},
                     {"G", color, 1, identity},
                     {"B", color, 2, identity},
                     {"A", color, 3, identity}});
    write("depth", {{"Z", &frame.depth, 0, identity}});
    write("motion", {{"X", &frame.motion, 0, identity}, {"Y", &frame.motion, 1, identity}});
    return;
  }

  // Cycles: Vector (X, Y) = previous - current and (Z, W) = current - next, both y up.
  const Image* motion = &frame.motion;
  const Image zeroMotion(w, h, 2);  // a scene that cannot see the next frame leaves it empty
  const Image* next = frame.nextMotion.empty() ? &zeroMotion : &frame.nextMotion;
  write("render", {{"ViewLayer.Combined.R", color, 0, identity},
                   {"ViewLayer.Combined.G", color, 1, identity},
                   {"ViewLayer.Combined.B", color, 2, identity},
                   {"ViewLayer.Combined.A", color, 3, identity},
                   {"ViewLayer.Depth.Z", &frame.depth, 0, cyclesDepth},
                   {"ViewLayer.Vector.X", motion, 0, identity},
                   {"ViewLayer.Vector.Y", motion, 1, negate},
                   {"ViewLayer.Vector.Z", next, 0, negate},
                   {"ViewLayer.Vector.W", next, 1, identity}});
}

}  // namespace taa::scenes
