// Hatching objects in scene files and plans (formats/scene.md). An object's input is a TAM style and
// its "mesh" the mesh the TAM is applied to; tambake writes the TAM array, the package and, when the
// material reads it, the threshold texture. The plan leaves out the finest TAM levels that no camera
// of the scene samples.
#include "hatching/pipe/pipe.h"

#include <cmath>

#include "bake/hatching/style.h"
#include "bake_formats/scene.h"
#include "core/json_keys.h"

namespace bake::hatching {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

Status readHatchingObject(const pipe::SceneReader& r, const json& node, const std::string& where, pipe::Object& o) {
  const std::string at = jsonPointerChild(where, "mesh");
  if (!node.contains("mesh")) return r.error(at, "is missing (the mesh the TAM is applied to)");
  BAKE_ASSIGN_OR_RETURN(o.mesh, r.path(node["mesh"], at));
  return Status::ok();
}

// The finest TAM levels no view samples: level l is kept while a texel of it covers at least
// kKeepLevelTexelPixels pixels at the object's largest pixels per unit (formats/scene.md).
Status skipFinestLevels(pipe::ObjectPlanner& p, const pipe::Object& object, const fs::path& stylePath, pipe::Step& step) {
  if (!p.scene.pixelsPerUnit && p.scene.cameras.empty()) return {};
  BAKE_ASSIGN_OR_RETURN(const Style style, readStyle(stylePath.string(), false));
  double radius = 0;
  if (!p.scene.pixelsPerUnit) { BAKE_ASSIGN_OR_RETURN(radius, p.meshRadius(*object.mesh)); }
  BAKE_ASSIGN_OR_RETURN(const double pixels, p.pixelsPerUnit(object, radius));
  p.plan.maxPixelsPerUnit = std::max(p.plan.maxPixelsPerUnit, pixels);
  if (!std::isfinite(pixels)) return {};
  const double tilesPerUnit = jsonNumberOr(object.options, "tilesPerUnit", 1.0);
  const double texelsPerUnit = style.resolution * tilesPerUnit;
  constexpr double kKeep = format::scene::kKeepLevelTexelPixels;
  int skip = 0;
  const int levels = int(std::floor(std::log2(double(style.resolution)))) + 1;
  while (skip + 1 < levels && pixels * std::ldexp(1.0, skip) / texelsPerUnit < kKeep) ++skip;
  if (skip == 0) return {};
  step.arguments.insert(step.arguments.end(), {"--skip-levels", std::to_string(skip)});
  const std::string sides = std::to_string(style.resolution) +
                            (skip > 1 ? " to " + std::to_string(style.resolution >> (skip - 1)) : std::string()) + " texels";
  p.leaveOut(object, (skip > 1 ? "TAM levels 0-" + std::to_string(skip - 1) : std::string("TAM level 0")) + " (" + sides + ")",
             "at most " + pipe::ObjectPlanner::number(std::round(pixels * 10) / 10) +
                 " pixels per unit on screen: their texels are below " + pipe::ObjectPlanner::number(kKeep) + " pixel");
  return {};
}

Status planHatching(pipe::ObjectPlanner& p, const pipe::Object& object, pipe::Step& step) {
  const pipe::Material& material = p.scene.materialOf(object);
  const fs::path style = p.resolve(object.input);
  p.addInput(step, style);
  const fs::path mesh = p.resolve(*object.mesh);
  step.inputs.push_back(mesh);
  const fs::path package = p.baked(object, ".glb");
  step.arguments.insert(step.arguments.end(), {"-o", p.baked(object, ".ktx2").string(), "--apply-to", mesh.string(),
                                               "--package", package.string()});
  step.outputs = {package, p.baked(object, ".ktx2")};
  pipe::ObjectPlanner::option(step, object.options, "tilesPerUnit", "--tiles-per-unit");
  pipe::ObjectPlanner::option(step, object.options, "rotation", "--rotation");
  pipe::ObjectPlanner::option(step, object.options, "orientation", "--orientation");
  if (object.options.contains("baseColour")) {
    const json& c = object.options["baseColour"];
    step.arguments.insert(step.arguments.end(),
                          {"--base-color", pipe::ObjectPlanner::number(c[0].get<double>()) + "," +
                                                pipe::ObjectPlanner::number(c[1].get<double>()) + "," +
                                                pipe::ObjectPlanner::number(c[2].get<double>())});
  }
  if (material.readsThreshold || p.settings.keepUnused) {
    const fs::path threshold = p.baked(object, ".threshold.ktx2");
    step.arguments.insert(step.arguments.end(), {"--threshold", threshold.string()});
    step.outputs.push_back(threshold);
  } else {
    p.leaveOut(object, "threshold texture", "material '" + material.name + "' does not read it");
  }
  if (p.settings.keepUnused) return {};
  return skipFinestLevels(p, object, style, step);
}

}  // namespace

const pipe::TechniqueHooks& pipeHooks() {
  static const pipe::TechniqueHooks hooks{.optionKeys = {"tilesPerUnit", "rotation", "orientation", "baseColour"},
                                          .objectKeys = {"mesh"},
                                          .readObject = readHatchingObject,
                                          .reads = {{"threshold", &pipe::Material::readsThreshold}},
                                          .plan = planHatching,
                                          .outputOption = false,
                                          .assemble = &assembleRules()};
  return hooks;
}

}  // namespace bake::hatching
