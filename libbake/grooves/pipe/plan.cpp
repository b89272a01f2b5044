// Groove objects in scene files and plans (formats/scene.md). An object may name a UV-mapped "mesh"
// the grooves are drawn on (groovebake --apply-to); without one its package holds the preview plane
// over the domain. The plan bakes no special-case records
// when the material line-samples everywhere, and reports the kinds of special case the pattern does
// not contain (nothing of them is baked).
#include "grooves/pipe/pipe.h"

#include "core/json_keys.h"
#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

Status readGroovesObject(const pipe::SceneReader& r, const json& node, const std::string& where, pipe::Object& o) {
  if (!node.contains("mesh")) return Status::ok();
  BAKE_ASSIGN_OR_RETURN(o.mesh, r.path(node["mesh"], jsonPointerChild(where, "mesh")));
  return Status::ok();
}

Status planGrooves(pipe::ObjectPlanner& p, const pipe::Object& object, pipe::Step& step) {
  const pipe::Material& material = p.scene.materialOf(object);
  const fs::path input = p.resolve(object.input);
  p.addInput(step, input);
  if (object.mesh) {
    const fs::path mesh = p.resolve(*object.mesh);
    step.inputs.push_back(mesh);
    step.arguments.insert(step.arguments.end(), {"--apply-to", mesh.string()});
  }
  pipe::ObjectPlanner::option(step, object.options, "cellSize", "--cell-size");
  pipe::ObjectPlanner::option(step, object.options, "maxCells", "--max-cells");
  step.outputs.push_back(p.baked(object, ".glb"));
  if (!material.readsSpecialCases && !p.settings.keepUnused) {
    step.arguments.push_back("--no-special-cases");
    p.leaveOut(object, "special-case records", "material '" + material.name + "' line-samples everywhere");
    return {};
  }
  if (object.input.generated) return {};
  BAKE_ASSIGN_OR_RETURN(const GrooveScene grooves, readGrooveScene(input.string()));
  GridSettings grid;
  // Read leniently: an option of the wrong type is the baker's to refuse when the step runs.
  grid.cellSize = jsonNumberOr(object.options, "cellSize", 0.0);
  const std::int64_t maxCells = jsonIndexOr(object.options, "maxCells");
  if (maxCells > 0) grid.maxCells = std::uint64_t(maxCells);
  BAKE_ASSIGN_OR_RETURN(const GrooveGrid built, buildGrooveGrid(grooves, grid));
  const GridStats stats = gridStats(built);
  const std::pair<const char*, std::uint64_t> kinds[] = {
      {"intersection records", stats.intersections}, {"end records", stats.ends}, {"corner records", stats.corners}};
  for (const auto& [what, count] : kinds)
    if (count == 0) p.leaveOut(object, what, "the pattern has none");
  return {};
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{.optionKeys = {"cellSize", "maxCells"},
                                          .objectKeys = {"mesh"},
                                          .readObject = readGroovesObject,
                                          .reads = {{"specialCases", &pipe::Material::readsSpecialCases}},
                                          .plan = planGrooves,
                                          .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::grooves
