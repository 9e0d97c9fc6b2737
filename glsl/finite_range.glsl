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

// Lanczos' negative lobes push a reconstruction past its samples; near the top of a compressive
// bracket (x / (x + 4) approaches 1) the inverse turns a small overshoot into a huge or infinite
// linear value, and beside a large negative sample a small positive weight does the same
// (issue 25, defect 4: a patch at -1000 gave +FLT_MAX neighbours). The overshoot may reach half
// the samples' own spread past them, and at most half of the distance to the working range's
// end: ordinary edges keep their ringing (uAntiRinging removes it), no edge runs off.
vec3 limitOvershoot(vec3 filtered, vec3 samplesMin, vec3 samplesMax) {
  vec3 allowed = 0.5 * (samplesMax - samplesMin);
  vec3 lo = samplesMin - min(allowed, max(0.5 * (samplesMin - vec3(uWorkingRange.x)), 0.0));
  vec3 hi = samplesMax + min(allowed, max(0.5 * (vec3(uWorkingRange.y) - samplesMax), 0.0));
  return clamp(filtered, lo, hi);
}

// The last guard before the inverse bracket and history: a working value stays within the
// working range's ends, or within the pixel's own samples where they lie beyond those ends.
// Whatever a stage did (a colour box's corner in YCoCg lies outside the samples' RGB range),
// the inverse then never meets a value it maps to infinity.
vec4 withinWorkingRange(vec4 working, vec3 samplesMin, vec3 samplesMax) {
  vec3 lo = min(vec3(uWorkingRange.x), samplesMin);
  vec3 hi = max(vec3(uWorkingRange.y), samplesMax);
  return vec4(clamp(working.rgb, lo, hi), working.a);
}

// An output colour the output's type can hold: NaN (from a user bracket) becomes 0, anything
// beyond the type's range its largest finite value.
vec4 finiteOutput(vec4 color) {
  return clamp(mix(color, vec4(0.0), isnan(color)), -uOutputLimit, uOutputLimit);
}

// A pass's sum (issue 21): NaN becomes 0, values stay within float's range. The pass's own
// type's range is applied when its channels are finished (resolve/pass_plan.cpp): a float data
// pass must keep values beyond half's 65504 when the colour is written as half.
vec4 finitePass(vec4 value) {
  return clamp(mix(value, vec4(0.0), isnan(value)), -3.4028235e38, 3.4028235e38);
}
