// Shared by the two halves of the GeoTextures runtime: the BAKE_geodesic material parsing and loader
// checks (geodesic_params.cpp, no GL, also linked into the GLB fuzz target) and the renderer
// (geodesic.cpp). Internal to runtime/render.
#pragma once

#include <string>
#include <vector>

#include "render/geodesic.h"

namespace bake::play::geodesic_detail {

inline constexpr int kMaxSlots = 4;  // COMBINE_MIN merges up to four fields; separate slots are two

struct PresetInfo {
  GeoPreset preset;
  const char* name;
  const char* define;
};

const PresetInfo& infoOf(GeoPreset preset);
std::string attributeName(int field);

// The field attributes a material reads (its "fields" names resolved against the primitive).
Result<std::vector<int>> resolveFields(const GeoTextureParams& params, const glb::Primitive& primitive,
                                       const Location& where);
// Whether the package stores distances in model units (normalisation "none"), and the factor that
// maps an attribute's values to [0, 1].
bool storesModelUnits(const glb::Package& package);
float normalisingFactor(const glb::Package& package, const std::string& attribute);
Status checkFieldAttribute(const glb::Attribute& a, const Location& where, bool modelUnits = false);

}  // namespace bake::play::geodesic_detail
