// The BAKE_paintstrokes package (formats/paintstrokes.md): the strokes quantised per stroke box and
// packed in std430 records for direct GPU upload, the baked self-shadowing table, and a LINES mesh of
// the centrelines as the fallback every glTF viewer shows. Writer (package.cpp) and reader
// (package_read.cpp, also the runtime's loader).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake/paintstrokes/model.h"
#include "bake_formats/paintstrokes.h"

namespace bake::paintstrokes {

// The decoded arrays, exactly as stored, and the extension's header fields.
struct PaintstrokePackage {
  int version = 0;
  std::string units;
  std::vector<format::paintstrokes::Stroke> strokes;
  std::vector<format::paintstrokes::ControlPoint> points;
  std::vector<format::paintstrokes::Style> styles;
  std::vector<std::uint8_t> shadows;                 // points x shadowDirections.size()
  std::vector<std::array<float, 3>> shadowDirections;  // unit, towards the light
  std::vector<std::string> styleNames;
  std::array<float, 3> boundsMin{0, 0, 0}, boundsMax{0, 0, 0};

  // A stored point dequantised (position x, y, z and radius), for tools, tests and the tube reference.
  std::array<double, 4> positionRadius(std::size_t stroke, std::size_t pointInStroke) const;
};

// Largest packing errors of a stroke set against its stored form, in input units (reported by
// strokebake; the bounds of formats/paintstrokes.md hold them).
struct QuantizationError {
  double position = 0;  // largest |stored - input| over every axis and point
  double radius = 0;
  double unorm = 0;     // colour, opacity, reflectance
  // The radius bound that holds for every stored point: radiusStep / 2 of each stroke, or a whole
  // radiusStep for a stroke with a radius below half a step (stored as one step, as 0 is not allowed).
  double radiusBound = 0;
};

// Packs `strokes` (already validated) with their baked shadow table (`shadows`: points x directions,
// values in [0, 1]; empty when `directions` is). `extraMesh`, when given, is added as a second mesh
// with a standard material (the mesh strokes were grown on).
Result<glb::Package> buildPaintstrokePackage(const StrokeSet& strokes, const std::vector<Vec3d>& directions,
                                             const std::vector<double>& shadows, const glb::Mesh* extraMesh,
                                             QuantizationError* error = nullptr);

// Reads one material's extension object and its arrays, checking strides, counts, every stroke's
// point range, style index and limits (the header's kMax*); `where` names the material in messages.
Result<PaintstrokePackage> decodePaintstrokeExtension(const glb::Package& package, const nlohmann::json& extension,
                                                      const std::string& where);
// The first material carrying the extension.
Result<PaintstrokePackage> decodePaintstrokePackage(const glb::Package& package, const std::string& name);
Result<PaintstrokePackage> readPaintstrokePackage(const std::filesystem::path& path);

// package_check.cpp
// Reads one material's BAKE_paintstrokes object with the decoder (which checks version,
// strides, counts, point ranges, style indices and limits) and adds the checks of what shaders read: finite
// quantisation boxes and culling spheres, positive radius steps, style values in range, unit shadow
// directions. `where` names the material.
Result<PaintstrokePackage> readPaintstrokes(const glb::Package& package, const nlohmann::json& extension,
                                              const Location& where);

// Loader checks of BAKE_paintstrokes for `bakeplay validate`: every material that carries it reads,
// and every primitive drawn with it is a LINES primitive (glTF mode 1) with one POSITION per control
// point.
Status checkPaintstrokePackage(const glb::Package& package, const std::string& name);

}  // namespace bake::paintstrokes
