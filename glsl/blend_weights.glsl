// Weights of the exponential blend between history and the current frame (luma():
// color_space.glsl).

// Anti-flicker: when history and current luma agree, trust history more; when they differ, the
// difference is real change and the current frame gets more weight. Returns the current frame's
// weight between alphaMin (agreeing) and alphaMax (disagreeing) (Lottes, "TSSAA", 2011; Karis 2014).
float antiFlickerAlpha(float historyLuma, float currentLuma, float alphaMin, float alphaMax) {
  float difference = abs(currentLuma - historyLuma) / max(max(currentLuma, historyLuma), 0.2);
  float agreement = 1.0 - difference;
  return mix(alphaMax, alphaMin, agreement * agreement);
}

// Blends with each side weighted by 1 / (1 + luma), so that one very bright sample cannot
// dominate the average (Karis 2014: HDR fireflies).
vec4 lumaWeightedBlend(vec4 history, vec4 current, float alpha) {
  float historyWeight = (1.0 - alpha) / (1.0 + max(luma(history.rgb), 0.0));
  float currentWeight = alpha / (1.0 + max(luma(current.rgb), 0.0));
  return (history * historyWeight + current * currentWeight) / (historyWeight + currentWeight);
}
