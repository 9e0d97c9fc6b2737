#version 410 core
// Window resolve: whether a moving sample of t lies near each pixel (window_surroundings.frag's
// G, where the region test takes its stricter tolerance: a moving object's contact shadow
// moves with it), on a coarse grid of blocks of uStride x uStride pixels: first whether any of
// t's samples in a block moves (FROM_RING 1), then that widened by uReach blocks each way
// along rows, then columns (FROM_RING 0). The stride grows with the picture, so that the
// reach covers the same part of it at any size; at the reference size a block is a pixel. Every
// sample counts, however narrow the object, for about a tenth of the fetches a strided search
// around every pixel took at 1080p (docs/PERFORMANCE.md, "The near-moving search on blocks").

#include "window_ring.glsl"

#ifndef FROM_RING
#define FROM_RING 1
#endif

#if FROM_RING
uniform usampler2DArray uRing;
uniform int uLayer;
uniform int uStride;
#else
uniform sampler2D uBlocks;
uniform int uReach;
uniform bool uAlongColumns;
#endif

layout(location = 0) out float outMoving;

void main() {
  ivec2 block = ivec2(gl_FragCoord.xy);
  float moving = 0.0;
  // Loops whose test comes at the end (window_gather.frag: llvmpipe runs an iteration a test at
  // the top breaks to its end, masked). Both run at least once.
#if FROM_RING
  ivec2 size = textureSize(uRing, 0).xy;
  ivec2 corner = block * uStride;
  int i = 0;
  do {
    ivec2 n = min(corner + ivec2(i % uStride, i / uStride), size - 1);  // the last blocks' edge
    moving = max(moving, ringDepth(texelFetch(uRing, ivec3(n, uLayer), 0)) < 0.0 ? 1.0 : 0.0);
    ++i;
  } while (i < uStride * uStride);
#else
  ivec2 size = textureSize(uBlocks, 0);
  ivec2 step = uAlongColumns ? ivec2(0, 1) : ivec2(1, 0);
  int d = -uReach;
  do {
    moving = max(moving, texelFetch(uBlocks, clamp(block + d * step, ivec2(0), size - 1), 0).r);
    ++d;
  } while (d <= uReach);
#endif
  outMoving = moving;
}
