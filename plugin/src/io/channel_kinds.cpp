#include "io/channel_kinds.h"

#include <fnmatch.h>

#include <algorithm>
#include <array>
#include <utility>

#include "taa/error.h"

namespace taa::io {
namespace {

constexpr std::array<std::pair<const char*, ChannelKind>, 8> kKindNames{{
    {"light", ChannelKind::Light},
    {"factor", ChannelKind::Factor},
    {"average", ChannelKind::Average},
    {"normal", ChannelKind::Normal},
    {"nearest", ChannelKind::Nearest},
    {"cryptomatte", ChannelKind::Cryptomatte},
    {"copy", ChannelKind::Copy},
    {"drop", ChannelKind::Drop},
}};

// Pass names and their kinds. Cycles' as Blender 3.4.1 writes them with every pass on
// (measured); Arnold's, RenderMan's and Karma's from their documentation (assumed, untested).
struct PassName {
  const char* name;
  ChannelKind kind;
};
constexpr PassName kPassNames[] = {
    // Cycles
    {"Combined", ChannelKind::Light}, {"DiffDir", ChannelKind::Light},
    {"DiffInd", ChannelKind::Light}, {"GlossDir", ChannelKind::Light},
    {"GlossInd", ChannelKind::Light}, {"TransDir", ChannelKind::Light},
    {"TransInd", ChannelKind::Light}, {"VolumeDir", ChannelKind::Light},
    {"VolumeInd", ChannelKind::Light}, {"Emit", ChannelKind::Light},
    {"Env", ChannelKind::Light}, {"AO", ChannelKind::Light}, {"Shadow", ChannelKind::Light},
    {"ShadowCatcher", ChannelKind::Light}, {"DiffCol", ChannelKind::Factor},
    {"GlossCol", ChannelKind::Factor}, {"TransCol", ChannelKind::Factor},
    {"Normal", ChannelKind::Normal}, {"Position", ChannelKind::Average},
    {"UV", ChannelKind::Average}, {"Depth", ChannelKind::Nearest},
    {"Mist", ChannelKind::Nearest}, {"IndexOB", ChannelKind::Nearest},
    {"IndexMA", ChannelKind::Nearest}, {"Vector", ChannelKind::Nearest},
    {"Denoising Albedo", ChannelKind::Factor}, {"Denoising Normal", ChannelKind::Normal},
    {"Denoising Depth", ChannelKind::Nearest}, {"Sample Count", ChannelKind::Nearest},
    // Arnold (assumed)
    {"RGBA", ChannelKind::Light}, {"direct", ChannelKind::Light},
    {"indirect", ChannelKind::Light}, {"diffuse", ChannelKind::Light},
    {"diffuse_direct", ChannelKind::Light}, {"diffuse_indirect", ChannelKind::Light},
    {"specular", ChannelKind::Light}, {"specular_direct", ChannelKind::Light},
    {"specular_indirect", ChannelKind::Light}, {"transmission", ChannelKind::Light},
    {"transmission_direct", ChannelKind::Light}, {"transmission_indirect", ChannelKind::Light},
    {"sss", ChannelKind::Light}, {"volume", ChannelKind::Light},
    {"emission", ChannelKind::Light}, {"background", ChannelKind::Light},
    {"diffuse_albedo", ChannelKind::Factor}, {"specular_albedo", ChannelKind::Factor},
    {"transmission_albedo", ChannelKind::Factor}, {"albedo", ChannelKind::Factor},
    {"N", ChannelKind::Normal}, {"P", ChannelKind::Average}, {"Pref", ChannelKind::Average},
    {"Z", ChannelKind::Nearest}, {"ID", ChannelKind::Nearest},
    {"motionvector", ChannelKind::Nearest},
    // RenderMan and Karma (assumed)
    {"Ci", ChannelKind::Light}, {"C", ChannelKind::Light},
    {"directDiffuse", ChannelKind::Light}, {"indirectDiffuse", ChannelKind::Light},
    {"directSpecular", ChannelKind::Light}, {"indirectSpecular", ChannelKind::Light},
    {"emissive", ChannelKind::Light}, {"subsurface", ChannelKind::Light},
    {"transmissive", ChannelKind::Light}, {"Nn", ChannelKind::Normal},
    {"z", ChannelKind::Nearest}, {"Pz", ChannelKind::Nearest}, {"depth", ChannelKind::Nearest},
    {"id", ChannelKind::Nearest},
};

// "ViewLayer.DiffDir.R" -> "DiffDir"; "diffuse.R" -> "diffuse"; "Z" -> "Z".
std::string passNameOf(const std::string& channel) {
  const std::size_t last = channel.rfind('.');
  if (last == std::string::npos) return channel;
  const std::size_t before = channel.rfind('.', last == 0 ? 0 : last - 1);
  const std::size_t start = before == std::string::npos || before >= last ? 0 : before + 1;
  return channel.substr(start, last - start);
}

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string kindName(ChannelKind kind) {
  for (const auto& [name, k] : kKindNames) {
    if (k == kind) return name;
  }
  return "?";
}

ChannelKindRule parseChannelKindRule(const std::string& text) {
  const std::size_t equals = text.rfind('=');
  std::string kinds;
  for (const auto& entry : kKindNames) kinds += (kinds.empty() ? "" : ", ") + std::string(entry.first);
  if (equals == std::string::npos || equals == 0) {
    throw Error("--aov wants PATTERN=kind, got '" + text + "' (kinds: " + kinds + ")");
  }
  const std::string kind = text.substr(equals + 1);
  for (const auto& [name, k] : kKindNames) {
    if (kind == name) return {text.substr(0, equals), k};
  }
  throw Error("--aov '" + text + "': unknown kind '" + kind + "' (kinds: " + kinds + ")");
}

ChannelKind channelKind(const std::string& channel, const std::vector<ChannelKindRule>& rules) {
  for (const ChannelKindRule& rule : rules) {
    if (::fnmatch(rule.pattern.c_str(), channel.c_str(), 0) == 0) return rule.kind;
  }
  const std::string pass = passNameOf(channel);
  // Cryptomatte layers: Blender's CryptoObject00, Arnold's crypto_object00, any "cryptomatte".
  std::string lower = pass;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (startsWith(lower, "crypto")) return ChannelKind::Cryptomatte;
  for (const PassName& known : kPassNames) {
    if (pass == known.name) return known.kind;
  }
  // Unknown: colour components are taken for light (a renderer's light group or custom AOV);
  // anything else is data, never blended.
  const std::string component = channel.substr(channel.rfind('.') + 1);
  for (const char* rgba : {"R", "G", "B", "A", "r", "g", "b", "a"}) {
    if (component == rgba) return ChannelKind::Light;
  }
  return ChannelKind::Nearest;
}

std::string factorChannelOf(const std::string& channel) {
  const std::string pass = passNameOf(channel);
  std::string factor;
  for (const char* suffix : {"Dir", "Ind"}) {  // Cycles: DiffDir, DiffInd -> DiffCol
    if (endsWith(pass, suffix) && pass.size() > 3) factor = pass.substr(0, pass.size() - 3) + "Col";
  }
  for (const char* suffix : {"_direct", "_indirect"}) {  // Arnold: diffuse_direct -> _albedo
    if (endsWith(pass, suffix)) factor = pass.substr(0, pass.size() - std::string(suffix).size()) + "_albedo";
  }
  if (factor.empty() || factor == "VolumeCol") return "";
  // The same layer prefix and component around the factor's pass name.
  const std::size_t last = channel.rfind('.');
  const std::size_t start = last == std::string::npos ? 0 : channel.rfind(pass + ".", last);
  if (last == std::string::npos || start == std::string::npos) return "";
  return channel.substr(0, start) + factor + channel.substr(last);
}

}  // namespace taa::io
