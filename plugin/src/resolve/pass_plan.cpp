#include "resolve/pass_plan.h"

#include <Imath/half.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <tuple>
#include <utility>

#include "resolve/pass_band_stream.h"
#include "taa/error.h"

namespace taa {
namespace {

using io::ChannelKind;

bool summed(ChannelKind kind) {
  return kind == ChannelKind::Light || kind == ChannelKind::Factor ||
         kind == ChannelKind::Average || kind == ChannelKind::Normal;
}

// The component after the last dot: "X" of "ViewLayer.Normal.X".
std::string componentOf(const std::string& name) { return name.substr(name.rfind('.') + 1); }
std::string stemOf(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? "" : name.substr(0, dot);
}

// Cryptomatte sets among the channels: "<set><NN>.<r|g|b|a>" of kind Cryptomatte, every rank
// layer from 00 on complete (R, G, B, A spellings too). Others stay t's own.
void findCryptomatteSets(PassPlan& plan, const std::map<std::string, int>& index) {
  std::map<std::string, bool> seen;
  for (std::size_t c = 0; c < plan.names.size(); ++c) {
    if (plan.kinds[c] != ChannelKind::Cryptomatte) continue;
    const std::string stem = stemOf(plan.names[c]);  // "ViewLayer.CryptoObject00"
    if (stem.size() < 3 || !std::isdigit((unsigned char)stem[stem.size() - 1]) ||
        !std::isdigit((unsigned char)stem[stem.size() - 2])) {
      continue;
    }
    const std::string set = stem.substr(0, stem.size() - 2);
    if (seen.count(set)) continue;
    seen[set] = true;
    PassPlan::CryptomatteSet found{set, {}};
    for (int layer = 0; layer < 100; ++layer) {
      const std::string prefix = set + (layer < 10 ? "0" : "") + std::to_string(layer) + ".";
      std::array<int, 4> channels{};
      bool complete = true;
      for (int k = 0; k < 4; ++k) {
        auto it = index.find(prefix + "rgba"[k]);
        if (it == index.end()) it = index.find(prefix + "RGBA"[k]);
        complete = complete && it != index.end() &&
                   plan.kinds[std::size_t(it->second)] == ChannelKind::Cryptomatte;
        if (complete) channels[std::size_t(k)] = it->second;
      }
      if (!complete) break;
      found.layers.push_back(channels);
    }
    if (!found.layers.empty()) plan.cryptomatte.push_back(found);
  }
}

}  // namespace

PassPlan planPasses(const std::vector<std::string>& names,
                    const std::vector<OIIO::TypeDesc>& formats,
                    const std::vector<io::ChannelKindRule>& rules) {
  PassPlan plan;
  plan.names = names;
  plan.formats = formats;
  for (const OIIO::TypeDesc& format : formats) {
    plan.halfOrFloat = plan.halfOrFloat && (format == OIIO::TypeHalf || format == OIIO::TypeFloat);
  }
  std::map<std::string, int> index;
  for (int c = 0; c < int(names.size()); ++c) index[names[std::size_t(c)]] = c;
  for (const std::string& name : names) plan.kinds.push_back(io::channelKind(name, rules));
  plan.value.assign(names.size(), -1);
  plan.factor.assign(names.size(), -1);
  for (int c = 0; c < int(names.size()); ++c) {
    const ChannelKind kind = plan.kinds[std::size_t(c)];
    if (kind != ChannelKind::Light) continue;
    const auto found = index.find(io::factorChannelOf(names[std::size_t(c)]));
    if (found != index.end() && plan.kinds[std::size_t(found->second)] == ChannelKind::Factor) {
      plan.factor[std::size_t(c)] = found->second;
    }
  }
  // A product of two halves rounded to half again loses 2^-11 of itself, far below what the
  // comp sees, and halves the ring's memory; so a value may be held as half where its channel
  // and its factor are. The all-half values go first, so that they fill whole groups: in file
  // order a render's half and float passes interleave and one float value makes a group of
  // four float (a 1080p Cycles frame with every pass: 144 -> 120 bytes a pixel in the ring).
  const auto halfValue = [&](int c) {
    const int factor = plan.factor[std::size_t(c)];
    return formats[std::size_t(c)] == OIIO::TypeHalf &&
           (factor < 0 || formats[std::size_t(factor)] == OIIO::TypeHalf);
  };
  for (const bool half : {true, false}) {
    for (int c = 0; c < int(names.size()); ++c) {
      if (!summed(plan.kinds[std::size_t(c)]) || halfValue(c) != half) continue;
      plan.value[std::size_t(c)] = int(plan.valueChannel.size());
      plan.valueChannel.push_back(c);
      plan.valueFactor.push_back(plan.factor[std::size_t(c)]);
    }
  }
  findCryptomatteSets(plan, index);
  std::vector<bool> inSet(names.size(), false);
  for (const PassPlan::CryptomatteSet& set : plan.cryptomatte) {
    for (const auto& layer : set.layers) {
      for (int c : layer) inSet[std::size_t(c)] = true;
    }
  }
  plan.kept.assign(names.size(), -1);
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (plan.value[c] < 0 && !inSet[c]) plan.kept[c] = plan.keptCount++;
  }
  for (int g = 0; g < plan.groups(); ++g) {
    bool half = true;
    for (std::size_t v = std::size_t(4 * g); v < std::min(plan.valueChannel.size(), std::size_t(4 * g + 4)); ++v) {
      half = half && halfValue(plan.valueChannel[v]);
    }
    plan.halfGroups.push_back(half);
  }
  // Normals: X, Y, Z of one stem, renormalised together.
  for (int c = 0; c < int(names.size()); ++c) {
    if (plan.kinds[std::size_t(c)] != ChannelKind::Normal) continue;
    const std::string& name = names[std::size_t(c)];
    const std::string component = componentOf(name), stem = stemOf(name);
    if (component != "X" && component != "R" && component != "x") continue;
    const std::string y = component == "X" ? "Y" : component == "R" ? "G" : "y";
    const std::string z = component == "X" ? "Z" : component == "R" ? "B" : "z";
    const std::string prefix = stem.empty() ? "" : stem + ".";
    const auto fy = index.find(prefix + y), fz = index.find(prefix + z);
    if (fy == index.end() || fz == index.end() || fy->second != c + 1 || fz->second != c + 2 ||
        plan.kinds[std::size_t(c + 1)] != ChannelKind::Normal ||
        plan.kinds[std::size_t(c + 2)] != ChannelKind::Normal) {
      continue;
    }
    plan.normalX.push_back(c);
  }
  return plan;
}

PackedPasses newPackedPasses(const PassPlan& plan, int width, int height) {
  PackedPasses packed;
  for (int g = 0; g < plan.groups(); ++g) {
    packed.groups.emplace_back(width, height, 4,
                               plan.halfGroups[std::size_t(g)] ? SampleType::Half
                                                               : SampleType::Float);
  }
  for (std::size_t s = 0; s < plan.cryptomatte.size(); ++s) {
    packed.cryptomatte.emplace_back(width, height, 4);
  }
  packed.kept = Image(width, height, plan.keptCount);
  return packed;
}

void packPassRows(const float* values, std::size_t firstPixel, std::size_t count,
                  const PassPlan& plan, PackedPasses& packed) {
  const std::size_t stride = plan.names.size();
  // Per summed value: where it goes (slot k of its group's first pixel, half or float).
  const std::size_t summed = plan.valueChannel.size();
  std::vector<Imath::half*> halfTarget(summed, nullptr);
  std::vector<float*> floatTarget(summed, nullptr);
  for (std::size_t v = 0; v < summed; ++v) {
    TypedImage& group = packed.groups[v / 4];
    if (group.type() == SampleType::Half) {
      halfTarget[v] = group.halves()->pixels.data() + v % 4;
    } else {
      floatTarget[v] = group.floats()->pixels.data() + v % 4;
    }
  }
  std::vector<std::size_t> keptFrom;  // kept channel k is channel keptFrom[k]
  for (std::size_t c = 0; c < plan.kept.size(); ++c) {
    if (plan.kept[c] >= 0) keptFrom.push_back(c);
  }
  const std::size_t keptStride = keptFrom.size();
  // Pixel by pixel, each pixel's channels once: a pixel's channels are neighbours in memory,
  // a channel's are not. Unused group slots stay 0, as the images were made.
  for (std::size_t n = 0; n < count; ++n) {
    const std::size_t i = firstPixel + n;
    const float* row = values + n * stride;
    for (std::size_t v = 0; v < summed; ++v) {
      const int factor = plan.valueFactor[v];
      const float value = row[plan.valueChannel[v]];
      const float product = factor < 0 ? value : value * row[factor];
      if (halfTarget[v]) {
        halfTarget[v][4 * i] = Imath::half(product);
      } else {
        floatTarget[v][4 * i] = product;
      }
    }
    for (std::size_t s = 0; s < plan.cryptomatte.size(); ++s) {
      const std::array<int, 4>& first = plan.cryptomatte[s].layers.front();
      float* target = &packed.cryptomatte[s].pixels[4 * i];
      for (std::size_t k = 0; k < 4; ++k) target[k] = row[first[k]];
    }
    float* kept = keptStride ? &packed.kept.pixels[i * keptStride] : nullptr;
    for (std::size_t k = 0; k < keptStride; ++k) kept[k] = row[keptFrom[k]];
  }
}

PackedPasses packPasses(const Image& passes, const PassPlan& plan) {
  if (passes.channels != int(plan.names.size())) {
    throw Error("the frame has " + std::to_string(passes.channels) +
                " pass channels where the first frame had " + std::to_string(plan.names.size()));
  }
  PackedPasses packed = newPackedPasses(plan, passes.width, passes.height);
  packPassRows(passes.pixels.data(), 0, std::size_t(passes.width) * std::size_t(passes.height),
               plan, packed);
  return packed;
}

namespace {

// Finishes pixels of one frame: where each channel's values are, decided once per frame so
// that a pixel's work is loads, a division and stores.
class PassFinisher {
 public:
  // `sums` may hold a band of the frame: its first pixel is the frame's pixel `sumsFirst`.
  PassFinisher(const PassSums& sums, const Image& kept, const PassPlan& plan,
               std::size_t sumsFirst = 0)
      : sums_(sums), kept_(kept), plan_(plan), sumsFirst_(sumsFirst) {
    for (const TypedImage& group : sums.groups) {
      halfSums_.push_back(group.halves() ? group.halves()->pixels.data() : nullptr);
      floatSums_.push_back(group.floats() ? group.floats()->pixels.data() : nullptr);
    }
    for (const OIIO::TypeDesc& format : plan.formats) {
      halfChannel_.push_back(format == OIIO::TypeHalf ? 1 : 0);
    }
  }

  // Pixel i's channels (plan.names' order) into `target`.
  void pixel(std::size_t i, float* target) const {
    const std::size_t stride = plan_.names.size();
    const std::size_t keptStride = std::size_t(plan_.keptCount);
    constexpr float kHalfMax = 65504.0f;
    for (std::size_t c = 0; c < stride; ++c) {
      const int value = plan_.value[c];
      if (value < 0) {  // kept, or Cryptomatte (written below)
        if (plan_.kept[c] >= 0) {
          target[c] = kept_.pixels[i * keptStride + std::size_t(plan_.kept[c])];
        }
        continue;
      }
      float v = sum(value, i);
      const int factor = plan_.factor[c];
      if (factor >= 0) {
        // Light = (light x factor) / factor, as the renderer divides its sums; where no
        // sample had any factor (black albedo) the light is 0, as Cycles writes it.
        const float f = sum(plan_.value[std::size_t(factor)], i);
        v = f != 0.0f ? v / f : 0.0f;
      }
      // A half channel holds what half can: a quotient of sums may pass 65504 (negative factors).
      target[c] = halfChannel_[c] ? std::clamp(v, -kHalfMax, kHalfMax) : v;
    }
    // Cryptomatte: the resolve's three rank layers into the set's layers (more layers are 0).
    for (std::size_t s = 0; s < plan_.cryptomatte.size(); ++s) {
      const PassPlan::CryptomatteSet& set = plan_.cryptomatte[s];
      for (std::size_t layer = 0; layer < set.layers.size(); ++layer) {
        for (std::size_t k = 0; k < 4; ++k) {
          target[std::size_t(set.layers[layer][k])] =
              layer < 3 ? sums_.cryptomatte[3 * s + layer].pixels[4 * (i - sumsFirst_) + k]
                        : 0.0f;
        }
      }
    }
    for (int x : plan_.normalX) {
      float* n = &target[std::size_t(x)];
      const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (length > 0.0f) {
        for (int k = 0; k < 3; ++k) n[k] /= length;
      }
    }
  }

  // Pixels [first, first + count) packed in their file types (half or float), pixel first + n
  // at pixels + n * stride.
  void packed(std::size_t first, std::size_t count, unsigned char* pixels,
              std::size_t stride) const {
    std::vector<float> values(plan_.names.size());
    for (std::size_t n = 0; n < count; ++n) {
      pixel(first + n, values.data());
      unsigned char* to = pixels + n * stride;
      for (std::size_t c = 0; c < values.size(); ++c) {
        // As the writer narrows a float channel to half (io/exr_writer's storeAs).
        if (halfChannel_[c]) {
          const Imath::half h(values[c]);
          std::memcpy(to, &h, sizeof h);
          to += sizeof h;
        } else {
          std::memcpy(to, &values[c], sizeof(float));
          to += sizeof(float);
        }
      }
    }
  }

 private:
  float sum(int value, std::size_t i) const {
    const std::size_t group = std::size_t(value / 4);
    const std::size_t at = 4 * (i - sumsFirst_) + std::size_t(value % 4);
    return halfSums_[group] ? float(halfSums_[group][at]) : floatSums_[group][at];
  }

  const PassSums& sums_;
  const Image& kept_;
  const PassPlan& plan_;
  const std::size_t sumsFirst_;
  std::vector<const Imath::half*> halfSums_;
  std::vector<const float*> floatSums_;
  std::vector<char> halfChannel_;  // per channel: 1 where the file holds it as half
};

std::pair<int, int> sizeOf(const PassSums& sums, const Image& kept) {
  if (!sums.groups.empty()) return {sums.groups.front().width(), sums.groups.front().height()};
  if (!sums.cryptomatte.empty()) return {sums.cryptomatte.front().width, sums.cryptomatte.front().height};
  return {kept.width, kept.height};
}

}  // namespace

Image finishPasses(const PassSums& sums, const Image& kept, const PassPlan& plan) {
  const auto [width, height] = sizeOf(sums, kept);
  Image out(width, height, int(plan.names.size()));
  const PassFinisher finisher(sums, kept, plan);
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  for (std::size_t i = 0; i < pixels; ++i) {
    finisher.pixel(i, &out.pixels[i * plan.names.size()]);
  }
  return out;
}

io::ExtraChannels::Packed finishPassesPacked(PassSums sums, Image kept, PassPlan plan) {
  io::ExtraChannels::Packed out;
  std::tie(out.width, out.height) = sizeOf(sums, kept);
  // What the writer's band calls finish from, and the finisher set up once for all of them;
  // kept alive by the calls (a std::function is copied).
  struct Inputs {
    Inputs(PassSums s, Image k, PassPlan p)
        : sums(std::move(s)), kept(std::move(k)), plan(std::move(p)), finisher(sums, kept, plan) {}
    PassSums sums;
    Image kept;
    PassPlan plan;
    PassFinisher finisher;  // after what it refers to
  };
  auto inputs = std::make_shared<const Inputs>(std::move(sums), std::move(kept), std::move(plan));
  out.rows = [inputs](std::size_t first, std::size_t count, unsigned char* to,
                      std::size_t stride) { inputs->finisher.packed(first, count, to, stride); };
  return out;
}

io::ExtraChannels::Packed finishPassesStreamed(std::shared_ptr<PassBandStream> stream, int frame,
                                               Image kept, PassPlan plan, int width,
                                               int height) {
  io::ExtraChannels::Packed out;
  out.width = width;
  out.height = height;
  struct Inputs {
    std::shared_ptr<PassBandStream> stream;
    int frame;
    Image kept;
    PassPlan plan;
  };
  auto inputs = std::make_shared<const Inputs>(
      Inputs{std::move(stream), frame, std::move(kept), std::move(plan)});
  const std::size_t rowPixels = std::size_t(width);
  out.rows = [inputs, rowPixels](std::size_t first, std::size_t count, unsigned char* to,
                                 std::size_t stride) {
    // Band by band of the GL's (a call may cross from one into the next).
    while (count > 0) {
      const PassBandStream::Band& band = inputs->stream->band(inputs->frame, int(first / rowPixels));
      const std::size_t bandFirst = std::size_t(band.firstRow) * rowPixels;
      const std::size_t n = std::min(count, bandFirst + std::size_t(band.rows) * rowPixels - first);
      PassFinisher(band.sums, inputs->kept, inputs->plan, bandFirst).packed(first, n, to, stride);
      first += n;
      count -= n;
      to += n * stride;
    }
  };
  return out;
}

}  // namespace taa
