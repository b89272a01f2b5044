// Standard shading for everything without a bake extension: Blinn-Phong with the material's base
// colour (glTF pbrMetallicRoughness.baseColorFactor), one directional light and an ambient term.
// Variants: HAS_NORMALS when the primitive has normals (else flat normals from derivatives); UNLIT
// for points and lines (the base colour).
#pragma once

#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

// glTF pbrMetallicRoughness.baseColorFactor of a material, or glTF's default when it has none (any part
// of the material may have any type: it is read leniently).
std::array<float, 4> baseColourOf(const nlohmann::json& material);

class StandardRenderer : public TechniqueRenderer {
 public:
  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances, gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;

 private:
  struct Item {
    GpuPrimitive gpu;
    unsigned program = 0;
    Mat4 world;
    std::array<float, 4> baseColour{0.8f, 0.8f, 0.8f, 1.0f};
  };
  std::vector<Item> items_;
};

}  // namespace bake::play
