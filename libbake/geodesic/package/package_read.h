// The reader of BAKE_geodesic materials and fields (formats/geodesic-material.md, seed 003 sections
// 5.2.3-5.3), beside the package's writer (bake_package.cpp): GeoTexture presets and their defaults,
// parsing of a material's extension (every key optional, wrong types are errors), which field
// attributes a material reads, and the package checks the runtime, `bakeplay validate` and bakeinfo
// run.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"

namespace bake::geodesic {

enum class GeoPreset {
  Isolines,
  SandWater,
  MossGranite,
  PaintMetalRust,
  WaterLava,
  OpacityFront,
  WaveDisplacement
};

const char* geoPresetName(GeoPreset preset);  // "sand-water", ...
std::optional<GeoPreset> geoPresetFromName(const std::string& name);
std::vector<std::string> geoPresetNames();

using Rgb = std::array<float, 3>;

// The parameters of one GeoTexture material: the preset's defaults, then what the material sets.
// Distances, thresholds and widths are in normalised field units (0 at the sources, 1 at maxDistance).
struct GeoTextureParams {
  GeoPreset preset = GeoPreset::Isolines;
  std::vector<int> fields{0};  // field indices k of the attributes _GEODESIC_k
  bool fieldsGiven = false;    // false: the preset's default list, trimmed to the fields present
  bool combineMin = false;     // merge the fields into one min-distance field (else slots 0 and 1)
  std::array<float, 4> thresholds{0.3f, 0.3f, 0.3f, 0.3f};  // fronts, from the source outward
  std::array<float, 4> widths{0.02f, 0.02f, 0.02f, 0.02f};  // transition width of each front
  float speed = 0;                                          // threshold advance per second
  float noiseFrequency = 8;                                 // front noise: cycles per object radius
  float noiseAmplitude = 0;                                 // front noise: normalised distance
  float patternScale = 1;        // multiplies the frequency of the materials' own patterns
  float bumpScale = 1;           // multiplies the presets' bump heights
  std::array<Rgb, 4> colours{};  // linear RGB of the materials, from the source outward
  Rgb unreachableColour{1.0f, 0.0f, 1.0f};
  float isolineSpacing = 0.05f, isolineWidth = 1.5f;  // normalised distance; pixels
  Rgb isolineColour{0.02f, 0.02f, 0.02f};
  float opacity = 0.2f;  // opacity-front: opacity beyond the front
  struct Wave {
    float amplitude = 0.04f;   // object radii
    float wavelength = 0.05f;  // normalised distance
    float reach = 0.3f;        // length of the packet behind the front
    bool displace = true;      // tessellate and displace (else bump only)
    float pixelsPerEdge = 6;   // target on-screen length of a tessellated edge
    float maxLevel = 16;       // largest tessellation level
  } wave;
};

GeoTextureParams geoPresetDefaults(GeoPreset preset);
// Reads a material's BAKE_geodesic object; `where` names it in errors.
Result<GeoTextureParams> parseGeoTexture(const nlohmann::json& extension, const Location& where);

// The fields a primitive carries (k of every _GEODESIC_k attribute), sorted.
std::vector<int> geodesicFieldsOf(const glb::Primitive& primitive);

// Loader checks of BAKE_geodesic (for `bakeplay validate`): field attributes are SCALAR float or
// normalized unsigned short, hold values in [0, 1] or the unreachable flag, match the root
// extension's field list and encoding; materials name a known preset with well-formed parameters and
// read fields their primitives carry.
Status checkGeodesicPackage(const glb::Package& package, const std::string& name);

namespace material_detail {

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

}  // namespace material_detail

}  // namespace bake::geodesic
