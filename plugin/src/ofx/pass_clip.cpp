#include "ofx/pass_clip.h"

#include <stdexcept>

namespace taa::ofx {
namespace {

// Component suffixes: RGBA, or XYZ for a normal (the node renormalises an X, Y, Z triple).
std::vector<std::string> named(const std::string& stem, int components, bool normal) {
  static const char* const kColour[] = {"R", "G", "B", "A"};
  static const char* const kVector[] = {"X", "Y", "Z"};
  if (components == 1) return {stem + ".A"};  // an Alpha clip
  std::vector<std::string> names;
  for (int c = 0; c < components; ++c) {
    // A normal's fourth component is not part of the vector: averaged apart from it.
    names.push_back(normal && c < 3 ? stem + "." + kVector[c]
                    : normal        ? "Pass.NormalAlpha.A"
                                    : stem + "." + kColour[c]);
  }
  return names;
}

}  // namespace

PassChannels passChannels(int kind, int components, bool withFactor) {
  PassChannels channels;
  switch (kind) {
    case kPassLight:
      // "DiffDir" and "DiffCol": the names by which the node pairs a light with its factor.
      channels.pass = named("Pass.DiffDir", components, false);
      if (withFactor) channels.factor = named("Pass.DiffCol", components, false);
      break;
    case kPassFactor: channels.pass = named("Pass.Colour", components, false); break;
    case kPassAverage:
    case kPassNearest: channels.pass = named("Pass.Data", components, false); break;
    case kPassNormal: channels.pass = named("Pass.Normal", components, components >= 3); break;
    case kPassCryptomatte:
      channels.pass = {"Pass.Crypto00.r", "Pass.Crypto00.g", "Pass.Crypto00.b", "Pass.Crypto00.a"};
      channels.pass.resize(std::size_t(components));
      break;
    default: throw std::runtime_error("Pass Kind choice out of range");
  }
  return channels;
}

std::string passRules(int kind) {
  switch (kind) {
    case kPassLight: return "Pass.DiffDir.*=light;Pass.DiffCol.*=factor";
    case kPassFactor: return "Pass.*=factor";
    case kPassAverage: return "Pass.*=average";
    case kPassNormal: return "Pass.Normal.*=normal;Pass.*=average";
    case kPassNearest: return "Pass.*=nearest";
    case kPassCryptomatte: return "Pass.*=cryptomatte";
    default: throw std::runtime_error("Pass Kind choice out of range");
  }
}

PassBuffers::PassBuffers(int kind, const ClipImage& image, const ClipImage* factor,
                         const OfxRectI& bounds) {
  if (kind == kPassCryptomatte && (image.components() != 4 || image.isHalf())) {
    throw std::runtime_error("the " + image.where() +
                             " is Cryptomatte: it needs one rank layer as four float channels "
                             "(ID, coverage, ID, coverage; IDs are float hashes), not " +
                             std::to_string(image.components()) + " " +
                             (image.isHalf() ? "half" : "float") + " channel(s)");
  }
  const bool withFactor = kind == kPassLight && factor;
  if (withFactor && factor->components() != image.components()) {
    throw std::runtime_error("the " + factor->where() + " has " +
                             std::to_string(factor->components()) + " channel(s), the " +
                             image.where() + " " + std::to_string(image.components()) +
                             ": a light's factor needs one value per light channel");
  }
  names_ = passChannels(kind, image.components(), withFactor);
  // Where the host has no pixels: no light, no ID.
  pass_.emplace(image, 0, image.components(), bounds, 0.0f);
  for (int c = 0; c < image.components(); ++c) {
    passes_.push_back({names_.pass[std::size_t(c)].c_str(), &pass_->buffer(), c});
  }
  if (withFactor) {
    factor_.emplace(*factor, 0, factor->components(), bounds, 0.0f);
    for (int c = 0; c < factor->components(); ++c) {
      passes_.push_back({names_.factor[std::size_t(c)].c_str(), &factor_->buffer(), c});
    }
  }
}

}  // namespace taa::ofx
