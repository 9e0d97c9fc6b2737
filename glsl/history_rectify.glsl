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
