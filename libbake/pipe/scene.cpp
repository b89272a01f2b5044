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
#include "bake/core/atomic_file.h"
#include "bake/core/vector_text.h"
#include "core/json_keys.h"
#include "core/json_read.h"
#include "pipe/technique_hooks.h"

namespace bake::pipe {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;
namespace key = bake::format::scene;

std::string child(const std::string& parent, const std::string& name) { return jsonPointerChild(parent, name); }
std::string child(const std::string& parent, std::size_t index) { return jsonPointerChild(parent, index); }

// What a scene file may say of objects and materials, gathered once per scene from the registry's
// rows with scene hooks (registry order).
struct Vocabulary {
  struct Owned {
    const char* key;
    std::string technique;  // the technique whose objects (or materials) alone may carry the key
  };
  std::vector<std::string> techniques;
  std::vector<const TechniqueHooks*> hooks;  // one per technique
  std::vector<Owned> objectKeys, materialKeys;
  std::vector<const char*> knownObjectKeys, knownMaterialKeys, knownReads;

  static Vocabulary fromRegistry() {
    Vocabulary v;
    v.techniques = sceneTechniques();
    v.knownObjectKeys = {"name", "technique", "input"};
    v.knownMaterialKeys = {"name", "technique"};
    for (const std::string& technique : v.techniques) {
      const TechniqueHooks* hooks = hooksOf(technique);
      v.hooks.push_back(hooks);
      for (const char* key : hooks->objectKeys) v.objectKeys.push_back({key, technique});
      for (const char* key : hooks->materialKeys) v.materialKeys.push_back({key, technique});
      for (const ReadsFlag& flag : hooks->reads) v.knownReads.push_back(flag.key);
    }
    for (const Owned& owned : v.objectKeys) v.knownObjectKeys.push_back(owned.key);
    v.knownObjectKeys.insert(v.knownObjectKeys.end(), {"options", "position", "rotation", "scale", "material"});
    for (const Owned& owned : v.materialKeys) v.knownMaterialKeys.push_back(owned.key);
    v.knownMaterialKeys.push_back("reads");
    return v;
  }

  // The "technique" of an object or material, and its hooks.
  Result<const TechniqueHooks*> technique(const SceneReader& r, const json& node, const std::string& where,
                                          std::string& name) const {
    BAKE_ASSIGN_OR_RETURN(name, r.string(node, where));
    for (std::size_t t = 0; t < techniques.size(); ++t)
      if (techniques[t] == name) return hooks[t];
    std::string names;
    for (const std::string& known : techniques) names += (names.empty() ? "" : ", ") + known;
    return r.error(where, "unknown technique \"" + name + "\" (" + names + ")");
  }
};

Result<Generated> readGenerated(const SceneReader& r, const json& node, const std::string& where) {
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

Result<Object> readObject(const SceneReader& r, const Vocabulary& v, const json& node, const std::string& where,
                          const std::map<std::string, std::size_t>& materials) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, v.knownObjectKeys));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"name", "technique", "input", "material"}));
  Object o;
  BAKE_ASSIGN_OR_RETURN(o.name, r.name(node["name"], child(where, "name")));
  BAKE_ASSIGN_OR_RETURN(const TechniqueHooks* found, v.technique(r, node["technique"], child(where, "technique"), o.technique));
  const TechniqueHooks& hooks = *found;
  BAKE_ASSIGN_OR_RETURN(o.input, r.path(node["input"], child(where, "input")));
  // A key some techniques own (several may: "mesh") is refused on the objects of any other.
  for (const Vocabulary::Owned& owned : v.objectKeys) {
    if (!node.contains(owned.key)) continue;
    std::string owners;
    bool ours = false;
    for (const Vocabulary::Owned& other : v.objectKeys)
      if (std::string_view(other.key) == owned.key) {
        ours = ours || other.technique == o.technique;
        owners += (owners.empty() ? "" : " and ") + other.technique;
      }
    if (!ours) return r.error(child(where, owned.key), "is for " + owners + " objects only");
  }
  if (hooks.readObject) BAKE_RETURN_IF_ERROR(hooks.readObject(r, node, where, o));
  if (node.contains("options")) {
    BAKE_RETURN_IF_ERROR(r.object(node["options"], child(where, "options"), hooks.optionKeys));
    o.options = node["options"];
  }
  if (node.contains("position")) { BAKE_ASSIGN_OR_RETURN(o.position, r.vec3(node["position"], child(where, "position"))); }
  if (node.contains("rotation")) { BAKE_ASSIGN_OR_RETURN(o.rotation, r.rotation(node["rotation"], child(where, "rotation"))); }
  if (node.contains("scale")) { BAKE_ASSIGN_OR_RETURN(o.scale, r.positive(node["scale"], child(where, "scale"))); }
  BAKE_ASSIGN_OR_RETURN(const std::string material, r.name(node["material"], child(where, "material")));
  const auto named = materials.find(material);
  if (named == materials.end()) return r.error(child(where, "material"), "no material is named \"" + material + "\"");
  o.material = named->second;
  return o;
}

// The material's "reads" flags, each only for the technique that declares it.
Status readFlags(const SceneReader& r, const Vocabulary& v, const json& node, const std::string& at, Material& m) {
  BAKE_RETURN_IF_ERROR(r.object(node, at, v.knownReads));
  for (std::size_t t = 0; t < v.techniques.size(); ++t)
    for (const ReadsFlag& flag : v.hooks[t]->reads) {
      if (!node.contains(flag.key)) continue;
      if (m.technique != v.techniques[t])
        return r.error(child(at, flag.key), "is for " + v.techniques[t] + " materials only");
      BAKE_ASSIGN_OR_RETURN(m.*flag.value, r.boolean(node[flag.key], child(at, flag.key)));
    }
  return Status::ok();
}

Result<Material> readMaterial(const SceneReader& r, const Vocabulary& v, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, v.knownMaterialKeys));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"name", "technique"}));
  Material m;
  BAKE_ASSIGN_OR_RETURN(m.name, r.name(node["name"], child(where, "name")));
  BAKE_ASSIGN_OR_RETURN(const TechniqueHooks* hooks, v.technique(r, node["technique"], child(where, "technique"), m.technique));
  for (const Vocabulary::Owned& owned : v.materialKeys)
    if (node.contains(owned.key) && m.technique != owned.technique)
      return r.error(child(where, owned.key), "is for " + owned.technique + " materials only");
  if (hooks->readMaterial) BAKE_RETURN_IF_ERROR(hooks->readMaterial(r, node, where, m));
  if (node.contains("reads")) BAKE_RETURN_IF_ERROR(readFlags(r, v, node["reads"], child(where, "reads"), m));
  return m;
}

Result<Camera> readCamera(const SceneReader& r, const json& node, const std::string& where) {
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

// A light (formats/scene.md, "Lights"): every number checked, the cone within (0, 90] degrees.
Result<SceneLight> readLight(const SceneReader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"name", "type", "position", "target", "colour", "intensity", "cutoff", "exponent"}));
  BAKE_RETURN_IF_ERROR(r.required(node, where, {"type", "position"}));
  SceneLight light;
  if (node.contains("name")) { BAKE_ASSIGN_OR_RETURN(light.name, r.name(node["name"], child(where, "name"))); }
  BAKE_ASSIGN_OR_RETURN(light.type, r.string(node["type"], child(where, "type")));
  if (light.type != "directional" && light.type != "point" && light.type != "spot")
    return r.error(child(where, "type"), "is \"" + light.type + "\"; known: directional, point, spot");
  BAKE_ASSIGN_OR_RETURN(light.position, r.vec3(node["position"], child(where, "position")));
  if (light.type != "point") {
    if (!node.contains("target")) return r.error(child(where, "target"), "is missing: a " + light.type + " light shines toward it");
    BAKE_ASSIGN_OR_RETURN(light.target, r.vec3(node["target"], child(where, "target")));
    if (light.target == light.position) return r.error(child(where, "target"), "must differ from the position");
  } else if (node.contains("target") || node.contains("cutoff") || node.contains("exponent")) {
    return r.error(where, "a point light takes no target, cutoff or exponent");
  }
  if (node.contains("colour")) {
    BAKE_ASSIGN_OR_RETURN(light.colour, r.vec3(node["colour"], child(where, "colour")));
    for (int c = 0; c < 3; ++c)
      if (light.colour[std::size_t(c)] < 0) return r.error(child(child(where, "colour"), c), "must be >= 0");
  }
  if (node.contains("intensity")) { BAKE_ASSIGN_OR_RETURN(light.intensity, r.positive(node["intensity"], child(where, "intensity"))); }
  if (light.type != "spot" && (node.contains("cutoff") || node.contains("exponent")))
    return r.error(where, "only a spot light takes a cutoff and an exponent");
  if (node.contains("cutoff")) {
    BAKE_ASSIGN_OR_RETURN(light.cutoffDegrees, r.positive(node["cutoff"], child(where, "cutoff")));
    if (light.cutoffDegrees > 90) return r.error(child(where, "cutoff"), "must be at most 90 degrees");
  }
  if (node.contains("exponent")) {
    BAKE_ASSIGN_OR_RETURN(light.exponent, r.number(node["exponent"], child(where, "exponent")));
    if (light.exponent < 0 || light.exponent > 128) return r.error(child(where, "exponent"), "must be in [0, 128]");
  }
  return light;
}

}  // namespace

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

Status SceneReader::required(const json& node, const std::string& where, std::initializer_list<const char*> keys) const {
  for (const char* name : keys)
    if (!node.contains(name)) return error(child(where, name), "is missing");
  return Status::ok();
}

Result<double> SceneReader::positive(const json& node, const std::string& where) const {
  BAKE_ASSIGN_OR_RETURN(const double x, number(node, where));
  if (x <= 0) return error(where, "must be positive");
  return x;
}

Result<int> SceneReader::integer(const json& node, const std::string& where, int lowest, int highest) const {
  if (!node.is_number_integer()) return error(where, "must be an integer");
  const long long x = node.get<long long>();
  if (x < lowest || x > highest)
    return error(where, "must be in [" + std::to_string(lowest) + ", " + std::to_string(highest) + "]");
  return int(x);
}

Result<bool> SceneReader::boolean(const json& node, const std::string& where) const {
  if (!node.is_boolean()) return error(where, "must be true or false");
  return node.get<bool>();
}

Result<std::array<double, 3>> SceneReader::vec3(const json& node, const std::string& where) const {
  if (!node.is_array() || node.size() != 3) return error(where, "must be three numbers [x, y, z]");
  std::array<double, 3> v{};
  for (std::size_t k = 0; k < 3; ++k) { BAKE_ASSIGN_OR_RETURN(v[k], number(node[k], child(where, k))); }
  return v;
}

Result<std::array<double, 4>> SceneReader::rotation(const json& node, const std::string& where) const {
  if (!node.is_array() || node.size() != 4) return error(where, "must be a unit quaternion [x, y, z, w] (glTF's rotation)");
  std::array<double, 4> q{};
  for (std::size_t k = 0; k < 4; ++k) { BAKE_ASSIGN_OR_RETURN(q[k], number(node[k], child(where, k))); }
  const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(std::abs(length - 1) <= 1e-3))
    return error(where, "must be a unit quaternion [x, y, z, w]: its length is " + numberText(length));
  for (double& c : q) c /= length;
  return q;
}

Result<std::string> SceneReader::name(const json& node, const std::string& where) const {
  BAKE_ASSIGN_OR_RETURN(std::string text, string(node, where));
  if (text.empty()) return error(where, "must not be empty");
  for (const char c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
      return error(where, "\"" + text + "\" may only hold letters, digits, '-' and '_'");
  return text;
}

Result<InputPath> SceneReader::path(const json& node, const std::string& where) const {
  BAKE_ASSIGN_OR_RETURN(const std::string text, string(node, where));
  if (text.empty()) return error(where, "must not be empty");
  if (generatedOutputs && generatedOutputs->count(text)) return InputPath{fs::path(text), true};
  const fs::path resolved = (directory / text).lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(resolved, ec))
    return error(where, "\"" + text + "\" is not a file (looked for " + resolved.string() +
                            "; generated files: the scene's \"generated\" outputs)");
  return InputPath{resolved, false};
}

std::vector<std::string> Scene::fieldsRead(const Object& object) const {
  const Material& m = materialOf(object);
  if (!m.fields.empty()) return m.fields;
  if (object.fieldNames.empty()) return {};
  return {object.fieldNames.front()};
}

Result<Scene> parseScene(const json& doc, const fs::path& path) {
  SceneReader r;
  r.file = path.string();
  const Vocabulary vocabulary = Vocabulary::fromRegistry();
  BAKE_RETURN_IF_ERROR(r.object(doc, "", {"$schema", "description", "version", "name", "generated", "objects",
                                          "materials", "cameras", "lights", "pixelsPerUnit"}));
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
    BAKE_ASSIGN_OR_RETURN(Material m, readMaterial(r, vocabulary, doc["materials"][k], where));
    if (!materialIndex.emplace(m.name, k).second)
      return r.error(child(where, "name"), "\"" + m.name + "\" names two materials");
    scene.materials.push_back(std::move(m));
  }

  if (!doc["objects"].is_array() || doc["objects"].empty()) return r.error("/objects", "must be a non-empty list");
  r.directory = scene.directory;
  r.generatedOutputs = &generatedOutputs;
  std::set<std::string> objectNames;
  for (std::size_t k = 0; k < doc["objects"].size(); ++k) {
    const std::string where = child("/objects", k);
    BAKE_ASSIGN_OR_RETURN(Object o, readObject(r, vocabulary, doc["objects"][k], where, materialIndex));
    if (!objectNames.insert(o.name).second) return r.error(child(where, "name"), "\"" + o.name + "\" names two objects");
    const Material& m = scene.materials[o.material];
    if (m.technique != o.technique)
      return r.error(child(where, "material"),
                     "\"" + m.name + "\" is a " + m.technique + " material, the object is " + o.technique);
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
  if (doc.contains("lights")) {
    if (!doc["lights"].is_array()) return r.error("/lights", "must be a list");
    for (std::size_t k = 0; k < doc["lights"].size(); ++k) {
      BAKE_ASSIGN_OR_RETURN(SceneLight light, readLight(r, doc["lights"][k], child("/lights", k)));
      scene.lights.push_back(std::move(light));
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
