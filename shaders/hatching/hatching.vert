// Hatching (seed 004), vertex stage: object-space positions pass through; the geometry stage needs
// the whole adjacency primitive in object space to build the hatching frames (§3.2).

layout(location = 0) in vec3 aPosition;

out vec3 vObjectPosition;

void main() {
  vObjectPosition = aPosition;
  gl_Position = vec4(aPosition, 1.0);
}
