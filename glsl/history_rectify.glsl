// Rectifying history against the current frame's neighbourhood.

// Moves `history` toward `target` (which must lie inside [boxMin, boxMax]) until it enters the
// box: the point where the segment history -> target crosses the box surface. Unlike a per-axis
// clamp it keeps the history's hue direction (Pedersen, "Temporal Reprojection Anti-Aliasing in
// INSIDE", GDC 2016).
vec3 clipToBox(vec3 history, vec3 target, vec3 boxMin, vec3 boxMax) {
  vec3 toHistory = history - target;
  vec3 halfExtent = max(0.5 * (boxMax - boxMin), vec3(1e-7));
  vec3 centre = 0.5 * (boxMax + boxMin);
  // Largest scale along the segment (from target) that stays inside the box on every axis.
  vec3 room = halfExtent - sign(toHistory) * (target - centre);
  vec3 reach = abs(toHistory) / max(room, vec3(1e-7));
  float overshoot = max(reach.x, max(reach.y, reach.z));
  return overshoot > 1.0 ? target + toHistory / overshoot : history;
}

// Variance box: mean +- gamma standard deviations of the neighbourhood, intersected with its
// min/max box. Tighter than min/max when one outlier widens the box (Salvi, "An Excursion in
// Temporal Supersampling", GDC 2016).
void varianceBox(vec3 sum, vec3 sumOfSquares, float count, float gamma, inout vec3 boxMin,
                 inout vec3 boxMax) {
  vec3 mean = sum / count;
  vec3 sigma = sqrt(max(sumOfSquares / count - mean * mean, vec3(0.0)));
  boxMin = max(boxMin, mean - gamma * sigma);
  boxMax = min(boxMax, mean + gamma * sigma);
}
