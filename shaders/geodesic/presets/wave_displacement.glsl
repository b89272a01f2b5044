// Preset "wave-displacement" (seed 003 Fig. 5.10-5.12, Appendix C.6): a wave packet travels out from
// the source with the front. With the tessellation stages (DISPLACE) the surface is refined and moved
// along its normal, so the silhouette waves; without them the same height only bumps the normal.
// Either way the shading normal is the bump of the wave height over the undisplaced surface, which is
// the normal of the displaced surface to first order. Material 0 is the surface colour, material 1
// tints the crests.
#ifdef PRESET_WAVE

GeoSurface waveSurface(GeoFragment f) {
  float h = waveHeightAt(f.d);
  float crest = clamp(h / max(uWave.x, 1e-6), 0.0, 1.0);
  return GeoSurface(mix(uColours[0], uColours[1], crest), 1.0, h, vec3(0.0));
}

#endif
