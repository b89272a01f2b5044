// Preset "opacity-front" (seed 003 Fig. 5.7): the surface stays opaque (material 0) inside the front
// and turns see-through beyond it (material 1 at opacity uOpacity), so advancing the threshold
// reveals the inside of complex shapes without moving the camera.
#ifdef PRESET_OPACITY_FRONT

uniform float uOpacity;  // opacity beyond the front, 0..1

GeoSurface opacityFrontSurface(GeoFragment f) {
  float inside = geoCover(geoNoisyDistance(f.d.x, f.p), 0);
  return GeoSurface(mix(uColours[1], uColours[0], inside), mix(uOpacity, 1.0, inside), 0.0, vec3(0.0));
}

#endif
