// What each channel of a render is, so that every pass is resolved the way the comp uses it
// (issue 21): light adds up, factors multiply light, some data averages, the rest must never be
// blended. A channel's kind comes from the user's rules (--aov PATTERN=kind, first match wins),
// else from the pass names renderers write (Cycles measured; others from their documentation).
#pragma once

#include <string>
#include <vector>

namespace taa::io {

enum class ChannelKind {
  Light,        // additive radiance: summed with the beauty's weights
  Factor,       // a colour pass light is multiplied by (albedo): summed with the same weights
  Average,      // data that averages (UV, position)
  Normal,       // averaged, then the vector renormalised
  Nearest,      // depth, IDs, vectors: frame t's own sample, never a blend
  Cryptomatte,  // ID / coverage rank pairs
  Copy,         // copied untouched (--passthrough)
  Drop,         // not written
};

// "light", "factor", ... as --aov spells them.
std::string kindName(ChannelKind kind);

struct ChannelKindRule {
  std::string pattern;  // fnmatch on the whole channel name
  ChannelKind kind = ChannelKind::Light;
};

// "PATTERN=kind"; throws taa::Error quoting the text and listing the kinds.
ChannelKindRule parseChannelKindRule(const std::string& text);

// The kind of `channel` (a whole name such as "ViewLayer.DiffDir.R"): the first rule that
// matches, else the kind its pass name has (the name's component before the last, or the
// name itself without one).
ChannelKind channelKind(const std::string& channel, const std::vector<ChannelKindRule>& rules);

// A light channel's factor: "ViewLayer.DiffDir.R" -> "ViewLayer.DiffCol.R" (Cycles' Dir/Ind
// with Col), "diffuse_direct.R" -> "diffuse_albedo.R"; "" when the name has none. The caller
// checks that the file holds it.
std::string factorChannelOf(const std::string& channel);

}  // namespace taa::io
