// Weights of a carried sample in the window resolve (DESIGN.md section 4, "window resolve").

// Gaussian of the sample's distance to the output pixel centre: a small splat, sharper than a
// box of the pixel and smoother where few samples land (sigma ~0.35 px).
float spatialWeight(vec2 offset, float sigma) {
  return exp(-dot(offset, offset) / (2.0 * sigma * sigma));
}

// Weight by distance in frames: 1 / (1 + (frames / falloff)^2); falloff 0: every frame alike.
float temporalWeight(int frames, float falloff) {
  if (falloff <= 0.0) return 1.0;
  float x = float(frames) / falloff;
  return 1.0 / (1.0 + x * x);
}

// How well a sample agrees with the resolved frame's own 3x3 colour box (YCoCg, working
// space): 1 inside it, falling linearly to 0 at `tolerance` times the box's luma extent (plus a
// floor, so flat regions keep a little room) outside. Shading that changed over the window (a
// shadow that moved) falls outside and is left out.
float colourWeight(vec3 sampleYCoCg, vec3 boxMin, vec3 boxMax, float tolerance) {
  if (tolerance <= 0.0) return 1.0;
  float margin = tolerance * (boxMax.x - boxMin.x + 0.02);
  vec3 outside = max(max(boxMin - sampleYCoCg, sampleYCoCg - boxMax), vec3(0.0));
  float excess = max(outside.x, max(outside.y, outside.z)) / margin;
  return clamp(1.0 - excess, 0.0, 1.0);
}

// Visibility in the resolved frame: a carried sample is hidden only when every one of the
// frame's samples around where it lands is nearer (the farthest of them nearer than it). A
// test against the nearest alone would drop the backdrop beside every wire.
bool hiddenBehind(float carriedDepth, float farthestAround, float tolerance) {
  if (tolerance <= 0.0 || isinf(farthestAround)) return false;
  return isinf(carriedDepth) || farthestAround < carriedDepth * (1.0 - tolerance);
}

// True when the carried sample is nearer than every sample the frame has around it: a thin
// feature the frame's own samples missed (a sub-pixel wire). Its colour cannot be checked
// against a box that does not contain it, so the colour test is skipped for it.
bool nearerThanAll(float carriedDepth, float nearestAround, float tolerance) {
  if (isinf(carriedDepth)) return false;
  return isinf(nearestAround) || carriedDepth < nearestAround * (1.0 - tolerance);
}
