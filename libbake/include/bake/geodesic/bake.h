// geobake: per-vertex geodesic distance fields (seed 003, section 5.2.2). A bake reads a mesh, welds
// and cleans it into a Surface, resolves the sources of every field, solves each field with the chosen
// method, normalises to [0, 1] by the farthest reached point (the maximum is recorded), optionally
// measures the error against exact distances, and writes the mesh with `_GEODESIC_k` attributes and a
// BAKE_geodesic description (formats/geodesic.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "bake/geodesic/heat.h"

namespace bake::geodesic {

enum class Method { Exact, Heat, FastMarching };
enum class Normalization { PerField, Global, None };
enum class Encoding { Float, Unorm16 };

const char* methodName(Method method);  // "exact", "heat", "fmm"

// Where one source comes from, as the user gave it (kept for error messages and the package).
struct SourceSpec {
  enum class Kind { Vertex, Point, Node };
  Kind kind = Kind::Vertex;
  std::uint32_t vertex = 0;       // input vertex index
  std::array<double, 3> point{};  // input coordinates
  std::string node;               // named glTF node
  std::string origin;             // e.g. "--source-vertex 12" or "sources.json: fields[1].sources[0]"
};

// One field: the distance to the nearest of its sources.
struct FieldSpec {
  std::string name;
  std::vector<SourceSpec> sources;
};

struct Settings {
  std::string input;
  std::string output;
  // Sources on the command line: one field each, or one combined field with `combine`.
  std::vector<std::int64_t> sourceVertices;
  std::vector<std::array<double, 3>> sourcePoints;
  std::vector<std::string> sourceNodes;
  unsigned autoSources = 0;  // farthest-point sampling
  bool combine = false;
  std::string sourcesFile;  // JSON: {"fields": [{"name": ..., "sources": [{"vertex": i} | {"point": [x,y,z]} | {"node": "N"}]}]}
  // Bake only these fields of the sources file (by name, kept in file order); empty: all. A scene
  // whose materials read fewer fields leaves the others out (formats/scene.md).
  std::vector<std::string> onlyFields;

  Method method = Method::Exact;
  Normalization normalization = Normalization::PerField;
  Encoding encoding = Encoding::Float;
  unsigned verifySamples = 0;  // 0: no verification
  double weldTolerance = 0.0;
  HeatOptions heat;
  bool draco = false;
  std::string geotexture;  // adds a material choosing this GeoTexture preset (formats/geodesic-material.md)
  CommonOptions common;
};

// The option checks (usage errors), also made by run().
Status check(const Settings& settings);

// The files a bake of these settings reads and writes (for --print-inputs, the output plan and the
// cache).
Result<RunFiles> inputs(const Settings& settings);

Status run(const Settings& settings, Diagnostics& diagnostics);

}  // namespace bake::geodesic
