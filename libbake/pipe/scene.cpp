// The scene description reader (pipe/scene.h; formats/scene.md, formats/scene.schema.json). Strict
// like the other readers: unknown keys are errors with the nearest known key suggested, and every
// error names the file and the JSON pointer of the element at fault.
#include "pipe/scene.h"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "bake_formats/scene.h"
#include "core/atomic_file.h"
#include "core/json_keys.h"
#include "core/json_read.h"

namespace bake::pipe {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;
namespace key = bake::format::scene;

std::string child(const std::string& parent, const std::string& name) { return jsonPointerChild(parent, name); }
std::string child(const std::string& parent, std::size_t index) { return jsonPointerChild(parent, index); }

struct Reader : JsonReader {
  Status required(const json& node, const std::string& where, std::initializer_list<const char*> keys) const {
    for (const char* name : keys)
      if (!node.contains(name)) return error(child(where, name), "is missing");
    return Status::ok();
  }
  Result<double> positive(const json& node, const std::string& where) const {
    BAKE_ASSIGN_OR_RETURN(const double x, number(node, where));
    if (x <= 0) return error(where, "must be positive");
    return x;
  }
  Result<int> integer(const json& node, const std::string& where, int lowest, int highest) const {
    if (!node.is_number_integer()) return error(where, "must be an integer");
    const long long x = node.get<long long>();
    if (x < lowest || x > highest)
      return error(where, "must be in [" + std::to_string(lowest) + ", " + std::to_string(highest) + "]");
    return int(x);
  }
  Result<bool> boolean(const json& node, const std::string& where) const {
    if (!node.is_boolean()) return error(where, "must be true or false");
    return node.get<bool>();
  }
  Result<std::array<double, 3>> vec3(const json& node, const std::string& where) const {
    if (!node.is_array() || node.size() != 3) return error(where, "must be three numbers [x, y, z]");
    std::array<double, 3> v{};
    for (std::size_t k = 0; k < 3; ++k) { BAKE_ASSIGN_OR_RETURN(v[k], number(node[k], child(where, k))); }
    return v;
  }
  // Names become file names and node names: letters, digits, '-' and '_'.
  Result<std::string> name(const json& node, const std::string& where) const {
    BAKE_ASSIGN_OR_RETURN(std::string text, string(node, where));
    if (text.empty()) return error(where, "must not be empty");
    for (const char c : text)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
        return error(where, "\"" + text + "\" may only hold letters, digits, '-' and '_'");
    return text;
  }
  Result<Technique> technique(const json& node, const std::string& where) const {
    BAKE_ASSIGN_OR_RETURN(const std::string text, string(node, where));
    for (const Technique t : {Technique::Geodesic, Technique::Revolution, Technique::Hatching, Technique::Grooves})
      if (text == techniqueName(t)) return t;
    return error(where, "unknown technique \"" + text + "\" (geodesic, revolution, hatching, grooves)");
  }
};

struct Context {
  const Reader& r;
  const fs::path& directory;
  const std::set<std::string>& generatedOutputs;

  Result<InputPath> path(const json& node, const std::string& where) const {
    BAKE_ASSIGN_OR_RETURN(const std::string text, r.string(node, where));
    if (text.empty()) return r.error(where, "must not be empty");
    if (generatedOutputs.count(text)) return InputPath{fs::path(text), true};
    const fs::path resolved = (directory / text).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(resolved, ec))
      return r.error(where, "\"" + text + "\" is not a file (looked for " + resolved.string() +
                                "; generated files: the scene's \"generated\" outputs)");
    return InputPath{resolved, false};
  }
};

Result<Generated> readGenerated(const Reader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"output", "shape", "resolution"}));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"output", "shape"}));
  Generated g;
  BAKE_ASSIGN_OR_RETURN(g.output, r.string(node["output"], child(where, "output")));
  if (g.output.empty() || g.output.find('/') != std::string::npos || g.output[0] == '.')
    return r.error(child(where, "output"), "must be a plain file name");
  BAKE_ASSIGN_OR_RETURN(g.shape, r.name(node["shape"], child(where, "shape")));
  if (node.contains("resolution")) {
    BAKE_ASSIGN_OR_RETURN(g.resolution, r.integer(node["resolution"], child(where, "resolution"), 1, 16384));
  }
  return g;
}

// A JSON file, parsed; `what` names it in the error when it cannot be read ("scene file", ...).
Result<json> readJsonFile(const fs::path& path, const std::string& what) {
  Result<std::vector<std::uint8_t>> bytes = readFileBytes(path);
  if (!bytes.isOk()) {
    Status status = bytes.status();
    return Status(status.code(), "cannot read the " + what + ": " + status.message(), {path.string(), ""});
  }
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return parseJsonText(text, path.string());
}

// The field names of a geobake sources file, in order; unnamed fields are "field K".
Result<std::vector<std::string>> sourceFieldNames(const fs::path& path, const std::string& where, const Reader& r) {
  BAKE_ASSIGN_OR_RETURN(const json doc, readJsonFile(path, "sources file"));
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

Status readOptions(const Reader& r, const json& node, const std::string& where, Technique technique) {
  switch (technique) {
    case Technique::Geodesic: return r.object(node, where, {"method", "encoding", "normalize"});
    case Technique::Revolution: return r.object(node, where, {"resolution", "encoding", "heightScale", "projection"});
    case Technique::Hatching: return r.object(node, where, {"tilesPerUnit", "rotation", "orientation", "baseColour"});
    case Technique::Grooves: return r.object(node, where, {"cellSize", "maxCells"});
  }
  return Status::ok();
}

Result<Object> readObject(const Context& c, const json& node, const std::string& where,
                          const std::map<std::string, std::size_t>& materials) {
  const Reader& r = c.r;
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"name", "technique", "input", "sources", "mesh", "textures", "options",
                                              "position", "scale", "material"}));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"name", "technique", "input", "material"}));
  Object o;
  BAKE_ASSIGN_OR_RETURN(o.name, r.name(node["name"], child(where, "name")));
  BAKE_ASSIGN_OR_RETURN(o.technique, r.technique(node["technique"], child(where, "technique")));
  BAKE_ASSIGN_OR_RETURN(o.input, c.path(node["input"], child(where, "input")));
  const auto onlyFor = [&](const char* name, Technique t) -> Status {
    if (node.contains(name) && o.technique != t)
      return r.error(child(where, name), std::string("is for ") + techniqueName(t) + " objects only");
    return Status::ok();
  };
  BAKE_RETURN_IF_ERROR(onlyFor("sources", Technique::Geodesic));
  BAKE_RETURN_IF_ERROR(onlyFor("mesh", Technique::Hatching));
  BAKE_RETURN_IF_ERROR(onlyFor("textures", Technique::Revolution));
  if (o.technique == Technique::Geodesic) {
    if (!node.contains("sources")) return r.error(child(where, "sources"), "is missing (a geodesic object needs its fields)");
    BAKE_ASSIGN_OR_RETURN(o.sources, c.path(node["sources"], child(where, "sources")));
    if (o.sources->generated) return r.error(child(where, "sources"), "cannot be a generated file");
    BAKE_ASSIGN_OR_RETURN(o.fieldNames, sourceFieldNames(o.sources->path, child(where, "sources"), r));
  }
  if (o.technique == Technique::Hatching) {
    if (!node.contains("mesh")) return r.error(child(where, "mesh"), "is missing (the mesh the TAM is applied to)");
    BAKE_ASSIGN_OR_RETURN(o.mesh, c.path(node["mesh"], child(where, "mesh")));
  }
  if (node.contains("textures")) {
    const std::string at = child(where, "textures");
    BAKE_RETURN_IF_ERROR(r.object(node["textures"], at, {"baseColor", "heightMap"}));
    if (node["textures"].contains("baseColor")) {
      BAKE_ASSIGN_OR_RETURN(o.baseColor, c.path(node["textures"]["baseColor"], child(at, "baseColor")));
    }
    if (node["textures"].contains("heightMap")) {
      BAKE_ASSIGN_OR_RETURN(o.heightMap, c.path(node["textures"]["heightMap"], child(at, "heightMap")));
    }
  }
  if (node.contains("options")) {
    BAKE_RETURN_IF_ERROR(readOptions(r, node["options"], child(where, "options"), o.technique));
    o.options = node["options"];
  }
  if (node.contains("position")) { BAKE_ASSIGN_OR_RETURN(o.position, r.vec3(node["position"], child(where, "position"))); }
  if (node.contains("scale")) { BAKE_ASSIGN_OR_RETURN(o.scale, r.positive(node["scale"], child(where, "scale"))); }
  BAKE_ASSIGN_OR_RETURN(const std::string material, r.name(node["material"], child(where, "material")));
  const auto found = materials.find(material);
  if (found == materials.end()) return r.error(child(where, "material"), "no material is named \"" + material + "\"");
  o.material = found->second;
  return o;
}

Result<Material> readMaterial(const Reader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"name", "technique", "geotexture", "reads"}));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"name", "technique"}));
  Material m;
  BAKE_ASSIGN_OR_RETURN(m.name, r.name(node["name"], child(where, "name")));
  BAKE_ASSIGN_OR_RETURN(m.technique, r.technique(node["technique"], child(where, "technique")));
  if (node.contains("geotexture")) {
    const std::string at = child(where, "geotexture");
    if (m.technique != Technique::Geodesic) return r.error(at, "is for geodesic materials only");
    if (!node["geotexture"].is_object()) return r.error(at, "must be a JSON object");
    m.geotexture = node["geotexture"];
    if (m.geotexture.contains("fields")) {
      const json& fields = m.geotexture["fields"];
      if (!fields.is_array() || fields.empty() || fields.size() > 4)
        return r.error(child(at, "fields"), "must list 1 to 4 field names");
      for (std::size_t k = 0; k < fields.size(); ++k) {
        BAKE_ASSIGN_OR_RETURN(std::string field, r.string(fields[k], child(child(at, "fields"), k)));
        m.fields.push_back(std::move(field));
      }
    }
  }
  if (node.contains("reads")) {
    const std::string at = child(where, "reads");
    BAKE_RETURN_IF_ERROR(r.object(node["reads"], at, {"baseColor", "displacement", "threshold", "specialCases"}));
    const auto flag = [&](const char* name, bool& value, Technique t) -> Status {
      if (!node["reads"].contains(name)) return Status::ok();
      if (m.technique != t) return r.error(child(at, name), std::string("is for ") + techniqueName(t) + " materials only");
      BAKE_ASSIGN_OR_RETURN(value, r.boolean(node["reads"][name], child(at, name)));
      return Status::ok();
    };
    BAKE_RETURN_IF_ERROR(flag("baseColor", m.readsBaseColor, Technique::Revolution));
    BAKE_RETURN_IF_ERROR(flag("displacement", m.readsDisplacement, Technique::Revolution));
    BAKE_RETURN_IF_ERROR(flag("threshold", m.readsThreshold, Technique::Hatching));
    BAKE_RETURN_IF_ERROR(flag("specialCases", m.readsSpecialCases, Technique::Grooves));
  }
  return m;
}

Result<Camera> readCamera(const Reader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"name", "eye", "target", "yfov", "width", "height"}));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"eye", "target", "yfov", "width", "height"}));
  Camera c;
  if (node.contains("name")) { BAKE_ASSIGN_OR_RETURN(c.name, r.string(node["name"], child(where, "name"))); }
  BAKE_ASSIGN_OR_RETURN(c.eye, r.vec3(node["eye"], child(where, "eye")));
  BAKE_ASSIGN_OR_RETURN(c.target, r.vec3(node["target"], child(where, "target")));
  BAKE_ASSIGN_OR_RETURN(c.yfovDegrees, r.positive(node["yfov"], child(where, "yfov")));
  if (c.yfovDegrees >= 180) return r.error(child(where, "yfov"), "must be below 180 degrees");
  BAKE_ASSIGN_OR_RETURN(c.width, r.integer(node["width"], child(where, "width"), 1, 16384));
  BAKE_ASSIGN_OR_RETURN(c.height, r.integer(node["height"], child(where, "height"), 1, 16384));
  if (c.eye == c.target) return r.error(child(where, "target"), "must differ from the eye");
  return c;
}

}  // namespace

const char* techniqueName(Technique technique) {
  switch (technique) {
    case Technique::Geodesic: return key::kGeodesic;
    case Technique::Revolution: return key::kRevolution;
    case Technique::Hatching: return key::kHatching;
    case Technique::Grooves: return key::kGrooves;
  }
  return "?";
}

const char* bakerName(Technique technique) {
  switch (technique) {
    case Technique::Geodesic: return "geobake";
    case Technique::Revolution: return "revolbake";
    case Technique::Hatching: return "tambake";
    case Technique::Grooves: return "groovebake";
  }
  return "?";
}

std::vector<std::string> Scene::fieldsRead(const Object& object) const {
  const Material& m = materialOf(object);
  if (!m.fields.empty()) return m.fields;
  if (object.fieldNames.empty()) return {};
  return {object.fieldNames.front()};
}

Result<Scene> parseScene(const json& doc, const fs::path& path) {
  const Reader r{path.string()};
  BAKE_RETURN_IF_ERROR(r.object(doc, "", {"$schema", "description", "version", "name", "generated", "objects",
                                          "materials", "cameras", "pixelsPerUnit"}));
  BAKE_RETURN_IF_ERROR(r.required(doc, "", {"version", "objects", "materials"}));
  if (!doc["version"].is_number_integer() || doc["version"].get<long long>() != key::kVersion)
    return r.error("/version", "must be " + std::to_string(key::kVersion));
  Scene scene;
  scene.file = fs::absolute(path).lexically_normal();
  scene.directory = scene.file.parent_path();
  scene.name = scene.file.stem().string();
  if (doc.contains("name")) { BAKE_ASSIGN_OR_RETURN(scene.name, r.name(doc["name"], "/name")); }

  std::set<std::string> generatedOutputs;
  if (doc.contains("generated")) {
    if (!doc["generated"].is_array()) return r.error("/generated", "must be a list");
    for (std::size_t k = 0; k < doc["generated"].size(); ++k) {
      const std::string where = child("/generated", k);
      BAKE_ASSIGN_OR_RETURN(Generated g, readGenerated(r, doc["generated"][k], where));
      if (!generatedOutputs.insert(g.output).second)
        return r.error(child(where, "output"), "\"" + g.output + "\" is generated twice");
      scene.generated.push_back(std::move(g));
    }
  }

  if (!doc["materials"].is_array() || doc["materials"].empty()) return r.error("/materials", "must be a non-empty list");
  std::map<std::string, std::size_t> materialIndex;
  for (std::size_t k = 0; k < doc["materials"].size(); ++k) {
    const std::string where = child("/materials", k);
    BAKE_ASSIGN_OR_RETURN(Material m, readMaterial(r, doc["materials"][k], where));
    if (!materialIndex.emplace(m.name, k).second)
      return r.error(child(where, "name"), "\"" + m.name + "\" names two materials");
    scene.materials.push_back(std::move(m));
  }

  if (!doc["objects"].is_array() || doc["objects"].empty()) return r.error("/objects", "must be a non-empty list");
  const Context context{r, scene.directory, generatedOutputs};
  std::set<std::string> objectNames;
  for (std::size_t k = 0; k < doc["objects"].size(); ++k) {
    const std::string where = child("/objects", k);
    BAKE_ASSIGN_OR_RETURN(Object o, readObject(context, doc["objects"][k], where, materialIndex));
    if (!objectNames.insert(o.name).second) return r.error(child(where, "name"), "\"" + o.name + "\" names two objects");
    const Material& m = scene.materials[o.material];
    if (m.technique != o.technique)
      return r.error(child(where, "material"), "\"" + m.name + "\" is a " + techniqueName(m.technique) +
                                                   " material, the object is " + techniqueName(o.technique));
    for (std::size_t f = 0; f < m.fields.size(); ++f) {
      bool known = false;
      for (const std::string& name : o.fieldNames) known = known || name == m.fields[f];
      if (!known)
        return r.error(child(child(child("/materials", o.material), "geotexture"), "fields") + "/" + std::to_string(f),
                       "object \"" + o.name + "\" has no field \"" + m.fields[f] + "\" in its sources file");
    }
    scene.objects.push_back(std::move(o));
  }

  if (doc.contains("cameras")) {
    if (!doc["cameras"].is_array()) return r.error("/cameras", "must be a list");
    for (std::size_t k = 0; k < doc["cameras"].size(); ++k) {
      BAKE_ASSIGN_OR_RETURN(Camera c, readCamera(r, doc["cameras"][k], child("/cameras", k)));
      scene.cameras.push_back(std::move(c));
    }
  }
  if (doc.contains("pixelsPerUnit")) {
    const json& range = doc["pixelsPerUnit"];
    if (!range.is_array() || range.size() != 2) return r.error("/pixelsPerUnit", "must be [min, max]");
    std::array<double, 2> v{};
    BAKE_ASSIGN_OR_RETURN(v[0], r.positive(range[0], "/pixelsPerUnit/0"));
    BAKE_ASSIGN_OR_RETURN(v[1], r.positive(range[1], "/pixelsPerUnit/1"));
    if (v[0] > v[1]) return r.error("/pixelsPerUnit", "min must not exceed max");
    scene.pixelsPerUnit = v;
  }
  return scene;
}

Result<Scene> readScene(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return ioError("is a directory, not a scene file", {path.string(), ""});
  BAKE_ASSIGN_OR_RETURN(const json doc, readJsonFile(path, "scene file"));
  return parseScene(doc, path);
}

}  // namespace bake::pipe
