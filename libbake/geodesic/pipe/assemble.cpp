// Assembly rules for geodesic objects (formats/geodesic.md, formats/geodesic-material.md). The fields
// live as _GEODESIC_k attributes described by the root BAKE_geodesic object; the material reads them
// by index. Unread fields are removed and the rest renumbered _GEODESIC_0.. in package order, the
// root's field list with them (bakeplay checks that every listed attribute exists and that a
// material's indices name attributes of its primitives). The scene's geotexture becomes the material,
// its field names resolved to the renumbered indices. With `global` normalization every field is kept:
// the fields share one scale, so the baked values depend on all of them.
#include <bake_formats/geodesic.h>

#include <algorithm>

#include "geodesic/pipe/pipe.h"
#include "pipe/assemble_parts.h"

namespace bake::geodesic::assembly {

using namespace pipe::detail;

namespace {

using nlohmann::json;
namespace fmt = format::geodesic;

std::string attributeName(std::size_t field) { return fmt::kAttributePrefix + std::to_string(field); }

bool isFieldAttribute(const std::string& name) { return name.rfind(fmt::kAttributePrefix, 0) == 0; }

std::string fieldName(const json& field) { return field.is_object() ? field.value(fmt::kFieldName, "") : ""; }

// The field list entries the material reads, by position in the package's list.
Result<std::vector<std::size_t>> fieldsReadIn(const json& fields, const std::vector<std::string>& names,
                                              const ObjectInput& input) {
  std::vector<std::size_t> read;
  for (const std::string& name : names) {
    const auto found = std::find_if(fields.begin(), fields.end(), [&](const json& f) { return fieldName(f) == name; });
    if (found == fields.end())
      return input.error("the material '" + input.material.name + "' reads field '" + name +
                         "', which the package does not hold");
    read.push_back(std::size_t(found - fields.begin()));
  }
  return read;
}

// Keeps the listed fields (in package order) as _GEODESIC_0.., on every primitive and in the root list.
void keepOnly(glb::Package& package, const std::vector<bool>& keep, const ObjectInput& input) {
  json& fields = package.extensions[fmt::kExtension][fmt::kKeyFields];
  json kept = json::array();
  std::vector<std::string> renamed(fields.size());  // old attribute name -> new, "" when dropped
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const std::string attribute = fields[k].value(fmt::kFieldAttribute, "");
    if (!keep[k]) {
      input.drop("field '" + fieldName(fields[k]) + "' (" + attribute + ")");
      continue;
    }
    json field = fields[k];
    field[fmt::kFieldAttribute] = attributeName(kept.size());
    renamed[k] = attributeName(kept.size());
    kept.push_back(std::move(field));
  }
  for (glb::Mesh& mesh : package.meshes) {
    for (glb::Primitive& primitive : mesh.primitives) {
      std::vector<glb::Attribute> attributes;
      for (glb::Attribute& attribute : primitive.attributes) {
        if (!isFieldAttribute(attribute.name)) {
          attributes.push_back(std::move(attribute));
          continue;
        }
        for (std::size_t k = 0; k < fields.size(); ++k) {
          if (fields[k].value(fmt::kFieldAttribute, "") != attribute.name || renamed[k].empty()) continue;
          attribute.name = renamed[k];
          attributes.push_back(std::move(attribute));
          break;
        }
      }
      primitive.attributes = std::move(attributes);
    }
  }
  fields = std::move(kept);
}

// The scene's geotexture with field names replaced by the indices of the (renumbered) field list.
json geotextureMaterial(const json& fields, const ObjectInput& input) {
  json extension = input.material.geotexture;
  if (!extension.contains("version")) extension["version"] = fmt::kVersion;
  json indices = json::array();
  for (const std::string& name : input.scene.fieldsRead(input.object)) {
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (fieldName(fields[k]) != name) continue;
      const std::string attribute = fields[k].value(fmt::kFieldAttribute, "");
      indices.push_back(std::stoi(attribute.substr(std::string(fmt::kAttributePrefix).size())));
      break;
    }
  }
  extension[fmt::kKeyFields] = std::move(indices);
  return {{"name", input.material.name}, {"extensions", {{fmt::kExtension, std::move(extension)}}}};
}

Status checkFieldList(const json& fields, const ObjectInput& input) {
  if (!fields.is_array()) return input.error(std::string(fmt::kExtension) + " fields is not a list");
  for (const json& field : fields) {
    const std::string attribute = field.is_object() ? field.value(fmt::kFieldAttribute, "") : "";
    if (!isFieldAttribute(attribute) || attribute.size() == std::string(fmt::kAttributePrefix).size() ||
        attribute.find_first_not_of("0123456789", std::string(fmt::kAttributePrefix).size()) != std::string::npos)
      return input.error(std::string(fmt::kExtension) + " fields entry without a _GEODESIC_k attribute");
  }
  return {};
}

Status adaptGeodesic(glb::Package& package, const ObjectInput& input) {
  if (!package.extensions.contains(fmt::kExtension) || !package.extensions[fmt::kExtension].is_object())
    return input.error(std::string("not a geodesic package (no ") + fmt::kExtension + " extension)");
  const json& root = package.extensions[fmt::kExtension];
  const json fields = root.value(fmt::kKeyFields, json());
  BAKE_RETURN_IF_ERROR(checkFieldList(fields, input));
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::size_t> read,
                        fieldsReadIn(fields, input.scene.fieldsRead(input.object), input));

  std::vector<bool> keep(fields.size(), input.keepUnused);
  for (std::size_t k : read) keep[k] = true;
  const bool global = root.value(fmt::kKeyNormalization, "") == fmt::kNormalizationGlobal;
  if (global && std::find(keep.begin(), keep.end(), false) != keep.end()) {
    input.keep("every field kept: normalization 'global' scales all fields by their common largest distance");
    std::fill(keep.begin(), keep.end(), true);
  }
  keepOnly(package, keep, input);

  // The object's material is the scene's, on every primitive.
  package.materials = json::array({geotextureMaterial(package.extensions[fmt::kExtension][fmt::kKeyFields], input)});
  for (glb::Mesh& mesh : package.meshes)
    for (glb::Primitive& primitive : mesh.primitives) primitive.material = 0;
  return {};
}

// The root object is package-wide: bakeplay reads the encoding, the normalization and, for `none`,
// each field's maxDistance from it and checks that every geodesic primitive carries every listed
// attribute. Several geodesic objects therefore share one root only when those agree.
Status mergeGeodesicRoot(json& assembled, const glb::Package& package, const ObjectInput& input) {
  const json& root = package.extensions[fmt::kExtension];
  if (!assembled.contains(fmt::kExtension)) {
    assembled[fmt::kExtension] = root;
    return {};
  }
  const json& first = assembled[fmt::kExtension];
  bool same = first.value(fmt::kKeyEncoding, "") == root.value(fmt::kKeyEncoding, "") &&
              first.value(fmt::kKeyNormalization, "") == root.value(fmt::kKeyNormalization, "") &&
              first[fmt::kKeyFields].size() == root[fmt::kKeyFields].size();
  const bool modelUnits = root.value(fmt::kKeyNormalization, "") == fmt::kNormalizationNone;
  for (std::size_t k = 0; same && k < root[fmt::kKeyFields].size(); ++k) {
    const json &a = first[fmt::kKeyFields][k], &b = root[fmt::kKeyFields][k];
    same = fieldName(a) == fieldName(b) && a.value(fmt::kFieldAttribute, "") == b.value(fmt::kFieldAttribute, "") &&
           (!modelUnits || a.value(fmt::kFieldMaxDistance, 0.0) == b.value(fmt::kFieldMaxDistance, 0.0));
  }
  if (!same)
    return unsupported("object '" + input.object.name + "': its geodesic fields (names, encoding or normalization) differ "
                       "from another geodesic object's; one scene package holds one " + fmt::kExtension + " field list",
                       {input.file, std::string("extensions.") + fmt::kExtension});
  return {};
}

}  // namespace
}  // namespace bake::geodesic::assembly

namespace bake::geodesic {

const pipe::detail::TechniqueRules& assembleRules() {
  using namespace assembly;
  static const TechniqueRules rules{.extension = fmt::kExtension,
                                    .blobAlignment = 16,
                                    .adapt = adaptGeodesic,
                                    .mergeRoot = mergeGeodesicRoot};
  return rules;
}

}  // namespace bake::geodesic
