#version 410 core
// Window resolve, once per frame: which samples are static, i.e. carried to other frames by
// exact camera reprojection from their own depth, and which move and follow their motion
// vectors. Written into the ring as a signed depth: +depth static, -depth moving (the sky,
// +inf, is static: it moves with the camera alone), so the gather reads both in one fetch.
// A sample is static when its motion vector agrees with the camera's motion of a static point
// at its depth, at the sample's own (jittered) position: vectors are the sample's. The first
// frame of a shot has no previous camera; it is checked forward instead: the camera carries
// the sample into the next frame, whose vector there must lead back to it.

#include "camera_geometry.glsl"

// 0 no camera (every sample moves: vectors only), 1 against the previous camera, 2 forward
// against the next frame, 3 a camera but no neighbour in the shot (all static).
uniform int uClassifyMode;
uniform sampler2D uDepth;        // the frame's planar depth, +inf = no hit
uniform sampler2DArray uMotion;  // px, y down, to the previous frame (the ring's)
uniform int uLayer;              // mode 1: the frame's layer of uMotion
uniform int uNextLayer;          // mode 2: the next frame's layer
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
  if (any(lessThan(next, ivec2(0))) || any(greaterThanEqual(next, textureSize(uDepth, 0)))) {
    return true;  // it leaves the frame: nothing to check against; static is the common case
  }
  vec2 back = texelFetch(uMotion, ivec3(next, uNextLayer), 0).xy;
  return distance(other + back, position) <= uTolerance;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(uDepth, pixel, 0).r;
  outSignedDepth = isStatic(pixel, depth) ? depth : -depth;
}
