// Geodesic objects in scene files and plans (formats/scene.md). An object names its geobake sources
// file, whose field names the scene's materials read; the plan bakes only the fields the material
// reads (--fields), unless `normalize: global` makes every field depend on all of them.
#include "geodesic/pipe/pipe.h"

#include <algorithm>

#include "core/json_keys.h"

namespace bake::geodesic {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The field names of a geobake sources file, in order; unnamed fields are "field K".
Result<std::vector<std::string>> sourceFieldNames(const fs::path& path, const std::string& where, const pipe::SceneReader& r) {
  BAKE_ASSIGN_OR_RETURN(const json doc, pipe::readJsonFile(path, "sources file"));
  if (!doc.is_object() || !doc.contains("fields") || !doc["fields"].is_array() || doc["fields"].empty())
    return r.error(where, path.string() + " has no \"fields\" list");
  std::vector<std::string> names;
  for (std::size_t k = 0; k < doc["fields"].size(); ++k) {
    const json& field = doc["fields"][k];
    names.push_back(field.is_object() && field.contains("name") && field["name"].is_string()
                        ? field["name"].get<std::string>()
                        : "field " + std::to_string(k));
  }
  return names;
}

Status readGeodesicObject(const pipe::SceneReader& r, const json& node, const std::string& where, pipe::Object& o) {
  const std::string at = jsonPointerChild(where, "sources");
  if (!node.contains("sources")) return r.error(at, "is missing (a geodesic object needs its fields)");
  BAKE_ASSIGN_OR_RETURN(o.sources, r.path(node["sources"], at));
  if (o.sources->generated) return r.error(at, "cannot be a generated file");
  BAKE_ASSIGN_OR_RETURN(o.fieldNames, sourceFieldNames(o.sources->path, at, r));
  return Status::ok();
}

// "geotexture": the BAKE_geodesic material object, its "fields" by name.
Status readGeodesicMaterial(const pipe::SceneReader& r, const json& node, const std::string& where, pipe::Material& m) {
  if (!node.contains("geotexture")) return Status::ok();
  const std::string at = jsonPointerChild(where, "geotexture");
  if (!node["geotexture"].is_object()) return r.error(at, "must be a JSON object");
  m.geotexture = node["geotexture"];
  if (m.geotexture.contains("fields")) {
    const json& fields = m.geotexture["fields"];
    const std::string list = jsonPointerChild(at, "fields");
    if (!fields.is_array() || fields.empty() || fields.size() > 4) return r.error(list, "must list 1 to 4 field names");
    for (std::size_t k = 0; k < fields.size(); ++k) {
      BAKE_ASSIGN_OR_RETURN(std::string field, r.string(fields[k], jsonPointerChild(list, k)));
      m.fields.push_back(std::move(field));
    }
  }
  return Status::ok();
}

Status planGeodesic(pipe::ObjectPlanner& p, const pipe::Object& object, pipe::Step& step) {
  p.addInput(step, p.resolve(object.input));
  const fs::path sources = p.resolve(*object.sources);
  step.arguments.insert(step.arguments.end(), {"--sources", sources.string()});
  step.inputs.push_back(sources);
  const std::vector<std::string> read = p.scene.fieldsRead(object);
  const bool global = jsonStringOr(object.options, "normalize", "") == "global";
  if (!p.settings.keepUnused && read.size() < object.fieldNames.size()) {
    if (global) {
      p.leaveOut(object, "nothing of its fields", "normalize: global divides every field by the largest of all, so all are baked");
    } else {
      std::string list;
      for (const std::string& name : object.fieldNames) {
        if (std::find(read.begin(), read.end(), name) != read.end()) {
          list += (list.empty() ? "" : ",") + name;
          continue;
        }
        p.leaveOut(object, "field '" + name + "'", "material '" + p.scene.materialOf(object).name + "' does not read it");
      }
      step.arguments.insert(step.arguments.end(), {"--fields", list});
    }
  }
  pipe::ObjectPlanner::option(step, object.options, "method", "--method");
  pipe::ObjectPlanner::option(step, object.options, "encoding", "--encoding");
  pipe::ObjectPlanner::option(step, object.options, "normalize", "--normalize");
  step.outputs.push_back(p.baked(object, ".glb"));
  return {};
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{.optionKeys = {"method", "encoding", "normalize"},
                                          .objectKeys = {"sources"},
                                          .readObject = readGeodesicObject,
                                          .materialKeys = {"geotexture"},
                                          .readMaterial = readGeodesicMaterial,
                                          .plan = planGeodesic,
                                          .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::geodesic
