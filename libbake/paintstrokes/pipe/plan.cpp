// Paintstroke objects in scene files and plans (formats/scene.md). An object's input is a stroke list
// or a mesh to grow strokes on; its options are strokebake's. The plan leaves out the self-shadowing
// table when the material does not read shadows, and the styles no stroke uses (listed by name when
// the stroke list holds its strokes; a list whose generators make them is baked with the same option
// and strokebake's report names what it dropped).
#include "paintstrokes/pipe/pipe.h"

#include "paintstrokes/input/input.h"
#include "paintstrokes/input/validate.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// "lightDirections": [[x, y, z], ...] as repeated --light-dir x,y,z.
Status lightDirections(const json& options, pipe::Step& step) {
  if (!options.contains("lightDirections")) return {};
  const json& list = options["lightDirections"];
  const auto malformed = [] { return invalidInput("options.lightDirections must be a list of [x, y, z] numbers"); };
  if (!list.is_array()) return malformed();
  for (const json& direction : list) {
    if (!direction.is_array() || direction.size() != 3) return malformed();
    std::string text;
    for (const json& x : direction) {
      if (!x.is_number()) return malformed();
      text += (text.empty() ? "" : ",") + pipe::ObjectPlanner::number(x.get<double>());
    }
    step.arguments.insert(step.arguments.end(), {"--light-dir", text});
  }
  return {};
}

// The styles no stroke uses: left out by strokebake's --drop-unused-styles.
Status leaveOutUnusedStyles(pipe::ObjectPlanner& p, const pipe::Object& object, const fs::path& input, pipe::Step& step) {
  if (object.input.generated || !isStrokeList(input)) return {};  // strokes grown on a mesh share one style
  BAKE_ASSIGN_OR_RETURN(const StrokeInput list, readStrokeInput(input));
  if (list.set.styles.size() < 2 || (list.set.strokes.empty() && list.generators.empty())) return {};  // a package keeps a style
  if (!list.generators.empty()) {
    step.arguments.push_back("--drop-unused-styles");
    p.leaveOut(object, "styles no stroke uses, if any",
               "the list's generators make its strokes; strokebake's report names the styles it dropped");
    return {};
  }
  const std::vector<std::string> unused = unusedStyles(list.set);
  if (unused.empty()) return {};
  step.arguments.push_back("--drop-unused-styles");
  for (const std::string& name : unused) p.leaveOut(object, "style '" + name + "'", "no stroke uses it");
  return {};
}

Status planPaintstrokes(pipe::ObjectPlanner& p, const pipe::Object& object, pipe::Step& step) {
  const pipe::Material& material = p.scene.materialOf(object);
  const fs::path input = p.resolve(object.input);
  p.addInput(step, input);
  BAKE_RETURN_IF_ERROR(lightDirections(object.options, step));
  pipe::ObjectPlanner::option(step, object.options, "shadowDensity", "--shadow-density");
  pipe::ObjectPlanner::option(step, object.options, "shadowMinimum", "--shadow-minimum");
  pipe::ObjectPlanner::option(step, object.options, "count", "--count");
  pipe::ObjectPlanner::option(step, object.options, "length", "--length");
  pipe::ObjectPlanner::option(step, object.options, "radius", "--radius");
  pipe::ObjectPlanner::option(step, object.options, "seed", "--seed");
  step.outputs.push_back(p.baked(object, ".glb"));
  if (p.settings.keepUnused) return {};
  if (!material.readsShadows) {
    step.arguments.push_back("--no-shadows");
    p.leaveOut(object, "self-shadowing table", "material '" + material.name + "' does not read shadows");
  }
  return leaveOutUnusedStyles(p, object, input, step);
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{
      .optionKeys = {"lightDirections", "shadowDensity", "shadowMinimum", "count", "length", "radius", "seed"},
      .reads = {{"shadows", &pipe::Material::readsShadows}},
      .plan = planPaintstrokes,
      .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::paintstrokes
