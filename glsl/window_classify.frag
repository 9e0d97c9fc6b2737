#version 410 core
// Window resolve: which samples of a frame are static, i.e. carried to other frames by exact
// camera reprojection from their own depth, and which move and follow their motion vectors.
// Written into the ring as a signed depth (window_ring.glsl): +depth static, -depth moving
// (the sky, +inf, is static: it moves with the camera alone).
// A sample is static when its motion vector agrees with the camera's motion of a static point
// at its depth, at the sample's own (jittered) position: vectors are the sample's. A frame
// whose previous frame is not in the window (the window's first) is checked forward instead:
// the camera carries the sample into the next frame, whose vector there must lead back to it
// (or, where the next frame sees another surface, its own vector must match the camera's
// motion extrapolated backward).
// The frame's samples are read from its layer (the depth's sign, from an earlier
// classification, ignored) and written to another, their motion copied to that layer of the
// motion ring.

#include "camera_geometry.glsl"
#include "window_ring.glsl"

// 0 no camera (every sample moves: vectors only), 1 against the previous frame's camera, 2
// forward against the next frame, 3 a camera but no neighbour in the window (all static).
uniform int uClassifyMode;
uniform usampler2DArray uRing;   // the ring's samples
uniform usampler2DArray uRingMotion;  // their motion
uniform int uLayer;              // the frame's layer
uniform int uOtherLayer;         // mode 2: the next frame's layer
uniform vec2 uJitter;            // the frame's sample offset
uniform mat4 uRasterToCamera;    // the frame's raster -> camera
uniform mat4 uCameraToOtherRaster;  // mode 1: -> the previous frame's raster; 2: the next's
uniform mat4 uCameraToOtherCamera;  // mode 2: -> the next frame's camera space
uniform float uTolerance;        // px

layout(location = 0) out uvec4 outSample;
layout(location = 1) out uint outMotion;

bool isStatic(ivec2 pixel, float depth, vec2 vector) {
  if (uClassifyMode == 0) return false;
  // Renderers write zero vectors where nothing is hit; the sky moves with the camera alone.
  if (uClassifyMode == 3 || isinf(depth)) return true;
  vec2 position = gl_FragCoord.xy + uJitter;
  vec4 point = cameraPointOf(uRasterToCamera, position, depth);
  vec2 other = rasterOf(uCameraToOtherRaster, point);
  if (uClassifyMode == 1) return distance(position + vector, other) <= uTolerance;
  // Forward: the next frame's sample nearest to where the camera puts this one; its vector
  // points back to where it was, which is this sample's position if the point did not move.
  ivec2 next = ivec2(floor(other));
  if (any(lessThan(next, ivec2(0))) || any(greaterThanEqual(next, textureSize(uRing, 0).xy))) {
    return true;  // it leaves the frame: nothing to check against; static is the common case
  }
  uvec4 nextTexel = texelFetch(uRing, ivec3(next, uOtherLayer), 0);
  // Only the same surface can say. Where the next frame sees something else there (a wire
  // passing in front by parallax, or the background a moving object uncovers as it leaves),
  // the sample's own vector, to the previous frame, must agree with the camera's motion run
  // backward, as fast as it goes forward within half of it: a static point's does, while the
  // trailing edge of a moving object (which the next frame no longer sees) does not, and taken
  // for static it would be carried to t where the object has long left: a ghost of its edge.
  float expected = (uCameraToOtherCamera * point).z;
  if (abs(abs(ringDepth(nextTexel)) - expected) > 0.05 * expected) {
    vec2 backward = 2.0 * position - other;
    return distance(position + vector, backward) <= uTolerance + 0.5 * distance(other, position);
  }
  vec2 nextVector = unpackRingMotion(texelFetch(uRingMotion, ivec3(next, uOtherLayer), 0).r);
  return distance(other + nextVector, position) <= uTolerance;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uvec4 texel = texelFetch(uRing, ivec3(pixel, uLayer), 0);
  uint motion = texelFetch(uRingMotion, ivec3(pixel, uLayer), 0).r;
  float depth = abs(ringDepth(texel));
  bool still = isStatic(pixel, depth, unpackRingMotion(motion));
  outSample = withRingDepth(texel, still ? depth : -depth);
  outMotion = motion;
}
