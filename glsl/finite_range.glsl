// Keeping every value the resolve produces finite (issue 17), whatever the input and bracket.

// The bracket's working-space image of half float's range, [toWorking(-65504),
// toWorking(65504)] (color/ocio_bracket.h): where its inverse still gives finite values.
uniform vec2 uWorkingRange;
// The largest finite value of the output's sample type: 65504 for half, float's maximum else.
uniform float uOutputLimit;

// Working values stay within +-1e18 (input beyond about 1e17 saturates) and NaN from a user
// bracket becomes 0: the colour box's sums of squares (variance clip) then stay finite, and so
// does history, which would otherwise carry a NaN or Inf for the rest of the shot.
const float kWorkingLimit = 1e18;
vec4 finiteWorking(vec4 color) {
  return clamp(mix(color, vec4(0.0), isnan(color)), -kWorkingLimit, kWorkingLimit);
}

// Lanczos' negative lobes push a reconstruction past its samples. Near the top of a compressive
// bracket (x / (x + 4) approaches 1) the inverse turns a small overshoot into a huge or infinite
// linear value. The overshoot may cover at most half of the distance from the samples' range to
// the working range's ends: ordinary edges keep their ringing (see uAntiRinging to remove it),
// an edge beside a highlight cannot run off to infinity.
vec3 limitOvershoot(vec3 filtered, vec3 samplesMin, vec3 samplesMax) {
  vec3 lo = min(samplesMin, mix(samplesMin, vec3(uWorkingRange.x), 0.5));
  vec3 hi = max(samplesMax, mix(samplesMax, vec3(uWorkingRange.y), 0.5));
  return clamp(filtered, lo, hi);
}

// An output colour the output's type can hold: NaN (from a user bracket) becomes 0, anything
// beyond the type's range its largest finite value.
vec4 finiteOutput(vec4 color) {
  return clamp(mix(color, vec4(0.0), isnan(color)), -uOutputLimit, uOutputLimit);
}
