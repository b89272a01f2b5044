// Revolution mapping, vertex stage (seed 001, "Shape box"): places the shape box. The fragment stage
// rebuilds each pixel's ray itself from gl_FragCoord, so nothing but the position is passed on.

layout(location = 0) in vec3 aPosition;

uniform mat4 uObjectToClip;  // projection * view * model

void main() {
  gl_Position = uObjectToClip * vec4(aPosition, 1.0);
}
