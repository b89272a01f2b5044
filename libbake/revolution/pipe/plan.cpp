// Revolution objects in scene files and plans (formats/scene.md). An object may name a base colour
// texture and a height map ("textures"); the plan leaves out either when the material does not read
// it (and the height scale with the height map).
#include "revolution/pipe/pipe.h"

namespace bake::revolution {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

Status readRevolutionObject(const pipe::SceneReader& r, const json& node, const std::string& where, pipe::Object& o) {
  if (!node.contains("textures")) return Status::ok();
  const std::string at = jsonPointerChild(where, "textures");
  BAKE_RETURN_IF_ERROR(r.object(node["textures"], at, {"baseColor", "heightMap"}));
  if (node["textures"].contains("baseColor")) {
    BAKE_ASSIGN_OR_RETURN(o.baseColor, r.path(node["textures"]["baseColor"], jsonPointerChild(at, "baseColor")));
  }
  if (node["textures"].contains("heightMap")) {
    BAKE_ASSIGN_OR_RETURN(o.heightMap, r.path(node["textures"]["heightMap"], jsonPointerChild(at, "heightMap")));
  }
  return Status::ok();
}

// A list option ([3, 1, 1]) as the comma-separated value revolbake reads ("3,1,1").
void listOption(pipe::Step& step, const json& options, const char* key, const char* flag) {
  if (!options.contains(key)) return;
  const json& value = options[key];
  if (!value.is_array()) return pipe::ObjectPlanner::option(step, options, key, flag);
  std::string text;
  for (const json& item : value) text += (text.empty() ? "" : ",") + (item.is_string() ? item.get<std::string>() : item.dump());
  step.arguments.insert(step.arguments.end(), {flag, text});
}

// Copies of the object (seed 001 Eq. 9) and the self-shadow switch.
void replicaOptions(pipe::Step& step, const json& options) {
  listOption(step, options, "grid", "--grid");
  listOption(step, options, "gridSpacing", "--grid-spacing");
  pipe::ObjectPlanner::option(step, options, "mirror", "--mirror");
  pipe::ObjectPlanner::option(step, options, "ring", "--ring");
  pipe::ObjectPlanner::option(step, options, "ringRadius", "--ring-radius");
  if (options.contains("selfShadow") && options["selfShadow"] == false) step.arguments.push_back("--no-self-shadow");
}

Status planRevolution(pipe::ObjectPlanner& p, const pipe::Object& object, pipe::Step& step) {
  const pipe::Material& material = p.scene.materialOf(object);
  p.addInput(step, p.resolve(object.input));
  const auto texture = [&](const std::optional<pipe::InputPath>& path, bool read, const char* flag, const char* what) {
    if (!path) return false;
    if (!read && !p.settings.keepUnused) {
      p.leaveOut(object, what, "material '" + material.name + "' does not read it");
      return false;
    }
    const fs::path file = p.resolve(*path);
    step.arguments.insert(step.arguments.end(), {flag, file.string()});
    step.inputs.push_back(file);
    return true;
  };
  texture(object.baseColor, material.readsBaseColor, "--base-color", "base colour texture");
  if (texture(object.heightMap, material.readsDisplacement, "--height-map", "displacement map"))
    pipe::ObjectPlanner::option(step, object.options, "heightScale", "--height-scale");
  pipe::ObjectPlanner::option(step, object.options, "resolution", "--resolution");
  pipe::ObjectPlanner::option(step, object.options, "encoding", "--encoding");
  pipe::ObjectPlanner::option(step, object.options, "projection", "--projection");
  replicaOptions(step, object.options);
  step.outputs.push_back(p.baked(object, ".glb"));
  return {};
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{
      .optionKeys = {"resolution", "encoding", "heightScale", "projection", "grid", "gridSpacing", "mirror", "ring",
                     "ringRadius", "selfShadow"},
      .objectKeys = {"textures"},
      .readObject = readRevolutionObject,
      .reads = {{"baseColor", &pipe::Material::readsBaseColor}, {"displacement", &pipe::Material::readsDisplacement}},
      .plan = planRevolution,
      .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::revolution
