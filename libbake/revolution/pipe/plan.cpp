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
  step.outputs.push_back(p.baked(object, ".glb"));
  return {};
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{
      .optionKeys = {"resolution", "encoding", "heightScale", "projection"},
      .objectKeys = {"textures"},
      .readObject = readRevolutionObject,
      .reads = {{"baseColor", &pipe::Material::readsBaseColor}, {"displacement", &pipe::Material::readsDisplacement}},
      .plan = planRevolution,
      .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::revolution
