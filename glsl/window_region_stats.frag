#version 410 core
// Window resolve, the region test's statistics (WindowOptions::regionTolerance): for each 2x2
// block of a classified frame (a quarter of the pixels: its time and memory), a plane fitted to
// the decision luma of its static samples over the 6x6 centred on the block, and the variance
// of its value from what the plane leaves (a smooth gradient, a highlight's or a penumbra's, is
// no noise; docs/TUNING.md, "A plane for the region test"). Where a frame's samples differ from
// t's by less than one sample's noise (a contact shadow under 1-spp bounce noise), the fits of
// 36 tell.
// Written once per classification of a ring layer, into the stats array's same layer.

#include "color_space.glsl"
#include "window_ring.glsl"

uniform usampler2DArray uRing;
uniform int uLayer;
uniform bool uLinear;  // the ring holds input values: compressed as the gather's decisionLuma

// A plane fitted to the lumas (value at the block's centre, slope per pixel x and y) and the
// variance of its value from the residuals; the variance is -1 where fewer than 12 static
// samples were found (an object's inside, the screen's corner): no test there.
layout(location = 0) out vec4 outStats;

void main() {
  ivec2 block = 2 * ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uRing, 0).xy;
  float count = 0.0, sum = 0.0, squares = 0.0;
  float sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0, sxv = 0.0, syv = 0.0;
  for (int dy = -2; dy <= 3; ++dy) {
    for (int dx = -2; dx <= 3; ++dx) {
      ivec2 wanted = block + ivec2(dx, dy);
      ivec2 n = clamp(wanted, ivec2(0), size - 1);
      RingSample entry = unpackRingSample(texelFetch(uRing, ivec3(n, uLayer), 0));
      float y = luma(entry.colour.rgb);
      y = uLinear ? (y >= 0.0 ? y / (y + 4.0) : 0.25 * y) : y;
      float use = entry.depth >= 0.0 && n == wanted ? 1.0 : 0.0;  // static, on screen
      vec2 at = vec2(dx, dy) - 0.5;  // from the block's centre
      count += use;
      sum += use * y;
      squares += use * y * y;
      sx += use * at.x;
      sy += use * at.y;
      sxx += use * at.x * at.x;
      syy += use * at.y * at.y;
      sxy += use * at.x * at.y;
      sxv += use * at.x * y;
      syv += use * at.y * y;
    }
  }
  // Least squares for (value, slope x, slope y) from the normal equations; the mean, flat,
  // where they are singular (samples on a line).
  mat3 normal = mat3(count, sx, sy, sx, sxx, sxy, sy, sxy, syy);
  vec3 right = vec3(sum, sxv, syv);
  float det = determinant(normal);
  float mean = sum / max(count, 1.0);
  vec3 plane = abs(det) > 1e-3 * max(count * count * count, 1.0) ? inverse(normal) * right
                                                                  : vec3(mean, 0.0, 0.0);
  float residual = max(squares - dot(plane, right), 0.0);
  float variance = residual / max(count - 3.0, 1.0);
  outStats = vec4(plane, count >= 12.0 ? variance / count : -1.0);
}
