// Writing the package (formats/geodesic.md): the input mesh as read (positions, normals, texture
// coordinates, triangles; a mesh far from the origin relative to its centre, which the node's
// translation holds), one SCALAR attribute `_GEODESIC_k` per field, normalised to [0, 1] by the
// farthest reached vertex (seed 003, 5.2.2) or by the farthest over all fields, and the BAKE_geodesic
// description with the divisor of every field so the distances can be recovered in model units.
#include <algorithm>
#include <cmath>

#include "bake_formats/geodesic.h"
#include "geodesic/package/bake_package.h"

namespace bake::geodesic {
namespace {

namespace fmt = format::geodesic;
using nlohmann::json;

json describeSource(const SourceSpec& spec, const SurfacePoint& point, double snapDistance) {
  json source;
  switch (spec.kind) {
    case SourceSpec::Kind::Vertex: source["vertex"] = spec.vertex; return source;
    case SourceSpec::Kind::Point: source["point"] = spec.point; break;
    case SourceSpec::Kind::Node: source["node"] = spec.node; break;
  }
  source["face"] = point.face;
  source["barycentric"] = point.barycentric;
  source["snapDistance"] = snapDistance;
  return source;
}

const char* normalizationName(Normalization normalization) {
  switch (normalization) {
    case Normalization::PerField: return fmt::kNormalizationPerField;
    case Normalization::Global: return fmt::kNormalizationGlobal;
    case Normalization::None: return fmt::kNormalizationNone;
  }
  return "?";
}

// Per input vertex, the field divided by `scale` (or the unreachable flag).
glb::Attribute encodeField(const std::string& name, const std::vector<double>& distance,
                           const std::vector<std::uint32_t>& vertexMap, double scale, Encoding encoding) {
  const double inverse = scale > 0.0 ? 1.0 / scale : 0.0;
  if (encoding == Encoding::Float) {
    std::vector<float> values(vertexMap.size());
    for (std::size_t v = 0; v < vertexMap.size(); ++v) {
      const double d = distance[vertexMap[v]];
      values[v] = d == kUnreachable ? fmt::kUnreachableFloat : float(d * inverse);
    }
    return glb::Attribute::fromFloats(name, 1, values);
  }
  glb::Attribute attribute;
  attribute.name = name;
  attribute.componentType = glb::ComponentType::U16;
  attribute.components = 1;
  attribute.normalized = true;
  attribute.bytes.resize(vertexMap.size() * 2);
  for (std::size_t v = 0; v < vertexMap.size(); ++v) {
    const double d = distance[vertexMap[v]];
    const std::uint16_t code =
        d == kUnreachable ? fmt::kUnreachableUnorm16
                          : std::uint16_t(std::lround(std::clamp(d * inverse, 0.0, 1.0) * fmt::kMaxReachableUnorm16));
    attribute.bytes[2 * v] = std::uint8_t(code & 0xff);
    attribute.bytes[2 * v + 1] = std::uint8_t(code >> 8);
  }
  return attribute;
}

glb::Primitive meshPrimitive(const TriangleMesh& mesh) {
  glb::Primitive primitive;
  std::vector<float> flat;
  flat.reserve(mesh.vertexCount() * 3);
  for (const Vec3f& p : mesh.positions) flat.insert(flat.end(), p.begin(), p.end());
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, flat));
  if (!mesh.normals.empty()) {
    flat.clear();
    for (const Vec3f& n : mesh.normals) flat.insert(flat.end(), n.begin(), n.end());
    primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, flat));
  }
  if (!mesh.texcoords.empty()) {
    flat.clear();
    for (const Vec2f& t : mesh.texcoords) flat.insert(flat.end(), t.begin(), t.end());
    primitive.attributes.push_back(glb::Attribute::fromFloats("TEXCOORD_0", 2, flat));
  }
  // Other attributes of a glTF input pass through; fields of an earlier bake are replaced.
  for (const glb::Attribute& extra : mesh.extraAttributes)
    if (extra.name.rfind(fmt::kAttributePrefix, 0) != 0) primitive.attributes.push_back(extra);
  primitive.indices.reserve(mesh.triangleCount() * 3);
  for (const Triangle& t : mesh.triangles) primitive.indices.insert(primitive.indices.end(), t.begin(), t.end());
  return primitive;
}

}  // namespace

glb::Package buildPackage(const TriangleMesh& mesh, const SurfaceBuild& build,
                          const std::vector<ResolvedField>& fields,
                          const std::vector<std::vector<double>>& distances,
                          const std::vector<FieldError>& errors, const Settings& settings) {
  glb::Primitive primitive = meshPrimitive(mesh);
  double globalLargest = 0.0;
  for (const auto& d : distances) globalLargest = std::max(globalLargest, largestReached(d));

  json described = json::array();
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const std::string attribute = fmt::kAttributePrefix + std::to_string(f);
    const double largest = largestReached(distances[f]);
    const double scale = settings.normalization == Normalization::PerField ? largest
                         : settings.normalization == Normalization::Global ? globalLargest
                                                                           : 1.0;
    primitive.attributes.push_back(encodeField(attribute, distances[f], build.vertexMap, scale, settings.encoding));
    std::size_t unreachable = 0;
    for (std::uint32_t v : build.vertexMap) unreachable += distances[f][v] == kUnreachable ? 1 : 0;
    json field = {{fmt::kFieldAttribute, attribute},      {fmt::kFieldName, fields[f].name},
                  {fmt::kFieldMaxDistance, largest},      {"scale", scale},
                  {"unreachableVertices", unreachable}, {"sources", json::array()}};
    for (std::size_t s = 0; s < fields[f].specs.size(); ++s)
      field["sources"].push_back(describeSource(fields[f].specs[s], fields[f].points[s], fields[f].snapDistances[s]));
    if (f < errors.size() && errors[f].samples > 0)
      field["error"] = {{"reference", "exact"},
                        {"samples", errors[f].samples},
                        {"meanRelative", errors[f].meanRelative},
                        {"maxRelative", errors[f].maxRelative}};
    described.push_back(std::move(field));
  }

  glb::Package package;
  if (!settings.geotexture.empty()) {
    package.materials.push_back({{"name", "geotexture"},
                                 {"extensions", {{fmt::kExtension, {{"version", fmt::kVersion}, {"texture", settings.geotexture}}}}}});
    primitive.material = 0;
  }
  package.meshes.push_back({"geodesic", {std::move(primitive)}});
  glb::Node node;
  node.name = "geodesic";
  node.mesh = 0;
  node.translation = mesh.origin;  // a far-off mesh: float positions relative to it (io/mesh_place.h)
  package.nodes.push_back(node);
  const bool asFloat = settings.encoding == Encoding::Float;
  package.extensions[fmt::kExtension] = {
      {"version", fmt::kVersion},
      {"method", methodName(settings.method)},
      {fmt::kKeyEncoding, asFloat ? fmt::kEncodingFloat : fmt::kEncodingUnorm16},
      {fmt::kKeyNormalization, normalizationName(settings.normalization)},
      {"unreachableValue", asFloat ? json(fmt::kUnreachableFloat) : json(fmt::kUnreachableUnorm16)},
      {fmt::kKeyFields, std::move(described)}};
  return package;
}

}  // namespace bake::geodesic
