// The stages of tambake's run (bake.cpp), in order, with the state they hand on.
//   bake.cpp          settings checks, the style with its overrides, the mesh, construction, quality
//                     measurement and its report entries, staging of the outputs
//   bake_texture.cpp  the TAM and the threshold texture as KTX2 (formats/tam.md)
//   bake_package.cpp  the glTF package applying the TAM to a mesh (BAKE_hatching, formats/tam.md)
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/report.h"
#include "bake/hatching/bake.h"
#include "bake/hatching/style.h"
#include "bake/io/glb.h"
#include "bake/io/mesh.h"
#include "hatching/bake/build.h"
#include "hatching/bake/quality.h"
#include "io/ktx2.h"

namespace bake::hatching {

struct BakeState {
  Style style;                        // with the command line's overrides applied
  std::optional<TriangleMesh> mesh;   // --apply-to
  std::size_t normalsComputed = 0;    // vertices whose normal was computed (the mesh had none)
  Tam tam;
  Quality quality;
  // Mean darkness of each stroke level's layers as stored (8-bit): storedDarkness[level][tone].
  std::vector<std::vector<double>> storedDarkness;
  std::vector<std::uint8_t> tamBytes;        // the encoded TAM (.ktx2)
  std::vector<std::uint8_t> thresholdBytes;  // the encoded threshold texture, when asked for
};

// The `BAKE_tam` metadata JSON of a TAM (formats/tam.md); `threshold` adds "threshold": true.
nlohmann::json tamMetadata(const Tam& tam, const Style& style, bool threshold);
// The TAM as a KTX2 2D array: one layer per tone, the full mip chain, R8 (black ink) or RGBA8
// (coloured ink: RGB the composited colour, A the brightness).
Result<ktx2::Texture> tamTexture(const Tam& tam, const Style& style);
// Mean darkness (1 - brightness) of every layer of one level of an encoded TAM, from its R channel
// (R8) or its A channel (RGBA8): what the runtime will sample, quantisation included.
std::vector<double> storedDarkness(const ktx2::Texture& texture, std::uint32_t level);
// The threshold texture (build.h thresholdTexture) as a KTX2 2D R8 texture with the same mip chain.
Result<ktx2::Texture> thresholdKtx(const Tam& tam, const Style& style);

// Removes the `count` finest levels of a texture (the base becomes level `count`) and records it in
// the TAM metadata ("skippedLevels"; "strokeLevels" counts the stroke levels that remain).
Status dropFinestLevels(ktx2::Texture& texture, int count);

// Smooth vertex normals (area-weighted face normals) for a mesh without normals; existing normals
// are normalised. Vertices no triangle gives a direction get +Z. Returns how many were computed.
std::size_t ensureUnitNormals(TriangleMesh& mesh);
// The package: the mesh, one node, one material with BAKE_hatching and the embedded KTX2 images.
Result<glb::Package> buildPackage(const Settings& settings, const BakeState& state);

}  // namespace bake::hatching
