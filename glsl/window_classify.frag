#version 410 core
// Window resolve, once per frame: which samples are static, i.e. carried to other frames by
// exact camera reprojection from their own depth, and which move and follow their motion
// vectors. Written into the ring as a signed depth: +depth static, -depth moving (the sky,
// +inf, is static: it moves with the camera alone), so the gather reads both in one fetch.
// A sample is static when its motion vector agrees with the camera's motion of a static point
// at its depth, at the sample's own (jittered) position: vectors are the sample's. A frame
// whose previous frame is not in the window (the window's first) is checked forward instead:
// the camera carries the sample into the next frame, whose vector there must lead back to it.
// The frame's depth is read from its layer (its sign, from an earlier classification, ignored)
// and written to another.

#include "camera_geometry.glsl"

// 0 no camera (every sample moves: vectors only), 1 against the previous frame's camera, 2
// forward against the next frame, 3 a camera but no neighbour in the window (all static).
uniform int uClassifyMode;
uniform sampler2DArray uDepth;   // planar depth, +inf = no hit (the ring's, maybe signed)
uniform sampler2DArray uMotion;  // px, y down, to the previous frame (the ring's)
uniform int uDepthLayer;         // the frame's depth layer
uniform int uLayer;              // the frame's motion layer
uniform int uOtherLayer;         // mode 2: the next frame's motion layer
uniform vec2 uJitter;            // the frame's sample offset
uniform mat4 uRasterToCamera;    // the frame's raster -> camera
uniform mat4 uCameraToOtherRaster;  // mode 1: -> the previous frame's raster; 2: the next's
uniform float uTolerance;        // px

layout(location = 0) out float outSignedDepth;

bool isStatic(ivec2 pixel, float depth) {
  if (uClassifyMode == 0) return false;
  // Renderers write zero vectors where nothing is hit; the sky moves with the camera alone.
  if (uClassifyMode == 3 || isinf(depth)) return true;
  vec2 position = gl_FragCoord.xy + uJitter;
  vec2 other = rasterOf(uCameraToOtherRaster, cameraPointOf(uRasterToCamera, position, depth));
  if (uClassifyMode == 1) {
    vec2 vector = texelFetch(uMotion, ivec3(pixel, uLayer), 0).xy;
    return distance(position + vector, other) <= uTolerance;
  }
  // Forward: the next frame's sample nearest to where the camera puts this one; its vector
  // points back to where it was, which is this sample's position if the point did not move.
  ivec2 next = ivec2(floor(other));
  if (any(lessThan(next, ivec2(0))) || any(greaterThanEqual(next, textureSize(uDepth, 0).xy))) {
    return true;  // it leaves the frame: nothing to check against; static is the common case
  }
  vec2 back = texelFetch(uMotion, ivec3(next, uOtherLayer), 0).xy;
  return distance(other + back, position) <= uTolerance;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = abs(texelFetch(uDepth, ivec3(pixel, uDepthLayer), 0).r);
  outSignedDepth = isStatic(pixel, depth) ? depth : -depth;
}
