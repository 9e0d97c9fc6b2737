// A minimal OpenFX image-effect host for tests: loads a bundle binary with dlopen, offers the
// property, image-effect, parameter and message suites, and serves clip images from frames
// held in memory (converted to OFX's y-up layout with padded rows and offset bounds).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "host_properties.h"
#include "ofx/ofx_abi.h"
#include "util/image.h"

namespace taa::ofxtest {

struct HostParam {
  std::string type;
  PropertySet props;
  double doubleValue = 0.0;
  int intValue = 0;  // integer, boolean and choice parameters
};

// Frames of one clip: frame number -> image (rows top first, 1, 3 or 4 channels).
struct ClipFrames {
  std::map<int, Image> frames;
  bool half = false;  // serve as OfxBitDepthHalf (else float)
};

struct HostClip {
  std::string name;
  PropertySet props;
  const ClipFrames* source = nullptr;  // null: nothing connected (or the output clip)
  OfxRectI bounds{};                   // where every image of the clip lies
};

struct HostEffect {
  PropertySet props;
  PropertySet paramSetProps;
  std::map<std::string, HostParam> params;
  std::map<std::string, HostClip> clips;

  OfxImageEffectHandle handle() { return reinterpret_cast<OfxImageEffectHandle>(this); }
};

// One rendered output image, y-up with the bounds the host gave.
struct OutputImage {
  OfxRectI bounds{};
  bool half = false;
  std::vector<char> data;
  int rowBytes = 0;
  // Back to taa's layout: RGBA float, rows top first.
  Image toImage() const;
};

class TestHost {
 public:
  TestHost();
  ~TestHost();

  // dlopens the bundle binary and finds the plugin; returns "" or the reason it failed.
  std::string load(const std::string& binaryPath);
  OfxPlugin* plugin() const { return plugin_; }

  OfxStatus action(const char* name, HostEffect* effect, PropertySet* inArgs = nullptr,
                   PropertySet* outArgs = nullptr);

  // Builds an instance from a context descriptor: clips (connected to `inputs` by name) and
  // parameters with their defaults. The caller then runs kOfxActionCreateInstance.
  std::unique_ptr<HostEffect> makeInstance(HostEffect& contextDescriptor, const char* context,
                                           const std::map<std::string, const ClipFrames*>& inputs,
                                           OfxRectI bounds, double firstFrame, double lastFrame);

  // Renders the whole frame at `time` into a new output image (bounds of the instance).
  OfxStatus render(HostEffect& instance, double time, OutputImage& output,
                   double renderScale = 1.0);

  std::vector<std::string> messages() const;
  int liveImages() const;

  OfxHost* ofxHost() { return &host_; }

 private:
  void* library_ = nullptr;
  OfxPlugin* plugin_ = nullptr;
  OfxHost host_{};
  PropertySet hostProps_;
};

}  // namespace taa::ofxtest
