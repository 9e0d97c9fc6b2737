// The plugin's parameters, mirroring taatool's options that make sense in a host, and their
// mapping onto a C ABI node. Parameters do not animate: the whole history uses one setting.
#pragma once

#include "ofx/ofx_abi.h"
#include "taa/options.h"
#include "taa/taa.h"

namespace taa::ofx {

struct PluginSettings {
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

  bool operator==(const PluginSettings& other) const;
  bool operator!=(const PluginSettings& other) const { return !(*this == other); }
};

// Defines every parameter on the descriptor's parameter set (describe in context).
void defineParameters(OfxParamSetHandle parameters);

// Reads the instance's parameter values at `time`. Throws std::runtime_error on host errors.
PluginSettings readSettings(OfxImageEffectHandle effect, OfxTime time);

// Sets `settings` on `node`; pixel-unit motion is multiplied by `renderScale` (the host's
// render scale in x; taa assumes square scaling). Throws with the node's message on failure.
void applySettings(taa_node* node, const PluginSettings& settings, double renderScale);

}  // namespace taa::ofx
