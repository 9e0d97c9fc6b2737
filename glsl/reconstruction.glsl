// Reconstruction filters for unjittering the current frame.

// Weight of a sample at `offset` pixels from the point being reconstructed: a Gaussian fit to the
// Blackman-Harris window of width 3.3 pixels, exp(-2.29 d^2) (Karis, SIGGRAPH 2014).
float blackmanHarrisWeight(vec2 offset) {
  return exp(-2.29 * dot(offset, offset));
}
