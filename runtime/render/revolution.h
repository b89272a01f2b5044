// Revolution mapping (seed 001, "Revolution-bump mapping", Eq. 2-8 and 10-17): a surface of
// revolution drawn without polygons. The package's shape box is rasterised (its back faces, so a
// camera inside the box still sees it), and each fragment marches its ray through the box by over-
// relaxed sphere tracing (Keinert et al. 2014) over the signed shape map of the profile's (r, h)
// half-plane, exactly as formats/revolution.md prescribes. A hit is shaded with the normal from the
// map's gradient (Eq. 6), the projection's texture coordinates (cylindrical Eq. 10-13, spherical
// Eq. 14-17, or arc length along the profile), the base colour, bump mapping from the displacement
// map (Eq. 4-5) and Blinn-Phong; its depth is written so revolved objects intersect other geometry.
//
// revolution_params.cpp reads and checks the material extension (also for `bakeplay validate`);
// revolution.cpp uploads the maps and draws.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/glb.h"
#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

enum class ShapeEncoding { Float, Unorm16, Sqrt8 };
enum class RevolutionProjection { Cylindrical, Spherical, ArcLength };

// One material's BAKE_revolution object, checked against the package it lives in.
struct RevolutionParams {
  struct ShapeMap {
    int bufferView = 0;
    int width = 0, height = 0;
    float texelSize = 0;  // object units per texel, in r and h
    float hMin = 0;
    ShapeEncoding encoding = ShapeEncoding::Unorm16;
    float distanceScale = 1;  // S of the integer encodings
    float rMax() const { return float(width) * texelSize; }
    float hMax() const { return hMin + float(height) * texelSize; }
  } shapeMap;
  float safetyMargin = 0;
  int iterations = 35;
  float overRelaxation = 1.6f;
  float hitEpsilon = 0;
  std::vector<std::array<float, 3>> proxyBands;  // [hMin, hMax, rMax]
  struct Displacement {
    int bufferView = 0;
    int width = 0, height = 0;
    float derivativeScale = 1;
    float heightScale = 0;
  };
  std::optional<Displacement> displacement;
  RevolutionProjection projection = RevolutionProjection::Cylindrical;
  std::array<float, 2> repeat{1, 1};
  float sphereCentreH = 0;
  std::optional<int> arcLengthBufferView;
};

const char* shapeEncodingName(ShapeEncoding encoding);  // the format's names: "float", ...
const char* revolutionProjectionName(RevolutionProjection projection);

// Reads a material's BAKE_revolution object and checks it against the package (bufferViews exist and
// hold width * height texels of the encoding). `where` names the material; messages name the field.
Result<RevolutionParams> parseRevolution(const nlohmann::json& extension, const glb::Package& package,
                                         const Location& where);

// The embedded image behind a material's pbrMetallicRoughness.baseColorTexture (textures[i].source ->
// images[j] -> bufferView): nothing when the material has no such texture, an error when the chain
// names something missing or is not embedded (external URIs are not part of a package).
struct EmbeddedImage {
  std::size_t image = 0;
  std::size_t bufferView = 0;
  std::string mimeType;
};
Result<std::optional<EmbeddedImage>> baseColourTextureOf(const nlohmann::json& material, const glb::Package& package,
                                                         const Location& where);

// Loader checks of BAKE_revolution for `bakeplay validate`: every material that carries it parses
// (version, bufferViews and their sizes, encodings, texel size, margin, march, bands, projection),
// and its base colour texture, when it has one, names an embedded image.
Status checkRevolutionPackage(const glb::Package& package, const std::string& name);

class RevolutionRenderer : public TechniqueRenderer {
 public:
  RevolutionRenderer() = default;
  RevolutionRenderer(const RevolutionRenderer&) = delete;
  RevolutionRenderer& operator=(const RevolutionRenderer&) = delete;
  ~RevolutionRenderer() override;

  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                 gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;

 private:
  struct Item {
    GpuPrimitive box;  // the drawn shape box, outward-wound
    unsigned program = 0;
    Mat4 world;
    RevolutionParams params;
    Vec3 boxMin{0, 0, 0}, boxMax{0, 0, 0};  // where the march runs: mesh bounds within the map's box
    std::array<float, 4> baseColour{0.8f, 0.8f, 0.8f, 1.0f};
    unsigned shapeTexture = 0, displacementTexture = 0, arcLengthTexture = 0, colourTexture = 0;
  };
  void setUniforms(const Item& item, const FrameContext& frame) const;
  std::vector<Item> items_;
  std::vector<unsigned> textures_;  // every texture made, deleted with the renderer
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
