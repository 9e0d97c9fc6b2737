#include "resolve/pass_plan.h"

#include <Imath/half.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>

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
  std::map<std::string, int> index;
  for (int c = 0; c < int(names.size()); ++c) index[names[std::size_t(c)]] = c;
  for (const std::string& name : names) plan.kinds.push_back(io::channelKind(name, rules));
  plan.value.assign(names.size(), -1);
  plan.factor.assign(names.size(), -1);
  for (int c = 0; c < int(names.size()); ++c) {
    const ChannelKind kind = plan.kinds[std::size_t(c)];
    if (!summed(kind)) continue;
    if (kind == ChannelKind::Light) {
      const auto found = index.find(io::factorChannelOf(names[std::size_t(c)]));
      if (found != index.end() && plan.kinds[std::size_t(found->second)] == ChannelKind::Factor) {
        plan.factor[std::size_t(c)] = found->second;
      }
    }
    plan.value[std::size_t(c)] = int(plan.valueChannel.size());
    plan.valueChannel.push_back(c);
    plan.valueFactor.push_back(plan.factor[std::size_t(c)]);
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
      // A product of two halves rounded to half again loses 2^-11 of itself, far below what
      // the comp sees, and halves the ring's memory.
      const int factor = plan.valueFactor[v];
      half = half && formats[std::size_t(plan.valueChannel[v])] == OIIO::TypeHalf &&
             (factor < 0 || formats[std::size_t(factor)] == OIIO::TypeHalf);
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

// Pixel i's channels (plan.names' order) into `target`, from the sums, Cryptomatte ranks and
// frame t's kept channels (see finishPasses).
void finishPixel(std::size_t i, const std::vector<Image>& sums,
                 const std::vector<Image>& cryptomatte, const Image& kept, const PassPlan& plan,
                 float* target) {
  const std::size_t stride = plan.names.size();
  const std::size_t keptStride = std::size_t(plan.keptCount);
  constexpr float kHalfMax = 65504.0f;
  for (std::size_t c = 0; c < stride; ++c) {
    const int value = plan.value[c];
    if (value < 0) {  // kept, or Cryptomatte (written below)
      if (plan.kept[c] >= 0) target[c] = kept.pixels[i * keptStride + std::size_t(plan.kept[c])];
      continue;
    }
    float v = sums[std::size_t(value / 4)].pixels[4 * i + std::size_t(value % 4)];
    const int factor = plan.factor[c];
    if (factor >= 0) {
      // Light = (light x factor) / factor, as the renderer divides its sums; where no
      // sample had any factor (black albedo) the light is 0, as Cycles writes it.
      const int fv = plan.value[std::size_t(factor)];
      const float f = sums[std::size_t(fv / 4)].pixels[4 * i + std::size_t(fv % 4)];
      v = f != 0.0f ? v / f : 0.0f;
    }
    // A half channel holds what half can: a quotient of sums may pass 65504 (negative factors).
    target[c] = plan.formats[c] == OIIO::TypeHalf ? std::clamp(v, -kHalfMax, kHalfMax) : v;
  }
  // Cryptomatte: the resolve's three rank layers into the set's layers (more layers are 0).
  for (std::size_t s = 0; s < plan.cryptomatte.size(); ++s) {
    const PassPlan::CryptomatteSet& set = plan.cryptomatte[s];
    for (std::size_t layer = 0; layer < set.layers.size(); ++layer) {
      for (std::size_t k = 0; k < 4; ++k) {
        target[std::size_t(set.layers[layer][k])] =
            layer < 3 ? cryptomatte[3 * s + layer].pixels[4 * i + k] : 0.0f;
      }
    }
  }
  for (int x : plan.normalX) {
    float* n = &target[std::size_t(x)];
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0.0f) {
      for (int k = 0; k < 3; ++k) n[k] /= length;
    }
  }
}

}  // namespace

Image finishPasses(const std::vector<Image>& sums, const std::vector<Image>& cryptomatte,
                   const Image& kept, const PassPlan& plan) {
  const int width = sums.empty() ? kept.width : sums.front().width;
  const int height = sums.empty() ? kept.height : sums.front().height;
  Image out(width, height, int(plan.names.size()));
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  for (std::size_t i = 0; i < pixels; ++i) {
    finishPixel(i, sums, cryptomatte, kept, plan, &out.pixels[i * plan.names.size()]);
  }
  return out;
}

io::ExtraChannels::Packed finishPassesPacked(const std::vector<Image>& sums,
                                             const std::vector<Image>& cryptomatte,
                                             const Image& kept, const PassPlan& plan) {
  io::ExtraChannels::Packed out;
  out.width = sums.empty() ? kept.width : sums.front().width;
  out.height = sums.empty() ? kept.height : sums.front().height;
  // Half or float (planPasses' formats); not TypeDesc::size(), which lives in OIIO's library
  // and would make the OpenFX bundle (which links this file, not OIIO) need it.
  std::size_t pixelBytes = 0;
  for (const OIIO::TypeDesc& format : plan.formats) {
    pixelBytes += format == OIIO::TypeHalf ? sizeof(Imath::half) : sizeof(float);
  }
  const std::size_t pixels = std::size_t(out.width) * std::size_t(out.height);
  out.bytes.resize(pixels * pixelBytes);
  std::vector<float> values(plan.names.size());
  unsigned char* to = out.bytes.data();
  for (std::size_t i = 0; i < pixels; ++i) {
    finishPixel(i, sums, cryptomatte, kept, plan, values.data());
    for (std::size_t c = 0; c < values.size(); ++c) {
      // As the writer narrows a float channel to half (io/exr_writer's storeAs).
      if (plan.formats[c] == OIIO::TypeHalf) {
        const Imath::half h(values[c]);
        std::memcpy(to, &h, sizeof h);
        to += sizeof h;
      } else {
        std::memcpy(to, &values[c], sizeof(float));
        to += sizeof(float);
      }
    }
  }
  return out;
}

}  // namespace taa
