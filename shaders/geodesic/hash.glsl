// Integer hashes for the procedural noises (no textures): lattice points -> well-mixed 32-bit
// values -> floats in [0, 1). Integer arithmetic keeps the result identical on every GPU and on
// llvmpipe, unlike the sin()-based hashes whose precision varies between drivers.
// The mixing step is a permuted congruential step (O'Neill 2014, "PCG") followed by an xorshift.
#ifndef BAKE_GEODESIC_HASH_GLSL
#define BAKE_GEODESIC_HASH_GLSL

uint geoMix(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Distinct odd multipliers per axis, so (x, y, z) and its permutations hash differently.
uint geoHash(ivec2 p) { return geoMix(uint(p.x) * 0x8da6b343u ^ geoMix(uint(p.y) * 0xd8163841u)); }
uint geoHash(ivec3 p) {
  return geoMix(uint(p.x) * 0x8da6b343u ^ geoMix(uint(p.y) * 0xd8163841u ^ geoMix(uint(p.z) * 0xcb1ab31fu)));
}

float geoUnit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }  // 24 bits -> [0, 1)

vec2 geoHash2(ivec2 p) {
  uint h = geoHash(p);
  return vec2(geoUnit(h), geoUnit(geoMix(h)));
}
vec3 geoHash3(ivec3 p) {
  uint h = geoHash(p);
  uint g = geoMix(h);
  return vec3(geoUnit(h), geoUnit(g), geoUnit(geoMix(g)));
}

#endif
