#include "io/renderer_presets.h"

#include "taa/error.h"

namespace taa::io {
namespace {

using Names = std::vector<std::string>;

MotionConvention motion(MotionUnits units, bool toPrevious, bool yUp,
                        MotionEncoding encoding = MotionEncoding::Signed) {
  MotionConvention m;
  m.units = units;
  m.toPrevious = toPrevious;
  m.yUp = yUp;
  m.encoding = encoding;
  return m;
}

DepthConvention depth(DepthKind kind, float noHitAbove = 1e9f) {
  DepthConvention d;
  d.kind = kind;
  d.noHitAbove = noHitAbove;
  return d;
}

std::vector<RendererPreset> makePresets() {
  constexpr bool kToPrevious = true, kForward = false, kYUp = true, kYDown = false;
  const Names rgba = {"R", "G", "B", "A"};
  return {
      // Verified on a Blender render (DESIGN.md section 3).
      {"cycles", "Blender Cycles (multi-layer EXR)",
       {"{layer}Combined.R", "{layer}Combined.G", "{layer}Combined.B", "{layer}Combined.A"},
       {"{layer}Depth.Z"}, {"{layer}Vector.X", "{layer}Vector.Y"},
       motion(MotionUnits::Pixels, kToPrevious, kYUp), depth(DepthKind::Planar)},
      // Channel sets forward/backward and a 1/Z depth output are documented by Foundry; the
      // sign (backward = previous - current) and y up follow Nuke's y-up image space (assumed).
      {"nuke", "Foundry Nuke (ScanlineRender, VectorGenerator)", rgba, {"depth.Z"},
       {"backward.u", "backward.v"}, motion(MotionUnits::Pixels, kToPrevious, kYUp),
       depth(DepthKind::Inverse)},
      // Arnold's motion vector shader writes R, G over the shutter (time0 -> time1), raw with
      // "encode raw vector"; channel names, y direction and depth kind are assumed.
      {"arnold", "Autodesk Arnold (motionvector AOV, raw)", rgba, {"Z"},
       {"motionvector.R", "motionvector.G"}, motion(MotionUnits::Pixels, kForward, kYUp),
       depth(DepthKind::Planar)},
      // RenderMan's motionBack points to the previous frame in raster space (y down); the
      // channel suffixes and planar z are assumed.
      {"renderman", "Pixar RenderMan (motionBack, z)", rgba, {"z"},
       {"motionBack.r", "motionBack.g"}, motion(MotionUnits::Pixels, kToPrevious, kYDown),
       depth(DepthKind::Planar)},
      // V-Ray's Velocity element is documented as current -> next frame; raw only with "Clamp
      // velocity" off. Channel names, units and y direction are assumed.
      {"vray", "Chaos V-Ray (VRayVelocity, clamp off)", rgba, {"VRayZDepth.Z"},
       {"VRayVelocity.R", "VRayVelocity.G"}, motion(MotionUnits::Pixels, kForward, kYUp),
       depth(DepthKind::Planar)},
      // Karma's beauty render var is "C" (documented); motionvector and Pz are assumed.
      {"karma", "SideFX Karma (Solaris render vars)", {"C.R", "C.G", "C.B", "C.A"}, {"Pz.Z"},
       {"motionvector.R", "motionvector.G"}, motion(MotionUnits::Pixels, kForward, kYUp),
       depth(DepthKind::Planar)},
      // Redshift's Motion Vectors AOV stores x, y in R, G (documented); raw pixels ("no clamp"),
      // direction, y and names are assumed.
      {"redshift", "Maxon Redshift (Motion Vectors AOV, raw)", rgba, {"Z.Z"},
       {"MotionVectors.R", "MotionVectors.G"}, motion(MotionUnits::Pixels, kForward, kYUp),
       depth(DepthKind::Planar)},
      // Movie Render Queue writes one file per pass; give --depth and --motion patterns. The
      // motion-vector material's encoding (UV units, 0.5 centred, previous -> current velocity,
      // y down) is assumed; scene depth is planar (assumed).
      {"unreal", "Epic Unreal Engine Movie Render Queue (separate pass files)", rgba, {"R"},
       {"R", "G"},
       motion(MotionUnits::Uv, kForward, kYDown, MotionEncoding::Centred),
       depth(DepthKind::Planar)},
  };
}

Names expandLayer(const Names& names, const std::string& layer) {
  const std::string prefix = layer.empty() ? std::string() : layer + ".";
  Names expanded;
  for (std::string name : names) {
    const std::size_t at = name.find("{layer}");
    if (at != std::string::npos) name.replace(at, 7, prefix);
    expanded.push_back(name);
  }
  return expanded;
}

}  // namespace

const std::vector<RendererPreset>& rendererPresets() {
  static const std::vector<RendererPreset> presets = makePresets();
  return presets;
}

std::string presetNames() {
  std::string names;
  for (const RendererPreset& p : rendererPresets()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

AovLayout presetLayout(const std::string& name, const std::string& colorPattern,
                       const std::string& layer) {
  for (const RendererPreset& p : rendererPresets()) {
    if (p.name != name) continue;
    AovLayout layout;
    layout.color = {colorPattern, expandLayer(p.colorChannels, layer), ""};
    layout.depth = AovSource{"", expandLayer(p.depthChannels, layer), ""};
    layout.motion = AovSource{"", expandLayer(p.motionChannels, layer), ""};
    layout.motionConvention = p.motionConvention;
    layout.depthConvention = p.depthConvention;
    return layout;
  }
  throw Error("unknown preset \"" + name + "\" (known: " + presetNames() + ")");
}

}  // namespace taa::io
