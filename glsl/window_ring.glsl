#extension GL_ARB_shading_language_packing : require
// One sample of the window resolve's ring, packed so that a single fetch brings all of it: on
// llvmpipe each texel fetch costs more than the arithmetic around it. A ring texel is a uvec4:
// colour (working space) as four halves in x and y, the signed planar depth as a float in z
// (+ static, - moving, window_classify.frag; +inf: nothing hit), motion (px, y down, to the
// previous frame) as two halves in w.

struct RingSample {
  vec4 colour;
  float depth;  // signed
  vec2 motion;
};

uvec4 packRingSample(vec4 colour, float signedDepth, vec2 motion) {
  return uvec4(packHalf2x16(colour.rg), packHalf2x16(colour.ba), floatBitsToUint(signedDepth),
               packHalf2x16(motion));
}

RingSample unpackRingSample(uvec4 texel) {
  RingSample s;
  s.colour = vec4(unpackHalf2x16(texel.x), unpackHalf2x16(texel.y));
  s.depth = uintBitsToFloat(texel.z);
  s.motion = unpackHalf2x16(texel.w);
  return s;
}

float ringDepth(uvec4 texel) { return uintBitsToFloat(texel.z); }
vec2 ringMotion(uvec4 texel) { return unpackHalf2x16(texel.w); }
