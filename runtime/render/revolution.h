// Revolution mapping (seed 001, "Revolution-bump mapping", Eq. 2-8 and 10-17): a surface of
// revolution drawn without polygons. The package's shape box is rasterised (its back faces, so a
// camera inside the box still sees it), and each fragment marches its ray through the box by over-
// relaxed sphere tracing (Keinert et al. 2014) over the signed shape map of the profile's (r, h)
// half-plane, exactly as formats/revolution.md prescribes. A hit is shaded with the normal from the
// map's gradient (Eq. 6), the projection's texture coordinates (cylindrical Eq. 10-13, spherical
// Eq. 14-17, or arc length along the profile), the base colour, bump mapping from the displacement
// map (Eq. 4-5) and Blinn-Phong; its depth is written so revolved objects intersect other geometry.
// Copies in one box (Eq. 9, Fig. 13: a grid with mirrored axes, or a ring) are found by walking their
// cells along the ray; with selfShadow a second march toward the light decides the direct light.
//
// libbake's reader (revolution/package/package_read.h) reads and checks the material extension;
// revolution.cpp uploads the maps and draws.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "render/gpu_mesh.h"
#include "render/renderer.h"
#include "revolution/package/package_read.h"

namespace bake::play {

// The package's data as libbake's reader gives them (libbake/revolution/package_read.h).
using ShapeEncoding = revolution::DistanceEncoding;
using RevolutionProjection = revolution::Projection;
using revolution::RevolutionParams;
using revolution::parseRevolution;
using revolution::EmbeddedImage;
using revolution::baseColourTextureOf;
using revolution::checkRevolutionPackage;

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
    Vec3 boxMin{0, 0, 0}, boxMax{0, 0, 0};  // the drawn box: the shape map's, or every copy's
    std::array<float, 4> baseColour{0.8f, 0.8f, 0.8f, 1.0f};
    unsigned shapeTexture = 0, displacementTexture = 0, arcLengthTexture = 0, colourTexture = 0;
  };
  void setUniforms(const Item& item, const FrameContext& frame) const;
  std::vector<Item> items_;
  std::vector<unsigned> textures_;  // every texture made, deleted with the renderer
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
