// The plugin's parameters, mirroring taatool's options that make sense in a host, and their
// mapping onto a C ABI node. Parameters do not animate: the whole history (or window) uses one
// setting.
#pragma once

#include <string>

#include "ofx/ofx_abi.h"
#include "taa/options.h"
#include "taa/taa.h"

namespace taa::ofx {

// The Mode choice's entries (--mode history|window).
constexpr int kModeHistory = 0;
constexpr int kModeWindow = 1;

struct PluginSettings {
  int mode = taa::ResolveOptions{}.mode == taa::ResolveMode::Window ? kModeWindow
                                                                     : kModeHistory;  // --mode
  // Window mode (--window, --window-sigma, ...); defaults are the library's.
  int windowRadius = taa::WindowOptions{}.radius;
  int windowNear = taa::WindowOptions{}.nearRadius;
  int windowMoving = taa::WindowOptions{}.movingRadius;
  double windowSigma = taa::WindowOptions{}.sigma;
  double windowFalloff = taa::WindowOptions{}.falloff;
  bool windowTaper = taa::WindowOptions{}.taper;
  bool windowStrata = taa::WindowOptions{}.strata;
  bool windowTwoClusters = taa::WindowOptions{}.twoClusters;
  double windowColourTolerance = taa::WindowOptions{}.colourTolerance;
  double windowStaticTolerance = taa::WindowOptions{}.staticTolerance;
  double windowReconstructionWeight = taa::WindowOptions{}.reconstructionWeight;
  double blend = taa::ResolveOptions{}.blend;  // --blend
  int rectify = 0;            // 0 variance clip, 1 clip, 2 clamp, 3 none (--rectify)
  bool dilateMotion = true;   // --no-dilate when false
  int jitter = 0;             // 0 Halton, 1 None (--jitter)
  int jitterOffset = 0;       // --jitter-offset
  int jitterPeriod = 0;       // --jitter-period
  int motionY = 0;            // 0 down, 1 up (--motion-y); a property of the vectors' values
  int motionTo = 0;           // 0 previous, 1 next (--motion-to)
  double motionScale = 1.0;   // --motion-scale, at render scale 1
  double depthNoHit = 1e9;    // --depth-nohit
  int historyFrames = 0;      // 0: history from the clip's first frame; N: the last N frames
  // The tonemap bracket (--ocio-config, --colorspace-in, --bracket, --colorspace-out). The
  // config is taa's shipped one unless the user picks $OCIO or a file: hosts set $OCIO to the
  // studio's config, which has none of taa's bracket names.
  int ocioConfigSource = 0;   // 0 shipped, 1 $OCIO, 2 the file ocioConfigFile
  std::string ocioConfigFile;
  std::string colorspaceIn = taa::ColorOptions{}.colorspaceIn;
  std::string bracket = taa::ColorOptions{}.bracket;
  std::string colorspaceOut = taa::ColorOptions{}.colorspaceOut;
  // The Pass clip (ofx/pass_clip.h): its kind, and whether it and Pass Factor are connected
  // (from the clips, not parameters: a node's ring holds one set of passes).
  int passKind = 0;
  bool passConnected = false;
  bool passFactorConnected = false;

  bool operator==(const PluginSettings& other) const;
  bool operator!=(const PluginSettings& other) const { return !(*this == other); }
};

// The host's render scale: image pixels per full-resolution pixel, in x and in y.
struct RenderScale {
  double x = 1.0, y = 1.0;
  bool operator==(const RenderScale& o) const { return x == o.x && y == o.y; }
};

// Defines every parameter on the descriptor's parameter set (describe in context).
void defineParameters(OfxParamSetHandle parameters);

// Whether the parameter `name` is one of the tonemap bracket's.
bool isColorParameter(const std::string& name);

// The ColorOptions (taatool's --ocio-config and friends) these settings ask for. Throws
// std::runtime_error when a config file is asked for but none is named.
taa::ColorOptions colorOptions(const PluginSettings& settings);

// The jitter of `frame` in image pixels: the library's Halton offsets (taatool's, for the
// same Jitter, Offset and Period) times the render scale, per axis.
void frameJitter(const PluginSettings& settings, int frame, RenderScale scale, float jitter[2]);

// Reads the instance's parameter values at `time` (the clips' connections are the caller's). Throws std::runtime_error on host errors.
PluginSettings readSettings(OfxImageEffectHandle effect, OfxTime time);

// Sets `settings` on `node`; pixel-unit motion is multiplied by the render scale in x (the
// caller scales y values by scale.y / scale.x where the two differ). Jitter is not the node's:
// every frame carries it (frameJitter). Throws with the node's message on failure.
void applySettings(taa_node* node, const PluginSettings& settings, RenderScale scale);

}  // namespace taa::ofx
