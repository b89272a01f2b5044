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
// libbake's reader (hatching/package/package_read.h) reads and checks the material extension.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "hatching/package/package_read.h"
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
// The package's data as libbake's reader gives them (libbake/hatching/package_read.h).
using hatching::HatchingOrientation;
using hatching::HatchingParams;
using hatching::parseHatching;
using hatching::checkHatchingPackage;

// ---------------------------------------------------------------------------------------------
// hatching.cpp

// How a tone between the TAM's layers is drawn: the seed's blend of the two nearest layers, or Webb
// et al. 2002's fine tone control by the package's threshold texture (a package without one draws
// the blend).
enum class HatchingTone { Blend, Threshold };

class HatchingRenderer : public TechniqueRenderer {
 public:
  explicit HatchingRenderer(HatchingTone tone = HatchingTone::Blend) : tone_(tone) {}
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
    unsigned thresholdTexture = 0;  // 0: the two-layer blend
    Mat4 world;
    HatchingParams params;  // tam levels released after upload
  };
  HatchingTone tone_;
  std::vector<Item> items_;
  std::vector<unsigned> buffers_, vaos_, textures_;  // every GL object made, deleted with the renderer
  std::size_t bytes_ = 0;
};

}  // namespace bake::play
