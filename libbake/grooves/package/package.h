// The BAKE_grooves package (formats/grooves.md): a glTF binary with a preview plane over the domain
// whose material carries the groove grid (seed 000 §4.1-§4.2) in bufferViews laid out for direct GPU
// upload: the CSR cell lists, the special-case records, the primitives in cell-local fp32, the
// grooves, profiles and materials. Writer (package.cpp) and reader (package_read.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake_formats/grooves.h"
#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"

namespace bake::grooves {

struct GroovePackageHeader {
  int version = 0;
  std::string units;
  double domain[2] = {0, 0};
  bool wrapRepeat = false;
  std::uint32_t cells[2] = {0, 0};
  double cellSize[2] = {0, 0};
  double origin[2] = {0, 0};
  double wmax = 0, hmax = 0, dmax = 0;
  std::uint32_t baseMaterial = 0;
  std::vector<std::string> profileNames, materialNames;
  // The far level's grid (version 2; zero cells in a version 1 package, which has none).
  std::uint32_t farCells[2] = {0, 0};
  double farCellSize[2] = {0, 0};
};

// The decoded arrays, exactly as stored.
struct GroovePackage {
  GroovePackageHeader header;
  std::vector<std::uint32_t> cellStart, primitiveRefs, recordStart, recordRefs;
  std::vector<format::grooves::Record> records;
  std::vector<format::grooves::Primitive> primitives;
  std::vector<format::grooves::Groove> grooves;
  std::vector<format::grooves::Profile> profiles;
  std::vector<float> profilePoints;  // b, h pairs
  std::vector<format::grooves::Material> materials;
  std::vector<format::grooves::FarClass> farClasses;  // empty in a version 1 package
  std::vector<double> farTable;

  // A stored cell-local point back in domain coordinates (double).
  Vec2 position(const std::int32_t anchor[2], float u, float v) const;
};

// The package of a scene and its grid (in memory; glb::encode writes it). The bytes do not depend on
// `threads` (0 = all hardware threads).
Result<glb::Package> buildGroovePackage(const GrooveScene& scene, const GrooveGrid& grid, unsigned threads = 0);

// Reads the extension and its arrays, checking sizes, counts and every index they hold. Without
// `cellLists`, the four CSR arrays are left empty (and unchecked): enough to measure the geometry.
Result<GroovePackage> decodeGroovePackage(const glb::Package& package, const std::string& name, bool cellLists = true);
// The same for one material's extension object, for packages with several groove materials (an
// assembled scene).
Result<GroovePackage> decodeGrooveExtension(const glb::Package& package, const nlohmann::json& extension,
                                            const std::string& name, bool cellLists = true);
Result<GroovePackage> readGroovePackage(const std::filesystem::path& path);

// Loader checks of BAKE_grooves (package_check.cpp; `bakeplay validate`, bakeinfo): every material
// that carries the extension decodes (version, header, array sizes against counts and strides, CSR
// prefix sums, every index), and the mesh drawn with it has TEXCOORD_0.
Status checkGroovesPackage(const glb::Package& package, const std::string& name);

// Largest distance between the stored fp32 geometry, rebuilt in double, and the scene's geometry:
// positions (end points, centres, joint points, record points and boxes) and the arcs' end points
// rebuilt from centre, radius and angles.
struct StoredGeometryError {
  double maxPosition = 0;     // end points, joint points, record points and boxes (texture units)
  double maxArcCentre = 0;    // arc centres: far from their cell for nearly straight arcs
  double maxArcEndpoint = 0;  // arc end points rebuilt from centre, radius and angles
  double maxNormal = 0;       // joint normals, unitless
};
StoredGeometryError storedGeometryError(const GrooveScene& scene, const GrooveGrid& grid, const GroovePackage& stored);

}  // namespace bake::grooves
