// The Pass clip (issue 21): another pass of the render (a light, colour, data or Cryptomatte
// pass, chosen in the host, e.g. with a Shuffle) resolved with the Source's weights, as taatool
// resolves every pass of a multi-channel file beside the beauty. When it is connected the
// output is the resolved pass; the Source, Depth and Motion clips still decide the weights.
// A light pass may come with its colour (albedo) pass in the Pass Factor clip: light x colour
// is summed and divided by the summed colour at the end, as taatool does for Cycles' DiffDir
// with DiffCol, so that (resolved light) x (the colour resolved by a node with Pass Kind
// Factor) is the resolved product and the comp's sums still add up.
// The node knows a pass by its channel names, whose kinds its "aov" rules set; the names here
// are the plugin's own (the host's layer names never reach the node).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ofx/aux_buffer.h"
#include "ofx/clip_image.h"
#include "taa/taa.h"

namespace taa::ofx {

// The Pass Kind choice's entries, in the host's order.
enum PassKind {
  kPassLight = 0,    // additive radiance: summed (with its factor when Pass Factor is connected)
  kPassFactor = 1,   // a colour (albedo) pass: summed
  kPassAverage = 2,  // data averaged: UV, position
  kPassNormal = 3,   // averaged, then XYZ renormalised
  kPassNearest = 4,  // depth, IDs, vectors: frame t's own value, never a blend
  kPassCryptomatte = 5,  // one rank layer (two ID / coverage pairs): IDs re-weighed, float only
};

// The node's channel names for a pass of `components` channels (1, 3 or 4) and for its factor.
struct PassChannels {
  std::vector<std::string> pass, factor;  // factor: empty unless a light with a factor
};
PassChannels passChannels(int kind, int components, bool withFactor);

// The node's "aov" rules that give those channels `kind`.
std::string passRules(int kind);

// The node's passes for one frame: each channel of `image` (the pass, over `bounds`, the
// Source's) and of `factor` when given. Throws std::runtime_error naming the clip and frame
// when the images cannot be this kind's (Cryptomatte: four float channels).
class PassBuffers {
 public:
  PassBuffers(int kind, const ClipImage& image, const ClipImage* factor, const OfxRectI& bounds);
  const std::vector<taa_pass>& passes() const { return passes_; }

 private:
  PassChannels names_;
  std::optional<AuxBuffer> pass_, factor_;  // views of the host's images, or copies
  std::vector<taa_pass> passes_;
};

}  // namespace taa::ofx
