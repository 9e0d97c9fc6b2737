#version 410 core
// Window resolve, what the gather needs from around each pixel of frame t, as two passes of a
// separable reduction: along rows from the ring's layer (FROM_RING 1), then along columns of
// that (FROM_RING 0: the rows' pass has only R to give, into an R32F texture). Into an RG32F
// texture the gather reads once a pixel:
// - R, the thin search's input (--window-thin-search R): the nearest static depth of t's
//   samples in the (2R+1)^2 around the pixel (moving samples count as infinitely far). The
//   square takes t's 3x3 in too, which changes nothing: those depths are no nearer than the
//   3x3's nearest, and the gather keeps only a nearer one;
// - G, 1 where a moving sample of t is near (window_near_moving.frag's blocks, read by the
//   columns pass at the pixel's block; none in a frame without moving samples): the region
//   test's stricter tolerance applies there (a moving object's contact shadow moves with it).
// 2 (2R + 1) fetches a pixel, where the gather read (2R+1)^2 - 9 for R.

#include "window_ring.glsl"

#ifndef FROM_RING
#define FROM_RING 1
#endif

uniform int uRadius;
#if FROM_RING
uniform usampler2DArray uRing;
uniform int uLayer;
#else
uniform sampler2D uRows;  // R: nearest static depth along the row
uniform bool uAnyMoving;  // t has moving samples: uNearMoving holds where they are near
uniform sampler2D uNearMoving;
uniform int uNearMovingStride;  // pixels a block each way
#endif

layout(location = 0) out vec2 outSurroundings;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#if FROM_RING
  ivec2 size = textureSize(uRing, 0).xy;
  ivec2 step = ivec2(1, 0);
#else
  ivec2 size = textureSize(uRows, 0);
  ivec2 step = ivec2(0, 1);
#endif
  // Loops whose test comes at the end: llvmpipe runs an iteration that a test at the top
  // breaks to its end, masked (window_gather.frag). Both run at least once (radii >= 0).
  float nearest = 1.0 / 0.0;
  int d = -uRadius;
  do {
    ivec2 n = clamp(pixel + d * step, ivec2(0), size - 1);  // edges repeat, as in the gather
#if FROM_RING
    float depth = ringDepth(texelFetch(uRing, ivec3(n, uLayer), 0));
#else
    float depth = texelFetch(uRows, n, 0).r;
#endif
    nearest = depth >= 0.0 ? min(nearest, depth) : nearest;  // static samples only
    ++d;
  } while (d <= uRadius);
  float moving = 0.0;
#if !FROM_RING
  moving = uAnyMoving ? texelFetch(uNearMoving, pixel / uNearMovingStride, 0).r : 0.0;
#endif
  outSurroundings = vec2(nearest, moving);
}
