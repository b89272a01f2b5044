// A full-screen triangle for presenting an offscreen frame (no vertex buffer: positions from the id).
out vec2 vUv;

void main() {
  const vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  vUv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
