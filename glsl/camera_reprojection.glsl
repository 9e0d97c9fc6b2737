// Motion from depth and the two frames' cameras, for pixels whose motion vectors are absent or
// unreliable (no geometry: Cycles writes zero vectors on the sky even when the camera moves).

#include "camera_geometry.glsl"

// uRasterToCamera maps (raster x, raster y, ndc z, 1) of this frame to homogeneous camera space;
// uCameraToPreviousRaster maps this frame's camera space to the previous frame's (raster x,
// raster y, ndc z, w). Both are built on the CPU from worldToCamera / worldToNDC.
uniform mat4 uRasterToCamera;
uniform mat4 uCameraToPreviousRaster;
uniform mat4 uCameraToPreviousCamera;

vec4 cameraPoint(vec2 position, float depth) {
  return cameraPointOf(uRasterToCamera, position, depth);
}

// Motion (pixels, y down, to the previous frame) of a static surface at `depth`.
vec2 cameraMotion(vec2 position, float depth) {
  return rasterOf(uCameraToPreviousRaster, cameraPoint(position, depth)) - position;
}

// Planar depth the static surface at `depth` had in the previous frame (+inf stays +inf).
float previousCameraDepth(vec2 position, float depth) {
  if (isinf(depth)) return depth;
  return (uCameraToPreviousCamera * cameraPoint(position, depth)).z;
}
