// How the channels beside the beauty are resolved (issue 21). The window's gather sums four
// values a texel with the beauty's weights (glsl/window_gather.frag, PASS_GROUPS); this plan
// says which values those are and how the channels come back from the sums:
// - light with a factor (Cycles' DiffDir with DiffCol): the product is summed, as the renderer
//   accumulates light, and divided by the summed factor at the end, so Dir x Col of the result
//   is the resolved light and Combined = sum of (Dir + Ind) x Col + Emit + Env still holds;
// - light, factor, average: summed; normal: summed, then the vector renormalised;
// - Cryptomatte: each set's first rank layer (two ID / coverage pairs a sample) goes to the GPU,
//   which weighs each sample's IDs as the beauty weighs the sample and writes the six heaviest
//   back as three rank layers (glsl/window_cryptomatte.glsl);
// - nearest, copy: frame t's own value, never a blend.
#pragma once

#include <OpenImageIO/typedesc.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "io/channel_kinds.h"
#include "io/exr_writer.h"
#include "util/image.h"

namespace taa {

class PassBandStream;

struct PassPlan {
  std::vector<std::string> names;            // the channels, as read
  std::vector<OIIO::TypeDesc> formats;       // and their types in the file
  std::vector<io::ChannelKind> kinds;        // per channel
  // Per channel: the index of the value summed for it (group * 4 + slot), or -1 (t's own).
  std::vector<int> value;
  // Per channel: the channel its value is multiplied by before the sum (its factor), or -1.
  std::vector<int> factor;
  // What each summed value is: the channel, and the factor channel or -1.
  std::vector<int> valueChannel, valueFactor;
  std::vector<int> normalX;  // first channel of each normal triple (renormalised)
  // Per channel: its index among the channels taken from frame t as they are (not summed), or
  // -1; and how many those are.
  std::vector<int> kept;
  int keptCount = 0;
  // Per group: whether its ring may hold halves (every value from half channels).
  std::vector<bool> halfGroups;
  // Cryptomatte sets ("ViewLayer.CryptoObject"): each rank layer's r, g, b, a channels, from
  // layer 00 on. Their channels are neither summed nor kept.
  struct CryptomatteSet {
    std::string name;
    std::vector<std::array<int, 4>> layers;
  };
  std::vector<CryptomatteSet> cryptomatte;

  // Whether every channel is half or float: the finished passes can then be packed in their
  // file types band by band (finishPassesPacked); a uint channel goes the float way.
  bool halfOrFloat = true;

  int groups() const { return int((valueChannel.size() + 3) / 4); }
  bool empty() const { return names.empty(); }
};

// The plan for a frame's pass channels (names and types as read, in file order) under `rules`.
PassPlan planPasses(const std::vector<std::string>& names,
                    const std::vector<OIIO::TypeDesc>& formats,
                    const std::vector<io::ChannelKindRule>& rules);

// A frame's passes as the window resolve keeps them until its turn:
// - groups: each group's values, RGBA interleaved (unused slots 0), half where the plan's group
//   is (PassPlan::halfGroups: the ring's own type, uploaded as it is);
// - cryptomatte: each set's first rank layer, RGBA;
// - kept: the channels taken from frame t as they are (PassPlan::kept), for its output.
// About half the size of the frame's pass channels as float.
struct PackedPasses {
  std::vector<TypedImage> groups;
  std::vector<Image> cryptomatte;
  Image kept;
};

// Empty packed passes of a `width` x `height` frame under `plan`, to be filled by packPassRows.
PackedPasses newPackedPasses(const PassPlan& plan, int width, int height);

// Pixels [firstPixel, firstPixel + count) of the frame (rows top first) from `values`, their
// pass channels as read (plan.names' order, interleaved, float): the reader hands each band of
// rows over as it is decoded (io::PassBandReceiver), so the frame's channels are never held
// whole.
void packPassRows(const float* values, std::size_t firstPixel, std::size_t count,
                  const PassPlan& plan, PackedPasses& packed);

// A whole frame's pass channels (as read, plan.names' order) packed.
PackedPasses packPasses(const Image& passes, const PassPlan& plan);

// What a resolved frame's pass channels are made from: the gather's sums (one RGBA image a
// group, half where the plan's group is: PassPlan::halfGroups) and its Cryptomatte ranks
// (three RGBA images a set: id, coverage, id, coverage).
struct PassSums {
  std::vector<TypedImage> groups;
  std::vector<Image> cryptomatte;
};

// The resolved channels from the sums and frame t's kept channels (PackedPasses::kept): an
// image with `plan.names`' channels in their order.
Image finishPasses(const PassSums& sums, const Image& kept, const PassPlan& plan);
// The same channels packed in their file types (plan.formats, half or float) for the writer
// (io::ExtraChannels::Packed::rows): finished band by band as the writer reaches them, so a
// frame's finished passes (190 bytes a pixel for a render's every pass) are never held whole;
// what they are made from is held until then.
io::ExtraChannels::Packed finishPassesPacked(PassSums sums, Image kept, PassPlan plan);
// The same, finished from `frame`'s sums as the GL thread hands them over band by band
// (resolve/pass_band_stream): the writer waits for each band it reaches.
io::ExtraChannels::Packed finishPassesStreamed(std::shared_ptr<PassBandStream> stream, int frame,
                                               Image kept, PassPlan plan, int width,
                                               int height);

}  // namespace taa
