#include "scenegen/convention_writers.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <vector>

#include "scenegen/exr_output.h"
#include "taa/error.h"

namespace taa::scenes {
namespace {

// One output channel: its name and its value at pixel (x, y).
struct Channel {
  std::string name;
  std::function<float(int x, int y)> value;
};

Channel channelOf(const std::string& name, const Image& image, int c, float factor = 1.0f) {
  return {name, [&image, c, factor](int x, int y) { return factor * image.at(x, y)[c]; }};
}

void writeChannels(const std::string& path, const std::vector<Channel>& channels,
                   const SceneFrame& frame, const std::string& sceneName) {
  const int width = frame.color.width, height = frame.color.height;
  OIIO::ImageSpec spec(width, height, int(channels.size()), OIIO::TypeFloat);
  spec.channelnames.clear();
  for (const Channel& channel : channels) spec.channelnames.push_back(channel.name);
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  spec.attribute("compression", "zip");
  spec.attribute("taa:jitter", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::VEC2),
                 &frame.jitter.x);
  spec.attribute("taa:scene", sceneName);
  spec.attribute("taa:frame", frame.frame);
  if (frame.hasCamera) {
    // Column-vector GLM matrices stored column by column are the row-vector M44f EXR expects.
    spec.attribute("worldToCamera", OIIO::TypeMatrix44, &frame.camera.worldToCamera[0][0]);
    spec.attribute("worldToNDC", OIIO::TypeMatrix44, &frame.camera.worldToNDC[0][0]);
  }
  std::vector<float> pixels(std::size_t(width) * height * channels.size());
  std::size_t at = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (const Channel& channel : channels) pixels[at++] = channel.value(x, y);
    }
  }
  auto output = OIIO::ImageOutput::create("openexr");
  if (!output || !output->open(path, spec) ||
      !output->write_image(OIIO::TypeFloat, pixels.data()) || !output->close()) {
    const std::string reason = output ? output->geterror() : OIIO::geterror();
    throw Error("cannot write EXR: " + reason, {path, frame.frame, ""});
  }
}

std::vector<Channel> rgba(const Image& image) {
  return {channelOf("R", image, 0), channelOf("G", image, 1), channelOf("B", image, 2),
          channelOf("A", image, 3)};
}

// Planar depth -> depth-buffer value of a perspective projection with planes kNdcNear/kNdcFar.
float ndcDepth(float planar) {
  if (!std::isfinite(planar)) return 1.0f;
  const double n = kNdcNear, f = kNdcFar;
  return float(f / (f - n) - f * n / ((f - n) * planar));
}

void writeNuke(const SceneFrame& frame, const std::string& sceneName, const std::string& dir) {
  const Image& depth = frame.depth;
  const Image zero(frame.color.width, frame.color.height, 2);
  const Image& next = frame.nextMotion.empty() ? zero : frame.nextMotion;
  std::vector<Channel> channels = rgba(frame.color);
  channels.push_back({"depth.Z", [&depth](int x, int y) {
                        const float z = *depth.at(x, y);
                        return std::isfinite(z) ? 1.0f / z : 0.0f;
                      }});
  // Internal motion is y down; Nuke's image space is y up.
  channels.push_back(channelOf("backward.u", frame.motion, 0));
  channels.push_back(channelOf("backward.v", frame.motion, 1, -1.0f));
  channels.push_back(channelOf("forward.u", next, 0));
  channels.push_back(channelOf("forward.v", next, 1, -1.0f));
  writeChannels(framePath(dir, "nuke", frame.frame), channels, frame, sceneName);
}

void writeNdcSeparate(const SceneFrame& frame, const std::string& sceneName,
                      const std::string& dir) {
  const Image& depth = frame.depth;
  const float toNdcX = 2.0f / float(frame.color.width);
  const float toNdcY = -2.0f / float(frame.color.height);  // y up
  writeChannels(framePath(dir, "color", frame.frame), rgba(frame.color), frame, sceneName);
  writeChannels(framePath(dir, "depth_ndc", frame.frame),
                {{"Z", [&depth](int x, int y) { return ndcDepth(*depth.at(x, y)); }}}, frame,
                sceneName);
  writeChannels(framePath(dir, "motion_ndc", frame.frame),
                {channelOf("X", frame.motion, 0, toNdcX), channelOf("Y", frame.motion, 1, toNdcY)},
                frame, sceneName);
}

}  // namespace

bool parseConventionVariant(const std::string& name, ConventionVariant* variant) {
  if (name == "nuke") {
    *variant = ConventionVariant::Nuke;
  } else if (name == "ndc") {
    *variant = ConventionVariant::NdcSeparate;
  } else {
    return false;
  }
  return true;
}

void writeConventionFrame(const SceneFrame& frame, const std::string& sceneName,
                          ConventionVariant variant, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create output folder: " + ec.message(), {dir, frame.frame, ""});
  writeChannels(framePath(dir, "truth", frame.frame), rgba(frame.truth), frame, sceneName);
  if (variant == ConventionVariant::Nuke) {
    writeNuke(frame, sceneName, dir);
  } else {
    writeNdcSeparate(frame, sceneName, dir);
  }
}

}  // namespace taa::scenes
