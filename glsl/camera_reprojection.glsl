// Motion from depth and the two frames' cameras, for pixels whose motion vectors are absent or
// unreliable (no geometry: Cycles writes zero vectors on the sky even when the camera moves).

// uRasterToCamera maps (raster x, raster y, ndc z, 1) of this frame to homogeneous camera space;
// uCameraToPreviousRaster maps this frame's camera space to the previous frame's (raster x,
// raster y, ndc z, w). Both are built on the CPU from worldToCamera / worldToNDC.
uniform mat4 uRasterToCamera;
uniform mat4 uCameraToPreviousRaster;
uniform mat4 uCameraToPreviousCamera;

// The camera-space point seen at raster position `position` at planar depth `depth` (w = 0: a
// direction, for depth = +inf). Unprojects two points of the pixel's ray and walks it to z = depth;
// NDC z 0.25 and 0.75 stay finite for standard, infinite-far and reversed-Z projections alike.
vec4 cameraPoint(vec2 position, float depth) {
  vec4 a = uRasterToCamera * vec4(position, 0.25, 1.0);
  vec4 b = uRasterToCamera * vec4(position, 0.75, 1.0);
  vec3 near = a.xyz / a.w;
  vec3 far = b.xyz / b.w;
  vec3 along = far - near;
  if (isinf(depth)) return vec4(along * sign(along.z), 0.0);
  float t = (depth - near.z) / along.z;
  return vec4(near + t * along, 1.0);
}

// Motion (pixels, y down, to the previous frame) of a static surface at `depth`.
vec2 cameraMotion(vec2 position, float depth) {
  vec4 previous = uCameraToPreviousRaster * cameraPoint(position, depth);
  return previous.xy / previous.w - position;
}

// Planar depth the static surface at `depth` had in the previous frame (+inf stays +inf).
float previousCameraDepth(vec2 position, float depth) {
  if (isinf(depth)) return depth;
  return (uCameraToPreviousCamera * cameraPoint(position, depth)).z;
}
