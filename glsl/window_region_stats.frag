#version 410 core
// Window resolve, the region test's statistics (WindowOptions::regionTolerance): for each 2x2
// block of a classified frame (a quarter of the pixels: its time and memory), the mean of the
// decision luma of its static samples over the 6x6 centred on the block and the variance of
// that mean. Where a frame's samples differ from t's by less than
// one sample's noise (a contact shadow under 1-spp bounce noise), the means of 36 tell.
// Written once per classification of a ring layer, into the stats array's same layer.

#include "color_space.glsl"
#include "window_ring.glsl"

uniform usampler2DArray uRing;
uniform int uLayer;
uniform bool uLinear;  // the ring holds input values: compressed as the gather's decisionLuma

// Mean, variance of the mean; the variance is -1 where fewer than 12 static samples were found
// (an object's inside, the screen's corner): no test there.
layout(location = 0) out vec2 outStats;

void main() {
  ivec2 block = 2 * ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uRing, 0).xy;
  float count = 0.0, sum = 0.0, squares = 0.0;
  for (int dy = -2; dy <= 3; ++dy) {
    for (int dx = -2; dx <= 3; ++dx) {
      ivec2 wanted = block + ivec2(dx, dy);
      ivec2 n = clamp(wanted, ivec2(0), size - 1);
      RingSample entry = unpackRingSample(texelFetch(uRing, ivec3(n, uLayer), 0));
      float y = luma(entry.colour.rgb);
      y = uLinear ? (y >= 0.0 ? y / (y + 4.0) : 0.25 * y) : y;
      float use = entry.depth >= 0.0 && n == wanted ? 1.0 : 0.0;  // static, on screen
      count += use;
      sum += use * y;
      squares += use * y * y;
    }
  }
  float mean = sum / max(count, 1.0);
  float variance = max(squares / max(count, 1.0) - mean * mean, 0.0);
  outStats = vec2(mean, count >= 12.0 ? variance / count : -1.0);
}
