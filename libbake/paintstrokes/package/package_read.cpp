// Reads a BAKE_paintstrokes package (formats/paintstrokes.md) back into its arrays, treating it as
// untrusted: the version, every array's stride, count and bufferView size, every stroke's point range,
// point count and style index, the header's limits (kMax*), the shadow table's size against points x
// directions and every float a shader would use (finite; steps >= 0, radius steps > 0) are checked
// before anything uses them. Messages name the material, the array and the item.
#include <cmath>
#include <cstring>

#include "core/json_keys.h"
#include "paintstrokes/package/package.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;
namespace fmt = format::paintstrokes;
using Vec3f = std::array<float, 3>;

bool isIndex(const json& value) {
  return value.is_number_unsigned() || (value.is_number_integer() && value.get<std::int64_t>() >= 0);
}

bool finite(const float* values, int count) {
  for (int k = 0; k < count; ++k)
    if (!std::isfinite(values[k])) return false;
  return true;
}

struct PackageReader {
  const glb::Package& package;
  const std::string& where;
  const json& extension;

  Status fail(const std::string& element, const std::string& message) const {
    return invalidInput(std::string(fmt::kExtension) + ": " + message, {where, element});
  }

  Result<std::uint64_t> count(const char* key) const {
    const json& counts = jsonMember(extension, fmt::kCounts);
    const json& value = jsonMember(counts, key);
    if (!isIndex(value)) return fail(std::string("counts/") + key, "missing count");
    return value.get<std::uint64_t>();
  }

  // `items` records of `stride` bytes from the array's bufferView (the stride checked against the
  // extension's "strides" first).
  template <class T>
  Status array(const char* key, std::uint64_t items, std::vector<T>& out) const {
    const std::size_t stride = sizeof(T);
    const json& strides = jsonMember(extension, "strides");
    const json& declared = jsonMember(strides, key);
    if (!isIndex(declared) || declared.get<std::uint64_t>() != stride)
      return fail(std::string("strides/") + key, "expected stride " + std::to_string(stride));
    const json& view = jsonMember(jsonMember(extension, fmt::kBufferViews), key);
    if (!isIndex(view)) return fail(std::string("bufferViews/") + key, "missing bufferView");
    const std::uint64_t index = view.get<std::uint64_t>();
    if (index >= package.blobs.size())
      return fail(std::string("bufferViews/") + key, "bufferView " + std::to_string(index) + " does not exist");
    const std::vector<std::uint8_t>& bytes = package.blobs[index].bytes;
    if (items > bytes.size() / stride)
      return fail(std::string("bufferViews/") + key, "bufferView " + std::to_string(index) + " holds " +
                                                         std::to_string(bytes.size() / stride) + " items, fewer than the " +
                                                         std::to_string(items) + " counted");
    out.resize(items);
    if (items) std::memcpy(out.data(), bytes.data(), items * stride);
    return {};
  }
};

Result<std::array<float, 3>> finiteVec3(const PackageReader& reader, const json& value, const std::string& element) {
  if (!value.is_array() || value.size() != 3) return reader.fail(element, "expected 3 numbers");
  std::array<float, 3> out{};
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number() || !std::isfinite(value[k].get<double>())) return reader.fail(element, "expected finite numbers");
    out[k] = value[k].get<float>();
  }
  return out;
}

Status readHeader(const PackageReader& reader, PaintstrokePackage& out) {
  const json& e = reader.extension;
  const json& version = jsonMember(e, "version");
  if (!version.is_number_integer()) return reader.fail("version", "missing integer version");
  out.version = version.get<int>();
  if (out.version != fmt::kVersion)
    return unsupported(std::string(fmt::kExtension) + ": version " + std::to_string(out.version) + " (this reader knows " +
                           std::to_string(fmt::kVersion) + ")",
                       {reader.where, "version"});
  out.units = jsonStringOr(e, "units", "");
  const json& bounds = jsonMember(e, "bounds");
  BAKE_ASSIGN_OR_RETURN(out.boundsMin, finiteVec3(reader, jsonMember(bounds, "min"), "bounds/min"));
  BAKE_ASSIGN_OR_RETURN(out.boundsMax, finiteVec3(reader, jsonMember(bounds, "max"), "bounds/max"));
  const json& directions = jsonMember(e, "shadowDirections");
  if (!directions.is_array()) return reader.fail("shadowDirections", "expected a list of directions");
  if (directions.size() > fmt::kMaxShadowDirections)
    return reader.fail("shadowDirections", std::to_string(directions.size()) + " directions (at most " +
                                               std::to_string(fmt::kMaxShadowDirections) + ")");
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const std::string element = "shadowDirections/" + std::to_string(k);
    BAKE_ASSIGN_OR_RETURN(const Vec3f d, finiteVec3(reader, directions[k], element));
    const double length = std::sqrt(double(d[0]) * d[0] + double(d[1]) * d[1] + double(d[2]) * d[2]);
    if (std::abs(length - 1) > 1e-3) return reader.fail(element, "not a unit vector (length " + std::to_string(length) + ")");
    out.shadowDirections.push_back(d);
  }
  const json& names = jsonMember(e, "styleNames");
  if (!names.is_null()) {
    if (!names.is_array()) return reader.fail("styleNames", "expected a list of names");
    for (const json& n : names) out.styleNames.push_back(n.is_string() ? n.get<std::string>() : "");
  }
  return {};
}

Status readArrays(const PackageReader& reader, PaintstrokePackage& out) {
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t strokes, reader.count(fmt::kStrokes));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t points, reader.count(fmt::kPoints));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t styles, reader.count(fmt::kStyles));
  BAKE_ASSIGN_OR_RETURN(const std::uint64_t shadows, reader.count(fmt::kShadows));
  if (styles < 1 || styles > fmt::kMaxStyles)
    return reader.fail("counts/styles", std::to_string(styles) + " styles (1 to " + std::to_string(fmt::kMaxStyles) + " allowed)");
  if (points > UINT32_MAX) return reader.fail("counts/points", "more than 2^32-1 control points");
  if (shadows != points * out.shadowDirections.size())
    return reader.fail("counts/shadows", std::to_string(shadows) + " shadow values, expected points x directions = " +
                                             std::to_string(points * out.shadowDirections.size()));
  if (!out.styleNames.empty() && out.styleNames.size() != styles)
    return reader.fail("styleNames", std::to_string(out.styleNames.size()) + " names for " + std::to_string(styles) + " styles");
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kStrokes, strokes, out.strokes));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kPoints, points, out.points));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kStyles, styles, out.styles));
  BAKE_RETURN_IF_ERROR(reader.array(fmt::kShadows, shadows, out.shadows));
  return {};
}

Status checkStrokes(const PackageReader& reader, const PaintstrokePackage& p) {
  for (std::size_t s = 0; s < p.strokes.size(); ++s) {
    const fmt::Stroke& stroke = p.strokes[s];
    const std::string element = std::string(fmt::kStrokes) + "/" + std::to_string(s);
    const std::uint32_t first = stroke.info[0], count = stroke.info[1];
    if (count < 2 || count > fmt::kMaxPointsPerStroke)
      return reader.fail(element, std::to_string(count) + " control points (2 to " + std::to_string(fmt::kMaxPointsPerStroke) +
                                      " allowed)");
    if (std::uint64_t(first) + count > p.points.size())
      return reader.fail(element, "points " + std::to_string(first) + " to " + std::to_string(std::uint64_t(first) + count - 1) +
                                      " are beyond the " + std::to_string(p.points.size()) + " stored");
    if (stroke.info[2] >= p.styles.size())
      return reader.fail(element, "style " + std::to_string(stroke.info[2]) + " does not exist (" + std::to_string(p.styles.size()) +
                                      " styles)");
    if (stroke.info[3] != 0) return reader.fail(element, "unknown flags " + std::to_string(stroke.info[3]) + " (version 1 sets none)");
    if (!finite(stroke.origin, 4) || !finite(stroke.step, 4) || !finite(stroke.sphere, 4))
      return reader.fail(element, "origin, step or culling sphere is not finite");
    if (!(stroke.origin[3] > 0)) return reader.fail(element, "radius step is not > 0");
    if (stroke.step[0] < 0 || stroke.step[1] < 0 || stroke.step[2] < 0 || stroke.sphere[3] < 0)
      return reader.fail(element, "negative step or culling radius");
  }
  return {};
}

Status checkPointsAndStyles(const PackageReader& reader, const PaintstrokePackage& p) {
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const fmt::ControlPoint& q = p.points[i];
    const std::string element = std::string(fmt::kPoints) + "/" + std::to_string(i);
    if (q.radius == 0) return reader.fail(element, "radius 0 (a stored radius is at least one step)");
    if (q.reserved[0] || q.reserved[1] || q.reserved[2]) return reader.fail(element, "reserved bytes are not zero");
  }
  for (std::size_t k = 0; k < p.styles.size(); ++k) {
    const fmt::Style& s = p.styles[k];
    if (!finite(s.opacity, 4) || !finite(s.specular, 4) || !finite(s.shading, 4))
      return reader.fail(std::string(fmt::kStyles) + "/" + std::to_string(k), "a value is not finite");
  }
  return {};
}

}  // namespace

Result<PaintstrokePackage> decodePaintstrokeExtension(const glb::Package& package, const json& extension, const std::string& where) {
  if (!extension.is_object()) return invalidInput(std::string(fmt::kExtension) + " is not an object", {where, ""});
  const PackageReader reader{package, where, extension};
  PaintstrokePackage out;
  BAKE_RETURN_IF_ERROR(readHeader(reader, out));
  BAKE_RETURN_IF_ERROR(readArrays(reader, out));
  BAKE_RETURN_IF_ERROR(checkStrokes(reader, out));
  BAKE_RETURN_IF_ERROR(checkPointsAndStyles(reader, out));
  return out;
}

Result<PaintstrokePackage> decodePaintstrokePackage(const glb::Package& package, const std::string& name) {
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const json& extension = jsonMember(jsonMember(package.materials[m], "extensions"), fmt::kExtension);
    if (extension.is_null()) continue;
    const std::string materialName = jsonStringOr(package.materials[m], "name", "");
    return decodePaintstrokeExtension(package, extension,
                                      name + ": material " + std::to_string(m) + (materialName.empty() ? "" : " (" + materialName + ")"));
  }
  return invalidInput(std::string("no material carries ") + fmt::kExtension, {name, "materials"});
}

Result<PaintstrokePackage> readPaintstrokePackage(const std::filesystem::path& path) {
  BAKE_ASSIGN_OR_RETURN(const glb::Package package, glb::read(path));
  return decodePaintstrokePackage(package, path.string());
}

}  // namespace bake::paintstrokes
