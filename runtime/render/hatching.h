// Real-time hatching (seed 004: Suarez, Belhadj and Boyer, "GPU real time hatching", WSCG 2013) of
// meshes whose material carries BAKE_hatching (formats/tam.md). At load time the triangle-adjacency
// index buffer is built (hatching_adjacency.cpp) and the package's tonal art map (a KTX2 2D array,
// one layer per tone, full mip chain) is uploaded as a trilinear, repeating GL_TEXTURE_2D_ARRAY.
// Each frame shaders/hatching/ draw the mesh as GL_TRIANGLES_ADJACENCY: the geometry stage builds
// the light-oriented frame and hatching coordinates of the triangle and of its three neighbours
// (§3.2 Algorithm 1, §4 transformations) and their blend factors (§3.3 Algorithm 2); the fragment
// stage picks the tone of each of the four triangles from its Lambert term, interpolates the two
// nearest TAM layers and blends the four colours (§3.4 Algorithm 3).
//
// hatching_params.cpp reads and checks the material extension (also for `bakeplay validate`).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/glb.h"
#include "io/ktx2.h"
#include "render/renderer.h"

namespace bake::play {

// ---------------------------------------------------------------------------------------------
// hatching_adjacency.cpp

struct TriangleAdjacency {
  // Six indices per triangle in GL_TRIANGLES_ADJACENCY order: v0, n01, v1, n12, v2, n20, where vi
  // are the triangle's own vertices and nij the vertex of the neighbour across edge (vi, vj) that is
  // not on that edge. A boundary edge repeats the triangle's own opposite vertex (n01 = v2, ...).
  std::vector<std::uint32_t> indices;
  std::size_t boundaryEdges = 0;     // edges with no neighbour
  std::size_t nonManifoldEdges = 0;  // edges shared by more than two triangles (first other one wins)
};

// Neighbours are found through shared edges of welded positions: vertices at bit-identical positions
// count as one (split normals or texture seams do not cut the adjacency). `indices` is a triangle
// list; every index must be below positions.size() / 3. Deterministic (depends only on the input).
TriangleAdjacency buildTriangleAdjacency(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices);

// ---------------------------------------------------------------------------------------------
// hatching_params.cpp

enum class HatchingOrientation { TowardLight, AcrossLight };

// One material's BAKE_hatching object, with its TAM decoded.
struct HatchingParams {
  int tamImage = 0;
  std::vector<float> tones;  // darkness per layer, strictly increasing in (0, 1)
  float tilesPerUnit = 1;
  float rotation = 0;                 // radians about N
  std::array<float, 2> translation{0, 0};  // tiles along T and B
  HatchingOrientation orientation = HatchingOrientation::TowardLight;
  std::array<float, 3> baseColor{1, 1, 1};
  ktx2::Texture tam;  // 2D array, layers == tones.size(), full mip chain, R8 or RGBA8
};

// Reads a material's BAKE_hatching object and checks it against the package: the fields and their
// ranges, the embedded KTX2 image decodes and is a 2D array of `tones` layers with a full mip chain in
// R8 or RGBA8. `where` names the material; messages name the field.
Result<HatchingParams> parseHatching(const nlohmann::json& extension, const glb::Package& package,
                                     const Location& where);

// Loader checks of BAKE_hatching for `bakeplay validate`: every material that carries it parses.
Status checkHatchingPackage(const glb::Package& package, const std::string& name);

// ---------------------------------------------------------------------------------------------
// hatching.cpp

class HatchingRenderer : public TechniqueRenderer {
 public:
  HatchingRenderer() = default;
  HatchingRenderer(const HatchingRenderer&) = delete;
  HatchingRenderer& operator=(const HatchingRenderer&) = delete;
  ~HatchingRenderer() override;

  Status prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                 gl::ShaderLibrary& shaders) override;
  void draw(const FrameContext& frame) override;
  std::size_t gpuBytes() const override;

 private:
  struct Item {
    unsigned vao = 0;
    int indexCount = 0;
    unsigned program = 0;
    unsigned tamTexture = 0;
    Mat4 world;
    HatchingParams params;  // tam levels released after upload
  };
  std::vector<Item> items_;
  std::vector<unsigned> buffers_, vaos_, textures_;  // every GL object made, deleted with the renderer
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
