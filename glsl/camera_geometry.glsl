// Camera geometry shared by the resolves: the point a raster position sees at a planar depth,
// for any frame's matrices (built on the CPU by resolve/camera from worldToCamera and
// worldToNDC).

// The camera-space point seen at raster position `position` at planar depth `depth` (w = 0: a
// direction, for depth = +inf). `rasterToCamera` maps (raster x, raster y, ndc z, 1) to
// homogeneous camera space. Unprojects two points of the pixel's ray and walks it to
// z = depth; NDC z 0.25 and 0.75 stay finite for standard, infinite-far and reversed-Z
// projections alike.
vec4 cameraPointOf(mat4 rasterToCamera, vec2 position, float depth) {
  vec4 a = rasterToCamera * vec4(position, 0.25, 1.0);
  vec4 b = rasterToCamera * vec4(position, 0.75, 1.0);
  vec3 near = a.xyz / a.w;
  vec3 far = b.xyz / b.w;
  vec3 along = far - near;
  if (isinf(depth)) return vec4(along * sign(along.z), 0.0);
  float t = (depth - near.z) / along.z;
  return vec4(near + t * along, 1.0);
}

// Raster position of a homogeneous camera-space point through `cameraToRaster` (which maps
// camera space to another frame's (raster x, raster y, ndc z, w)).
vec2 rasterOf(mat4 cameraToRaster, vec4 point) {
  vec4 raster = cameraToRaster * point;
  return raster.xy / raster.w;
}

// The homogeneous raster position (x, y, w) in another frame of the point seen at raster
// `position` at planar depth `depth`, through the rows of resolve/camera's frameCarry() that
// raster needs (resolve/window_resolver's xywRows()): about half the work of cameraPointOf()
// and rasterOf() together.
vec3 carried(mat3 alongDepth, mat3 offset, vec2 position, float depth) {
  vec3 along = alongDepth * vec3(position, 1.0);
  return isinf(depth) ? along : depth * along + offset * vec3(position, 1.0);
}
