// Presents a linear-light frame on a window with the sRGB encoding that PNG output uses, so the
// window and `bakeplay render` show the same picture.
in vec2 vUv;
layout(location = 0) out vec4 fragColor;
layout(binding = 0) uniform sampler2D uFrame;

vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
  fragColor = vec4(encodeSrgb(texture(uFrame, vUv).rgb), 1.0);
}
