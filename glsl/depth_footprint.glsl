// The 3x3 depths around a texel from four gathers instead of nine fetches: on llvmpipe a gather
// costs about what one fetch does (docs/PERFORMANCE.md).

// d[3 * (dy + 1) + dx + 1] = depth at texel p + (dx, dy). The texture must clamp to its edge:
// border texels then repeat exactly as clamping the coordinates would.
void depthFootprint(sampler2D depth, ivec2 p, out float d[9]) {
  vec2 size = vec2(textureSize(depth, 0));
  // Each gather reads the 2x2 texels around a texel corner: the corner between p - 1 and p,
  // then the ones one texel right, down, and both.
  vec2 corner = vec2(p) / size;
  vec4 aboveLeft = textureGather(depth, corner);
  vec4 aboveRight = textureGather(depth, corner + vec2(1.0, 0.0) / size);
  vec4 belowLeft = textureGather(depth, corner + vec2(0.0, 1.0) / size);
  vec4 belowRight = textureGather(depth, corner + vec2(1.0, 1.0) / size);
  // A gather returns its texels (x0, y1), (x1, y1), (x1, y0), (x0, y0), y1 being the next row.
  d[0] = aboveLeft.w;
  d[1] = aboveLeft.z;
  d[2] = aboveRight.z;
  d[3] = aboveLeft.x;
  d[4] = aboveLeft.y;
  d[5] = aboveRight.y;
  d[6] = belowLeft.x;
  d[7] = belowLeft.y;
  d[8] = belowRight.y;
}
