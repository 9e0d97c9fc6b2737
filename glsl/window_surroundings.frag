#version 410 core
// Window resolve, what the gather needs from around each pixel of frame t, as two passes of a
// separable reduction: along rows from the ring's layer (FROM_RING 1), then along columns of
// that (FROM_RING 0). Into an RG32F texture the gather reads once a pixel:
// - R, the thin search's input (--window-thin-search R): the nearest static depth of t's
//   samples in the (2R+1)^2 around the pixel (moving samples count as infinitely far). The
//   square takes t's 3x3 in too, which changes nothing: those depths are no nearer than the
//   3x3's nearest, and the gather keeps only a nearer one;
// - G, 1 where a moving sample of t lies within uMovingRadius pixels each way, looked for at
//   every uMovingStride-th pixel (the stride grows with the picture, so that the radius covers
//   the same part of it at any size for the same fetches; a moving object narrower than the
//   stride may be missed): the region test's stricter tolerance applies there (a moving
//   object's contact shadow moves with it). uMovingRadius is 0 in a frame without moving
//   samples: nothing to look for.
// 2 (2R + 1) + 2 (2 uMovingRadius / uMovingStride + 1) fetches a pixel, where the gather read
// (2R+1)^2 - 9 for R.

#include "window_ring.glsl"

#ifndef FROM_RING
#define FROM_RING 1
#endif

uniform int uRadius;
uniform int uMovingRadius;  // G: whether a moving sample lies within this many pixels
uniform int uMovingStride;  // looking at every this many
#if FROM_RING
uniform usampler2DArray uRing;
uniform int uLayer;
#else
uniform sampler2D uRows;  // R: nearest static depth, G: moving within
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
  int steps = uMovingRadius / uMovingStride;
  int m = -steps;
  do {
    ivec2 n = clamp(pixel + m * uMovingStride * step, ivec2(0), size - 1);
#if FROM_RING
    moving = max(moving, ringDepth(texelFetch(uRing, ivec3(n, uLayer), 0)) < 0.0 ? 1.0 : 0.0);
#else
    moving = max(moving, texelFetch(uRows, n, 0).g);
#endif
    ++m;
  } while (m <= steps);
  outSurroundings = vec2(nearest, moving);
}
