// The reader of BAKE_revolution materials (formats/revolution.md), beside its writer
// (bake_package.cpp): what the runtime uploads, `bakeplay validate` and bakeinfo check. It trusts
// nothing: every bufferView must exist and hold exactly width * height texels of its encoding,
// numbers must be finite and in range, proxy bands well formed and no more than the shader's array
// holds; each error names the material and the field at fault.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake/revolution/projection.h"
#include "bake/revolution/shape_map.h"

namespace bake::revolution {

// One material's BAKE_revolution object, checked against the package it lives in.
struct RevolutionParams {
  struct ShapeMap {
    int bufferView = 0;
    int width = 0, height = 0;
    float texelSize = 0;  // object units per texel, in r and h
    float hMin = 0;
    DistanceEncoding encoding = DistanceEncoding::Unorm16;
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
  Projection projection = Projection::Cylindrical;
  std::array<float, 2> repeat{1, 1};
  float sphereCentreH = 0;
  std::optional<int> arcLengthBufferView;
  // Copies of the object in one box (seed 001 Eq. 9; formats/revolution.md, "Replicas").
  struct Replicas {
    enum class Layout { One, Grid, Ring } layout = Layout::One;
    std::array<int, 3> count{1, 1, 1};  // grid
    std::array<float, 3> spacing{0, 0, 0};
    std::array<bool, 3> mirror{false, false, false};
    int ringCount = 1;
    float ringRadius = 0;
    int total() const;
    // Most cells one straight ray passes through (the march's outer loop): a line crosses each
    // grid plane, or each ring wedge's boundary half-plane, at most once.
    int mostCellsCrossed() const;
  } replicas;
  bool selfShadow = false;
  // The object-space box that holds every copy (the one object's shape box without replicas).
  std::array<float, 3> boxMin() const;
  std::array<float, 3> boxMax() const;
};

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

// Loader checks of BAKE_revolution for `bakeplay validate` and bakeinfo: every material that carries it parses
// (version, bufferViews and their sizes, encodings, texel size, margin, march, bands, projection),
// and its base colour texture, when it has one, names an embedded image.
Status checkRevolutionPackage(const glb::Package& package, const std::string& name);

}  // namespace bake::revolution
