#extension GL_ARB_shading_language_packing : require
// One sample of the window resolve's ring, packed so that a single fetch brings what the
// static path needs: on llvmpipe each texel fetch costs more than the arithmetic around it.
// A ring texel is a uvec4: the working-space colour in x, y, z and the signed planar depth as
// a float in w (+ static, - moving, window_classify.frag; +inf: nothing hit). The motion (px,
// y down, to the previous frame) is kept apart, two halves in a uint of the motion ring, at
// the same layer: only the moving samples' chains and the classification read it.
//
// Colour precision: halves were not enough. A bracket that compresses highlights towards 1
// (taa_reinhard: x / (x + 4)) leaves 2^-11 of half between 0.9995 and 1, so 5000 came back
// as 4092 and anything above 16380 as infinity. Each of R, G, B keeps 16 bits of mantissa
// (the top 25 bits of its float) and stores 1 - w instead of w from 0.5 up, where the
// difference is the finer number: a relative error of at most 4e-6 in w, and about the same
// in the linear value whatever the bracket's slope near 1. Alpha (unbracketed) is a half whose
// bits fill the three words' low bits; a half input's alpha is kept exactly.

struct RingSample {
  vec4 colour;
  float depth;  // signed
};

// Bit 6 of a colour word: the word holds 1 - w; bits 0-5: its share of alpha's half.
const uint kComplementBit = 0x40u;
const uint kValueBits = 0xFFFFFF80u;

uint packRingChannel(float w, uint alphaShare) {
  bool complement = w >= 0.5;
  uint bits = floatBitsToUint(complement ? 1.0 - w : w);
  // Rounds the 23-bit mantissa to 16 bits (a carry into the exponent is the right rounding).
  bits = (bits + 0x40u) & kValueBits;
  return bits | (complement ? kComplementBit : 0u) | alphaShare;
}

float unpackRingChannel(uint word) {
  float v = uintBitsToFloat(word & kValueBits);
  return (word & kComplementBit) != 0u ? 1.0 - v : v;
}

uvec4 packRingSample(vec4 colour, float signedDepth) {
  uint alpha = packHalf2x16(vec2(colour.a, 0.0));
  return uvec4(packRingChannel(colour.r, alpha >> 10),
               packRingChannel(colour.g, (alpha >> 4) & 0x3Fu),
               packRingChannel(colour.b, alpha & 0xFu), floatBitsToUint(signedDepth));
}

RingSample unpackRingSample(uvec4 texel) {
  RingSample s;
  uint alpha = ((texel.x & 0x3Fu) << 10) | ((texel.y & 0x3Fu) << 4) | (texel.z & 0xFu);
  s.colour = vec4(unpackRingChannel(texel.x), unpackRingChannel(texel.y),
                  unpackRingChannel(texel.z), unpackHalf2x16(alpha).x);
  s.depth = uintBitsToFloat(texel.w);
  return s;
}

float ringDepth(uvec4 texel) { return uintBitsToFloat(texel.w); }
// The same texel with another signed depth (classification).
uvec4 withRingDepth(uvec4 texel, float signedDepth) {
  return uvec4(texel.xyz, floatBitsToUint(signedDepth));
}

uint packRingMotion(vec2 motion) { return packHalf2x16(motion); }
vec2 unpackRingMotion(uint bits) { return unpackHalf2x16(bits); }
