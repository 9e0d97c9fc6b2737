// Weights of a carried sample in the window resolve (DESIGN.md section 4, "window resolve").

// Gaussian of the sample's distance to the output pixel centre: a small splat, sharper than a
// box of the pixel and smoother where few samples land (sigma ~0.35 px).
float spatialWeight(vec2 offset, float sigma) {
  return exp(-dot(offset, offset) / (2.0 * sigma * sigma));
}

// The weight by distance in frames is the same for every pixel: resolve/window_frame_weight
// computes it once per source frame.

// How well one source frame's samples agree with the resolved frame's own, as a weight for all
// of them: shading that changed over the window (a shadow that moved, a light that turned)
// makes a frame's samples differ from t's by more than their sampling noise explains, texture
// detail does not. `difference` is the luma of the source's weighted mean minus t's; its
// expected spread comes from the within-frame variance of the samples (texture and aliasing
// inside the pixel's footprint) and the weights (about the number of samples) of both means.
// 1 within `tolerance` standard deviations (plus a small floor, 1% and 0.002, for flat
// regions; larger floors let a moving shadow's frames through), falling linearly to 0 at twice
// that; tolerance 0 turns the test off.
float agreementWeight(float difference, float withinVariance, float sourceWeight,
                      float targetWeight, float targetLuma, float tolerance) {
  if (tolerance <= 0.0) return 1.0;
  float spread = sqrt(withinVariance * (1.0 / max(sourceWeight, 0.05) +
                                        1.0 / max(targetWeight, 0.05)));
  float limit = tolerance * spread + 0.002 + 0.01 * abs(targetLuma);
  return clamp(2.0 - abs(difference) / limit, 0.0, 1.0);
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
