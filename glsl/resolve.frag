#version 410 core
// The temporal resolve of one output pixel (DESIGN.md section 4): unjitter the current frame,
// reproject history by motion, rectify it against the current neighbourhood, blend.
// Coordinates are raster pixels with y down: gl_FragCoord.xy is the pixel centre (i+0.5, j+0.5).

#include "color_space.glsl"
#include "history_rectify.glsl"
#include "reconstruction.glsl"

// DILATE_MOTION (0/1): take motion from the closest-depth pixel of the 3x3 neighbourhood.
#ifndef DILATE_MOTION
#define DILATE_MOTION 1
#endif

uniform sampler2D uCurrent;  // RGBA, nearest: this frame's jittered samples
uniform sampler2D uHistory;  // RGBA, linear: the previous output
uniform sampler2D uMotion;   // RG, nearest: pixels, y down, to the previous frame
uniform sampler2D uDepth;    // R, nearest: planar depth, +inf = no hit
uniform vec2 uJitter;        // this frame's sample offset from pixel centres, pixels, y down
uniform float uBlend;        // weight of the current frame
uniform bool uHasHistory;
uniform bool uHasMotion;
uniform bool uHasDepth;
uniform bool uClipHistory;

out vec4 outColor;

// Position of the motion sample to use for pixel p: p itself or its closest-depth neighbour.
ivec2 motionSourcePixel(ivec2 p, ivec2 maxPixel) {
#if DILATE_MOTION
  if (uHasDepth) {
    ivec2 best = p;
    float bestDepth = texelFetch(uDepth, p, 0).r;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), maxPixel);
        float d = texelFetch(uDepth, q, 0).r;
        if (d < bestDepth) {
          bestDepth = d;
          best = q;
        }
      }
    }
    return best;
  }
#endif
  return p;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 size = vec2(textureSize(uCurrent, 0));
  ivec2 maxPixel = ivec2(size) - 1;

  // Unjitter: neighbour q's sample sits at (q - pixel) + jitter from this pixel's centre.
  vec4 filtered = vec4(0.0);
  float weightSum = 0.0;
  vec3 boxMin = vec3(1e30);
  vec3 boxMax = vec3(-1e30);
  float alphaMin = 1e30;
  float alphaMax = -1e30;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), maxPixel);
      vec4 sampleColor = texelFetch(uCurrent, q, 0);
      float weight = blackmanHarrisWeight(vec2(dx, dy) + uJitter);
      filtered += weight * sampleColor;
      weightSum += weight;
      vec3 ycocg = rgbToYCoCg(sampleColor.rgb);
      boxMin = min(boxMin, ycocg);
      boxMax = max(boxMax, ycocg);
      alphaMin = min(alphaMin, sampleColor.a);
      alphaMax = max(alphaMax, sampleColor.a);
    }
  }
  filtered /= weightSum;

  vec2 motion = uHasMotion ? texelFetch(uMotion, motionSourcePixel(pixel, maxPixel), 0).xy
                           : vec2(0.0);
  vec2 previousPosition = gl_FragCoord.xy + motion;
  bool onScreen = all(greaterThanEqual(previousPosition, vec2(0.0))) &&
                  all(lessThanEqual(previousPosition, size));
  if (!uHasHistory || !onScreen) {
    outColor = filtered;
    return;
  }

  vec4 history = texture(uHistory, previousPosition / size);
  if (uClipHistory) {
    vec3 target = clamp(rgbToYCoCg(filtered.rgb), boxMin, boxMax);
    history.rgb = yCoCgToRgb(clipToBox(rgbToYCoCg(history.rgb), target, boxMin, boxMax));
    history.a = clamp(history.a, alphaMin, alphaMax);
  }
  outColor = mix(history, filtered, uBlend);
}
