#version 410 core
// Window resolve, the thin search's input (--window-thin-search R, window_gather.frag): the
// nearest static depth of frame t's samples in the (2R+1)^2 around each pixel, as two passes of
// a separable minimum: along rows from the ring's layer (FROM_RING 1; moving samples count as
// infinitely far), then along columns of that (FROM_RING 0). 4R + 2 fetches a pixel where the
// gather read (2R+1)^2 - 9. The square takes t's 3x3 in too, which changes nothing: those
// depths are no nearer than the 3x3's nearest, and the gather keeps only a nearer one.

#include "window_ring.glsl"

#ifndef FROM_RING
#define FROM_RING 1
#endif

uniform int uRadius;
#if FROM_RING
uniform usampler2DArray uRing;
uniform int uLayer;
#else
uniform sampler2D uRowMinimum;
#endif

layout(location = 0) out float outDepth;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#if FROM_RING
  ivec2 size = textureSize(uRing, 0).xy;
  ivec2 step = ivec2(1, 0);
#else
  ivec2 size = textureSize(uRowMinimum, 0);
  ivec2 step = ivec2(0, 1);
#endif
  float nearest = 1.0 / 0.0;
  for (int d = -uRadius; d <= uRadius; ++d) {
    ivec2 n = clamp(pixel + d * step, ivec2(0), size - 1);  // edges repeat, as in the gather
#if FROM_RING
    float depth = ringDepth(texelFetch(uRing, ivec3(n, uLayer), 0));
#else
    float depth = texelFetch(uRowMinimum, n, 0).r;
#endif
    nearest = depth >= 0.0 ? min(nearest, depth) : nearest;  // static samples only
  }
  outDepth = nearest;
}
