// Sampling the previous frame's output at a sub-pixel position (raster pixels, y down).

// Bilinear: cheap, but each reprojection blurs a little and the blur accumulates under motion.
vec4 sampleHistoryBilinear(sampler2D history, vec2 position) {
  return texture(history, position / vec2(textureSize(history, 0)));
}

// Catmull-Rom bicubic from 5 bilinear taps: the 4x4 footprint's weights are folded so that the
// middle two texels of each axis share one bilinear tap, and the four corner taps (smallest
// weights) are dropped (Jimenez, "Filmic SMAA", SIGGRAPH 2016). Keeps history sharp under motion;
// its negative lobes can overshoot, so the result is clamped to the taps' range. The texture
// must use linear filtering.
vec4 sampleHistoryCatmullRom(sampler2D history, vec2 position) {
  vec2 size = vec2(textureSize(history, 0));
  vec2 centre = floor(position - 0.5) + 0.5;  // texel centre at or before the position
  vec2 f = position - centre;                 // in [0, 1)
  // Catmull-Rom weights of the texels at centre - 1, centre, centre + 1, centre + 2.
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 at0 = (centre - 1.0) / size;
  vec2 at12 = (centre + w2 / w12) / size;
  vec2 at3 = (centre + 2.0) / size;
  vec4 top = texture(history, vec2(at12.x, at0.y));
  vec4 left = texture(history, vec2(at0.x, at12.y));
  vec4 middle = texture(history, at12);
  vec4 right = texture(history, vec2(at3.x, at12.y));
  vec4 bottom = texture(history, vec2(at12.x, at3.y));
  vec4 sum = top * (w12.x * w0.y) + left * (w0.x * w12.y) + middle * (w12.x * w12.y) +
             right * (w3.x * w12.y) + bottom * (w12.x * w3.y);
  float weight = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
  // Within the taps' own range: an overshoot resampled every frame would build on itself where
  // rectification is relaxed (the thin-feature hold), and beside a large negative texel a
  // small weight is a huge positive value (issue 25, defect 4).
  vec4 lo = min(min(min(top, left), min(middle, right)), bottom);
  vec4 hi = max(max(max(top, left), max(middle, right)), bottom);
  return clamp(sum / weight, lo, hi);
}
