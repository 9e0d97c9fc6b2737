#version 410 core
// One triangle that covers the whole viewport, from gl_VertexID alone (no vertex buffer):
// vertices (-1,-1), (3,-1), (-1,3) in clip space. Fragment shaders work from gl_FragCoord.

void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // (0,0), (2,0), (0,2)
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
