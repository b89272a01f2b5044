// Standard shading for everything without a bake extension: Blinn-Phong with the material's base
// colour (glTF pbrMetallicRoughness.baseColorFactor), one directional light and an ambient term.
// Variants: HAS_NORMALS when the primitive has normals (else flat normals from derivatives).
#pragma once

#include "render/gpu_mesh.h"
#include "render/renderer.h"

namespace bake::play {

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
