// GeoTextures (seed 003, sections 5.2-5.3 and Appendix C): procedural textures driven by the
// per-vertex geodesic distance fields of a BAKE_geodesic package. A material chooses a preset with
// `extensions.BAKE_geodesic = {"version": 1, "texture": "<preset>", ...}` (formats/geodesic-material.md)
// and the renderer draws it with shaders/geodesic/: fronts between materials where the normalised
// distance crosses a threshold (smoothstep over a width), nested fronts for several materials and
// fields, noise on a front, a threshold that advances with time, and for the wave preset a
// displacement refined by adaptive tessellation (level from the on-screen edge length).
//
// Only the field attributes a material reads are uploaded, and each material compiles one variant
// (preset, field count and encoding, normals, tessellation).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

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

// Gives every primitive that carries geodesic fields a GeoTexture: with `preset` set, that preset
// replaces the one its material names (other parameters are kept); a primitive whose material has no
// BAKE_* technique gets a copy of it with BAKE_geodesic added (the preset, or "isolines"), so a bare
// geobake package shows its fields. Primitives of other techniques are left alone.
Status attachGeoTextures(Scene& scene, const std::string& preset);

// Loader checks of BAKE_geodesic (for `bakeplay validate`): field attributes are SCALAR float or
// normalized unsigned short, hold values in [0, 1] or the unreachable flag, match the root
// extension's field list and encoding; materials name a known preset with well-formed parameters and
// read fields their primitives carry.
Status checkGeodesicPackage(const glb::Package& package, const std::string& name);

class GeodesicRenderer : public TechniqueRenderer {
 public:
  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                 gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;

 private:
  struct Item {
    GpuPrimitive gpu;
    unsigned program = 0;
    Mat4 world;
    GeoTextureParams params;
    Vec3 objectCentre{0, 0, 0};
    float objectRadius = 1;
    float worldScale = 1;                         // largest axis scale of `world`
    std::array<float, 4> fieldScale{1, 1, 1, 1};  // stored value -> normalised distance, per slot
    bool tessellated = false;
    bool translucent = false;
  };
  void setUniforms(const Item& item, const FrameContext& frame) const;
  void drawItem(const Item& item, int pass) const;
  std::vector<Item> items_;
};

}  // namespace bake::play
