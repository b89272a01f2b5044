// Reads a BAKE_grooves package (formats/grooves.md) back into its arrays, treating it as untrusted:
// the header's numbers, every array's size against its count and stride, the CSR prefix sums and
// every index an array holds are checked before anything uses them. Also measures the stored fp32
// geometry against the scene's double geometry (the bake's reported error).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/json_keys.h"
#include "grooves/package/package.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
namespace fmt = format::grooves;

// A JSON integer >= 0 (written unsigned, but a hand-edited file may hold a signed one).
bool isIndex(const json& value) {
  return value.is_number_unsigned() || (value.is_number_integer() && value.get<std::int64_t>() >= 0);
}

struct Reader {
  const glb::Package& package;
  const std::string& name;
  const json& extension;

  Status fail(const std::string& element, const std::string& message) const {
    return invalidInput(std::string(fmt::kExtension) + ": " + message, {name, element});
  }

  Result<double> positive(const json& value, const std::string& element) const {
    if (!value.is_number() || !(value.get<double>() > 0) || !std::isfinite(value.get<double>()))
      return fail(element, "expected a finite number > 0");
    return value.get<double>();
  }

  Result<std::uint64_t> count(const char* key) const {
    const json& counts = jsonMember(extension, fmt::kCounts);
    if (!counts.contains(key) || !isIndex(counts[key])) return fail(std::string("counts/") + key, "missing count");
    return counts[key].get<std::uint64_t>();
  }

  template <class T>
  Status array(const char* key, std::uint64_t items, std::size_t stride, std::vector<T>& out) const {
    const json& views = jsonMember(extension, fmt::kBufferViews);
    if (!views.contains(key) || !isIndex(views[key])) return fail(std::string("bufferViews/") + key, "missing bufferView");
    const std::uint64_t view = views[key].get<std::uint64_t>();
    if (view >= package.blobs.size()) return fail(std::string("bufferViews/") + key, "bufferView " + std::to_string(view) + " does not exist");
    const std::vector<std::uint8_t>& bytes = package.blobs[view].bytes;
    const std::uint64_t values = items * (stride / sizeof(T));
    if (items > bytes.size() / stride) return fail(std::string("bufferViews/") + key, "bufferView " + std::to_string(view) +
                                                                                       " holds fewer than " + std::to_string(items) + " items");
    out.resize(values);
    if (values) std::memcpy(out.data(), bytes.data(), values * sizeof(T));
    return {};
  }
};

Status readHeader(const Reader& reader, GroovePackageHeader& header) {
  const json& e = reader.extension;
  if (!e.contains("version") || !e["version"].is_number_integer()) return reader.fail("version", "missing integer version");
  header.version = e["version"].get<int>();
  if (header.version < fmt::kOldestReadableVersion || header.version > fmt::kVersion)
    return unsupported(std::string(fmt::kExtension) + ": version " + std::to_string(header.version) + " (this reader knows " +
                           std::to_string(fmt::kOldestReadableVersion) + " to " + std::to_string(fmt::kVersion) + ")",
                       {reader.name, "version"});
  header.units = jsonStringOr(e, "units", "");
  const json &domain = jsonMember(e, "domain"), &grid = jsonMember(e, "grid");
  if (!domain.is_array() || domain.size() != 2) return reader.fail("domain", "expected [U, V]");
  for (int k = 0; k < 2; ++k) {
    BAKE_ASSIGN_OR_RETURN(header.domain[k], reader.positive(domain[k], "domain"));
  }
  const std::string wrap = jsonStringOr(e, "wrap", "");
  if (wrap != fmt::kWrapNone && wrap != fmt::kWrapRepeat) return reader.fail("wrap", "expected \"none\" or \"repeat\"");
  header.wrapRepeat = wrap == fmt::kWrapRepeat;
  const json &cells = jsonMember(grid, "cells"), &size = jsonMember(grid, "cellSize"), &origin = jsonMember(grid, "origin");
  for (const json* pair : {&cells, &size, &origin}) {
    if (!pair->is_array() || pair->size() != 2) return reader.fail("grid", "expected cells, cellSize and origin pairs");
  }
  for (int k = 0; k < 2; ++k) {
    if (!isIndex(cells[k]) || cells[k].get<std::uint64_t>() < 1 || cells[k].get<std::uint64_t>() > UINT32_MAX)
      return reader.fail("grid/cells", "expected a count >= 1");
    header.cells[k] = cells[k].get<std::uint32_t>();
    BAKE_ASSIGN_OR_RETURN(header.cellSize[k], reader.positive(size[k], "grid/cellSize"));
    if (!origin[k].is_number() || !std::isfinite(origin[k].get<double>())) return reader.fail("grid/origin", "expected finite numbers");
    header.origin[k] = origin[k].get<double>();
  }
  for (auto [key, target] : {std::pair{"wmax", &header.wmax}, {"hmax", &header.hmax}, {"dmax", &header.dmax}}) {
    if (!e.contains(key) || !e[key].is_number() || !(e[key].get<double>() >= 0)) return reader.fail(key, "expected a number >= 0");
    *target = e[key].get<double>();
  }
  if (!e.contains("baseMaterial") || !isIndex(e["baseMaterial"])) return reader.fail("baseMaterial", "missing index");
  header.baseMaterial = e["baseMaterial"].get<std::uint32_t>();
  for (auto [key, names] : {std::pair{"profileNames", &header.profileNames}, {"materialNames", &header.materialNames}}) {
    const json& list = jsonMember(e, key);
    if (list.is_null()) continue;
    if (!list.is_array()) return reader.fail(key, "expected a list of names");
    for (const json& n : list) names->push_back(n.is_string() ? n.get<std::string>() : "");
  }
  if (header.version >= 2) {
    const json& far = jsonMember(e, fmt::kFar);
    const json &farCells = jsonMember(far, "cells"), &farSize = jsonMember(far, "cellSize");
    if (!farCells.is_array() || farCells.size() != 2 || !farSize.is_array() || farSize.size() != 2)
      return reader.fail("far", "expected cells and cellSize pairs");
    for (int k = 0; k < 2; ++k) {
      if (!isIndex(farCells[k]) || farCells[k].get<std::uint64_t>() < 1 || farCells[k].get<std::uint64_t>() > UINT32_MAX)
        return reader.fail("far/cells", "expected a count >= 1");
      header.farCells[k] = farCells[k].get<std::uint32_t>();
      BAKE_ASSIGN_OR_RETURN(header.farCellSize[k], reader.positive(farSize[k], "far/cellSize"));
    }
  }
  return {};
}

Status readArrays(const Reader& reader, bool cellLists, GroovePackage& out) {
  const std::uint64_t cells = std::uint64_t(out.header.cells[0]) * out.header.cells[1];
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t counted, reader.count("cells"));
  if (counted != cells) return reader.fail("counts/cells", "does not match grid/cells");
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t primitiveRefs, reader.count("primitiveRefs"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t recordRefs, reader.count("recordRefs"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t records, reader.count("records"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t primitives, reader.count("primitives"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t grooves, reader.count("grooves"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t profiles, reader.count("profiles"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t points, reader.count("profilePoints"));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t materials, reader.count("materials"));
  if (cellLists) {
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kCellStart, cells + 1, 4, out.cellStart));
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kPrimitiveRefs, primitiveRefs, 4, out.primitiveRefs));
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kRecordStart, cells + 1, 4, out.recordStart));
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kRecordRefs, recordRefs, 4, out.recordRefs));
  }
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kRecords, records, sizeof(fmt::Record), out.records));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kPrimitives, primitives, sizeof(fmt::Primitive), out.primitives));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kGrooves, grooves, sizeof(fmt::Groove), out.grooves));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kProfiles, profiles, sizeof(fmt::Profile), out.profiles));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kProfilePoints, points, fmt::kProfilePointSize, out.profilePoints));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kMaterials, materials, sizeof(fmt::Material), out.materials));
  if (out.header.version >= 2) {
    BAKE_ASSIGN_OR_RETURN(const std::uint64_t farClasses, reader.count(fmt::kFarClasses));
    BAKE_ASSIGN_OR_RETURN(const std::uint64_t farTable, reader.count(fmt::kFarTable));
    const std::uint64_t nodes = std::uint64_t(out.header.farCells[0] + 1ull) * (out.header.farCells[1] + 1ull);
    if (farClasses > 0 && farTable / farClasses != nodes)
      return reader.fail("counts/farTable", "expected (columns + 1) x (rows + 1) nodes per far class");
    if (farClasses == 0 && farTable != 0) return reader.fail("counts/farTable", "a table without classes");
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kFarClasses, farClasses, sizeof(fmt::FarClass), out.farClasses));
    BAKE_RETURN_IF_ERROR(reader.array(fmt::kFarTable, farTable, fmt::kFarTableEntrySize, out.farTable));
  }
  return {};
}

Status checkCsr(const Reader& reader, const char* key, const std::vector<std::uint32_t>& start,
                const std::vector<std::uint32_t>& refs, std::uint64_t targets) {
  if (start.front() != 0 || start.back() != refs.size()) return reader.fail(key, "the prefix sums do not span the references");
  for (std::size_t c = 0; c + 1 < start.size(); ++c)
    if (start[c] > start[c + 1]) return reader.fail(key, "cell " + std::to_string(c) + ": decreasing prefix sum");
  for (std::size_t k = 0; k < refs.size(); ++k)
    if (refs[k] >= targets) return reader.fail(key, "reference " + std::to_string(k) + " is out of range");
  return {};
}

bool finite(const float* values, int count) {
  for (int k = 0; k < count; ++k)
    if (!std::isfinite(values[k])) return false;
  return true;
}

Status checkIndices(const Reader& reader, bool cellLists, const GroovePackage& p) {
  if (cellLists) {
    BAKE_RETURN_IF_ERROR(checkCsr(reader, fmt::kCellStart, p.cellStart, p.primitiveRefs, p.primitives.size()));
    BAKE_RETURN_IF_ERROR(checkCsr(reader, fmt::kRecordStart, p.recordStart, p.recordRefs, p.records.size()));
  }
  for (std::size_t r = 0; r < p.records.size(); ++r) {
    const fmt::Record& record = p.records[r];
    if (record.info[0] > fmt::kRecordCorner || record.info[1] >= p.primitives.size() || record.info[2] >= p.primitives.size() ||
        !finite(record.point, 2) || !finite(record.box, 4))
      return reader.fail("records/" + std::to_string(r), "bad kind, primitive index or position");
  }
  for (std::size_t i = 0; i < p.primitives.size(); ++i) {
    const fmt::Primitive& prim = p.primitives[i];
    if (prim.groove >= p.grooves.size() || !finite(prim.ends, 4) || !finite(prim.arc, 4) || !finite(prim.measure, 4) ||
        !finite(prim.jointPoints, 4) || !finite(prim.jointNormals, 4))
      return reader.fail("primitives/" + std::to_string(i), "bad groove index or position");
  }
  for (std::size_t g = 0; g < p.grooves.size(); ++g) {
    const fmt::Groove& groove = p.grooves[g];
    if (groove.indices[0] >= p.profiles.size() || groove.indices[1] >= p.materials.size() ||
        std::uint64_t(groove.indices[2]) + groove.indices[3] > p.primitives.size() || groove.kind[1] > fmt::kPerturbationOffset)
      return reader.fail("grooves/" + std::to_string(g), "bad profile, material or primitive range");
  }
  for (std::size_t k = 0; k < p.profiles.size(); ++k)
    if (std::uint64_t(p.profiles[k].points[0]) + p.profiles[k].points[1] > p.profilePoints.size() / 2 || p.profiles[k].points[1] < 2)
      return reader.fail("profiles/" + std::to_string(k), "bad point range");
  if (p.header.baseMaterial >= p.materials.size()) return reader.fail("baseMaterial", "out of range");
  for (std::size_t c = 0; c < p.farClasses.size(); ++c) {
    const fmt::FarClass& farClass = p.farClasses[c];
    if (farClass.info[0] >= p.profiles.size() || farClass.info[1] >= p.materials.size() ||
        farClass.info[2] >= p.primitives.size() || !finite(farClass.direction, 3) || !(farClass.direction[2] >= 0))
      return reader.fail("farClasses/" + std::to_string(c), "bad profile, material, primitive or direction");
  }
  for (std::size_t k = 0; k < p.farTable.size(); ++k)
    if (!std::isfinite(p.farTable[k])) return reader.fail("farTable/" + std::to_string(k), "not finite");
  return {};
}

double distance(Vec2 a, Vec2 b) { return std::sqrt((a.u - b.u) * (a.u - b.u) + (a.v - b.v) * (a.v - b.v)); }

}  // namespace

Vec2 GroovePackage::position(const std::int32_t anchor[2], float u, float v) const {
  return {header.origin[0] + double(anchor[0]) * header.cellSize[0] + double(u),
          header.origin[1] + double(anchor[1]) * header.cellSize[1] + double(v)};
}

Result<GroovePackage> decodeGroovePackage(const glb::Package& package, const std::string& name, bool cellLists) {
  const json* extension = nullptr;
  for (const json& material : package.materials)
    if (material.contains("extensions") && material["extensions"].contains(fmt::kExtension))
      extension = &material["extensions"][fmt::kExtension];
  if (!extension || !extension->is_object())
    return invalidInput(std::string("no material carries ") + fmt::kExtension, {name, "materials"});
  return decodeGrooveExtension(package, *extension, name, cellLists);
}

Result<GroovePackage> decodeGrooveExtension(const glb::Package& package, const json& extension, const std::string& name,
                                            bool cellLists) {
  if (!extension.is_object()) return invalidInput(std::string(fmt::kExtension) + " is not an object", {name, "materials"});
  const Reader reader{package, name, extension};
  GroovePackage out;
  BAKE_RETURN_IF_ERROR(readHeader(reader, out.header));
  BAKE_RETURN_IF_ERROR(readArrays(reader, cellLists, out));
  BAKE_RETURN_IF_ERROR(checkIndices(reader, cellLists, out));
  return out;
}

Result<GroovePackage> readGroovePackage(const std::filesystem::path& path) {
  BAKE_ASSIGN_OR_RETURN(const glb::Package package, glb::read(path));
  return decodeGroovePackage(package, path.string());
}

StoredGeometryError storedGeometryError(const GrooveScene& scene, const GrooveGrid& grid, const GroovePackage& stored) {
  StoredGeometryError error;
  auto position = [&](Vec2 expected, const std::int32_t anchor[2], const float* local) {
    error.maxPosition = std::max(error.maxPosition, distance(expected, stored.position(anchor, local[0], local[1])));
  };
  const std::size_t primitives = std::min(scene.primitives.size(), stored.primitives.size());
  for (std::size_t i = 0; i < primitives; ++i) {
    const Primitive& p = scene.primitives[i];
    const format::grooves::Primitive& s = stored.primitives[i];
    const PrimitiveJoints joints = jointsOf(scene, i);
    position(p.a, s.anchor, s.ends);
    position(p.b, s.anchor, s.ends + 2);
    position(joints.start.point, s.anchor, s.jointPoints);
    position(joints.end.point, s.anchor, s.jointPoints + 2);
    error.maxNormal = std::max({error.maxNormal, distance(joints.start.normal, {s.jointNormals[0], s.jointNormals[1]}),
                                distance(joints.end.normal, {s.jointNormals[2], s.jointNormals[3]})});
    if (p.kind != Primitive::Kind::Arc) continue;
    const Vec2 centre = stored.position(s.anchor, s.arc[0], s.arc[1]);
    const double r = s.arc[2], a0 = s.arc[3], sweep = s.measure[0];
    const Vec2 start{centre.u + r * std::cos(a0), centre.v + r * std::sin(a0)};
    const Vec2 end{centre.u + r * std::cos(a0 + sweep), centre.v + r * std::sin(a0 + sweep)};
    error.maxArcCentre = std::max(error.maxArcCentre, distance(centre, p.centre));
    error.maxArcEndpoint = std::max({error.maxArcEndpoint, distance(start, p.a), distance(end, p.b)});
  }
  const std::size_t records = std::min(grid.records.size(), stored.records.size());
  for (std::size_t r = 0; r < records; ++r) {
    const format::grooves::Record& s = stored.records[r];
    position(grid.records[r].point, s.anchor, s.point);
    position(grid.records[r].lower, s.anchor, s.box);
    position(grid.records[r].upper, s.anchor, s.box + 2);
  }
  return error;
}

}  // namespace bake::grooves
