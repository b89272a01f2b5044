// The geodesic technique's row in the registry (techniques/registry.h): GeoTextures over the
// per-vertex distance fields geobake writes. bakeinfo describes a package after the loader checks
// (so a damaged one is reported): the fields (name, attribute, encoding, range, sources, unreachable
// vertices, the measured error where the bake recorded one) and every GeoTexture material (preset
// and the fields it reads).
#include <bake_formats/geodesic.h>

#include "geodesic/package/package_read.h"
#include "geodesic/pipe/pipe.h"
#include "info/describe.h"
#include "techniques/registry.h"

namespace bake::techniques {
namespace {

using nlohmann::json;
namespace fmt = format::geodesic;

json fieldJson(const json& field) {
  json out{{"name", field.value(fmt::kFieldName, "")},
           {"attribute", field.value(fmt::kFieldAttribute, "")},
           {"maxDistance", field.value(fmt::kFieldMaxDistance, json())},
           {"sources", field.contains("sources") && field["sources"].is_array() ? field["sources"].size() : 0},
           {"unreachableVertices", field.value("unreachableVertices", json())}};
  if (field.contains("error") && field["error"].is_object()) out["error"] = field["error"];
  return out;
}

Result<json> describeGeodesic(const glb::Package& package, const std::string& name) {
  BAKE_RETURN_IF_ERROR(geodesic::checkGeodesicPackage(package, name));
  json description{{"encoding", nullptr}, {"normalization", nullptr}, {"fields", json::array()}, {"materials", json::array()}};
  if (package.extensions.contains(fmt::kExtension)) {
    const json& root = package.extensions[fmt::kExtension];
    description["encoding"] = root.value(fmt::kKeyEncoding, json());
    description["normalization"] = root.value(fmt::kKeyNormalization, json());
    if (root.contains(fmt::kKeyFields) && root[fmt::kKeyFields].is_array())
      for (const json& field : root[fmt::kKeyFields]) description["fields"].push_back(fieldJson(field));
  }
  for (const std::size_t m : materialsWith(package, fmt::kExtension)) {
    const json& material = package.materials[m];
    BAKE_ASSIGN_OR_RETURN(const geodesic::GeoTextureParams p,
                          geodesic::parseGeoTexture(material["extensions"][fmt::kExtension],
                                                    {name, "material " + std::to_string(m)}));
    description["materials"].push_back({{"material", m},
                                        {"preset", geodesic::geoPresetName(p.preset)},
                                        {"fields", p.fieldsGiven ? json(p.fields) : json("preset default")},
                                        {"combineMin", p.combineMin}});
  }
  return description;
}

std::string formatGeodesic(const json& d) {
  using info::numberText;
  using info::plural;
  std::string out = "  geodesic: " + plural(d["fields"].size(), "field");
  if (!d["encoding"].is_null()) out += ", " + d["encoding"].get<std::string>();
  if (!d["normalization"].is_null()) out += ", normalised " + d["normalization"].get<std::string>();
  out += "\n";
  for (const json& f : d["fields"]) {
    out += "    " + f["attribute"].get<std::string>() + " \"" + f["name"].get<std::string>() + "\": up to " +
           numberText(f["maxDistance"]) + ", " + plural(f["sources"].get<std::size_t>(), "source");
    if (f["unreachableVertices"].is_number() && f["unreachableVertices"].get<double>() > 0)
      out += ", " + numberText(f["unreachableVertices"]) + " unreachable vertices";
    if (f.contains("error"))
      out += "; error against " + f["error"].value("reference", std::string("?")) + ": mean " +
             numberText(f["error"].value("meanRelative", json())) + ", max " +
             numberText(f["error"].value("maxRelative", json())) + " (relative)";
    out += "\n";
  }
  for (const json& m : d["materials"]) {
    out += "    material " + std::to_string(m["material"].get<int>()) + ": GeoTexture " + m["preset"].get<std::string>() +
           ", fields " + (m["fields"].is_string() ? m["fields"].get<std::string>() : m["fields"].dump()) +
           (m["combineMin"].get<bool>() ? ", merged to their minimum" : "") + "\n";
  }
  return out;
}

}  // namespace

Technique geodesicTechnique() {
  return {"geodesic", format::geodesic::kExtension, "geobake", geodesic::checkGeodesicPackage,
          describeGeodesic, formatGeodesic, &geodesic::pipeHooks()};
}

}  // namespace bake::techniques
