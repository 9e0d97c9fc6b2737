// A minimal OpenFX image-effect host for tests: loads a bundle binary with dlopen, offers the
// property, image-effect, parameter and message (version 2: persistent messages) suites, and
// serves clip images from frames held in memory, converted to OFX's y-up layout with padded
// rows and offset bounds. Like a host on the official SDK's host-support library it maps each
// input clip's components as the clip preferences action asks (default: the most chromatic
// connected input, so an Alpha clip becomes RGBA with its value in A), and can give clips
// their own bounds (overscan) and pixel aspect ratio.
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
  std::string stringValue;
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
  std::string components;              // images are served as this; "" = as stored
  double pixelAspectRatio = 1.0;
  int imagesServed = 0;                // clipGetImage calls answered with an image
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

  // Runs the clip preferences action with the host's defaults filled in first (each input:
  // the most chromatic components of the connected inputs), then maps every input clip to
  // what the plugin left in the arguments, or, with `honour` false, to the defaults whatever
  // the plugin asks (a host that cannot remap). `outArgs` receives the action's arguments.
  OfxStatus clipPreferences(HostEffect& instance, PropertySet& outArgs, bool honour = true);

  // Tells the instance that parameter `name` changed (kOfxActionInstanceChanged).
  OfxStatus parameterChanged(HostEffect& instance, const std::string& name);

  // Renders the whole frame at `time` into a new output image (bounds of the instance).
  OfxStatus render(HostEffect& instance, double time, OutputImage& output,
                   double renderScaleX = 1.0, double renderScaleY = -1.0 /* = x */);

  std::vector<std::string> messages() const;
  // The persistent message on `effect` ("type: text"), "" when none.
  std::string persistentMessage(const HostEffect& effect) const;
  int liveImages() const;
  // The most images the plugin held at once (since the last reset), then resets it.
  int peakLiveImages(bool reset = true) const;

  OfxHost* ofxHost() { return &host_; }

 private:
  void* library_ = nullptr;
  OfxPlugin* plugin_ = nullptr;
  OfxHost host_{};
  PropertySet hostProps_;
};

}  // namespace taa::ofxtest
