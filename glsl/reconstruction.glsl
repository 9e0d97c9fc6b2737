// Reconstruction filters for unjittering the current frame: the weight of a sample that lies
// `offset` pixels from the point being reconstructed.

// A Gaussian fit to the Blackman-Harris window of width 3.3 pixels, exp(-2.29 d^2) (Karis, "High
// Quality Temporal Supersampling", SIGGRAPH 2014). Soft, never negative.
float blackmanHarrisWeight(vec2 offset) {
  return exp(-2.29 * dot(offset, offset));
}

// Separable Lanczos-2 windowed sinc: sharper than Blackman-Harris, with small negative lobes.
float lanczos2(float x) {
  x = abs(x);
  if (x < 1e-5) return 1.0;
  if (x >= 2.0) return 0.0;
  float px = 3.14159265 * x;
  return 2.0 * sin(px) * sin(0.5 * px) / (px * px);
}
float lanczos2Weight(vec2 offset) {
  return lanczos2(offset.x) * lanczos2(offset.y);
}
