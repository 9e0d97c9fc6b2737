#version 410 core
// Window resolve: does a frame have any moving sample? Static samples are discarded, an
// occlusion query counts whether anything passed (nothing is written). A window whose frames
// have none is gathered without the chains' code (window_gather.frag, CHAINS 0).

#include "window_ring.glsl"

uniform usampler2DArray uRing;
uniform int uLayer;

layout(location = 0) out uvec4 outUnused;

void main() {
  if (ringDepth(texelFetch(uRing, ivec3(ivec2(gl_FragCoord.xy), uLayer), 0)) >= 0.0) discard;
  outUnused = uvec4(0u);
}
