// Colour-space helpers for the resolve.

// RGB -> YCoCg (luma, orange and green chroma). Orthogonal-ish and exactly invertible; boxes in
// YCoCg hug natural colour distributions tighter than RGB boxes (Karis, "High Quality Temporal
// Supersampling", SIGGRAPH 2014).
vec3 rgbToYCoCg(vec3 rgb) {
  return vec3(0.25 * rgb.r + 0.5 * rgb.g + 0.25 * rgb.b,
              0.5 * rgb.r - 0.5 * rgb.b,
              -0.25 * rgb.r + 0.5 * rgb.g - 0.25 * rgb.b);
}

// YCoCg -> RGB, the exact inverse of rgbToYCoCg.
vec3 yCoCgToRgb(vec3 ycocg) {
  float base = ycocg.x - ycocg.z;
  return vec3(base + ycocg.y, ycocg.x + ycocg.z, base - ycocg.y);
}

// Rec. 709 luma of working-space colour.
float luma(vec3 rgb) {
  return dot(rgb, vec3(0.2126, 0.7152, 0.0722));
}
