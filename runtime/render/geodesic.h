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
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/io/image.h"
#include "geodesic/package/package_read.h"
#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

// The package's data as libbake's reader gives them (libbake/geodesic/package_read.h).
using geodesic::GeoPreset;
using geodesic::geoPresetName;
using geodesic::geoPresetFromName;
using geodesic::geoPresetNames;
using geodesic::Rgb;
using geodesic::GeoTextureParams;
using geodesic::geoPresetDefaults;
using geodesic::parseGeoTexture;
using geodesic::geodesicFieldsOf;
using geodesic::checkGeodesicPackage;

// Gives every primitive that carries geodesic fields a GeoTexture: with `preset` set, that preset
// replaces the one its material names (other parameters are kept); a primitive whose material has no
// BAKE_* technique gets a copy of it with BAKE_geodesic added (the preset, or "isolines"), so a bare
// geobake package shows its fields. Primitives of other techniques are left alone.
Status attachGeoTextures(Scene& scene, const std::string& preset);



class GeodesicRenderer : public TechniqueRenderer {
 public:
  // `environment`: an equirectangular image (linear RGB) the wave preset reflects (seed 003 C.6.4);
  // none: the wave is lit like the other presets.
  explicit GeodesicRenderer(std::shared_ptr<const Image> environment = nullptr) : environment_(std::move(environment)) {}
  GeodesicRenderer(const GeodesicRenderer&) = delete;
  GeodesicRenderer& operator=(const GeodesicRenderer&) = delete;
  ~GeodesicRenderer() override;
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
  std::shared_ptr<const Image> environment_;
  unsigned environmentTexture_ = 0;
};

}  // namespace bake::play
