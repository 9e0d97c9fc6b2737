#version 410 core
// The context self test's known pattern (gl/self_test.cpp computes the same on the CPU).
// Every value is exactly representable in float32, so the read-back must match bit for bit;
// x and y tell row order and orientation apart, the product term catches swapped pixels.

layout(location = 0) out vec4 outColor;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);  // pixel (i, j), centres at (i + 0.5, j + 0.5)
  outColor = vec4(float(p.x), float(p.y), float((p.x * p.y) % 7) * 0.125 - 0.5,
                  float(p.x + 2 * p.y) * 0.25);
}
