// The reader of BAKE_hatching materials (formats/tam.md), beside their writer (bake_package.cpp):
// what the runtime uploads, `bakeplay validate` and bakeinfo check. Packages are untrusted: every
// field is checked as formats/hatching.schema.json states it, and a failure names the file, the
// material and the field.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "io/ktx2.h"

namespace bake::hatching {

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
  std::optional<ktx2::Texture> threshold;  // 2D R8, the TAM's size and mip chain (Webb et al. 2002)
};

// Reads a material's BAKE_hatching object and checks it against the package: the fields and their
// ranges, the embedded KTX2 image decodes and is a 2D array of `tones` layers with a full mip chain in
// R8 or RGBA8. `where` names the material; messages name the field.
Result<HatchingParams> parseHatching(const nlohmann::json& extension, const glb::Package& package,
                                     const Location& where);

// Loader checks of BAKE_hatching for `bakeplay validate`: every material that carries it parses.
Status checkHatchingPackage(const glb::Package& package, const std::string& name);

}  // namespace bake::hatching
