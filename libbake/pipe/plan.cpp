// Bake plans (pipe/plan.h; formats/scene.md, "What the plan leaves out, and why"). One step per
// generated file a kept step reads, then one baker step per object, with the options that leave out
// what the object's material does not read (each technique's plan hook, pipe/technique_hooks.h).
// Every omission is listed with its reason, so a test (and a person) can check it; --keep-unused
// plans the full bakes instead.
#include "pipe/plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "bake/io/mesh.h"
#include "bake/mesh/shapes.h"
#include "pipe/technique_hooks.h"
#include "techniques/registry.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Planner : ObjectPlanner {
  Step stepFor(const Object& object) const {
    Step step;
    step.tool = techniques::byName(object.technique)->tool;
    step.id = step.tool + ":" + object.name;
    step.object = object.name;
    return step;
  }

  Status object(const Object& object) {
    Step step = stepFor(object);
    const TechniqueHooks& hooks = *hooksOf(object.technique);
    BAKE_RETURN_IF_ERROR(hooks.plan(*this, object, step));
    if (hooks.outputOption) step.arguments.insert(step.arguments.end(), {"-o", step.outputs[0].string()});
    step.arguments.push_back("-q");
    cached(step);
    plan.packages.push_back(step.outputs[0]);
    plan.steps.push_back(std::move(step));
    return {};
  }

  void cached(Step& step) const {
    if (!settings.cacheDirectory.empty())
      step.arguments.insert(step.arguments.end(), {"--cache-dir", settings.cacheDirectory.string()});
  }

  // bakeshape steps for the generated files a kept step reads, before the bakes; the others are
  // left out with the reason.
  void generatedSteps() {
    std::vector<Step> steps;
    for (const Generated& g : scene.generated) {
      if (!generatedUsed.count(g.output)) {
        plan.leftOut.push_back({"(scene)", "generated " + g.output, "no step that is kept reads it"});
        continue;
      }
      Step step;
      step.id = "bakeshape:" + g.output;
      step.tool = "bakeshape";
      step.arguments = {g.shape, "-o", out(g.output).string(), "-q"};
      if (g.resolution) step.arguments.insert(step.arguments.begin() + 1, {"--resolution", std::to_string(*g.resolution)});
      cached(step);
      step.outputs = {out(g.output)};
      steps.push_back(std::move(step));
    }
    plan.steps.insert(plan.steps.begin(), steps.begin(), steps.end());
  }
};

json pathList(const std::vector<fs::path>& paths) {
  json list = json::array();
  for (const fs::path& p : paths) list.push_back(p.string());
  return list;
}

}  // namespace

fs::path ObjectPlanner::baked(const Object& object, const std::string& extension) const {
  return out(object.name + "." + object.technique + extension);
}

fs::path ObjectPlanner::resolve(const InputPath& path) {
  if (!path.generated) return path.path;
  generatedUsed.insert(path.path.string());
  return out(path.path.string());
}

void ObjectPlanner::leaveOut(const Object& object, std::string what, std::string why) {
  plan.leftOut.push_back({object.name, std::move(what), std::move(why)});
}

void ObjectPlanner::addInput(Step& step, const fs::path& path) {
  step.arguments.push_back(path.string());
  step.inputs.push_back(path);
}

void ObjectPlanner::option(Step& step, const json& options, const char* key, const char* flag) {
  if (!options.contains(key)) return;
  const json& value = options[key];
  step.arguments.push_back(flag);
  step.arguments.push_back(value.is_string() ? value.get<std::string>() : value.dump());
}

std::string ObjectPlanner::number(double x) {
  json j = x;
  return j.dump();
}

Result<double> ObjectPlanner::meshRadius(const InputPath& mesh) const {
  TriangleMesh triangles;
  if (mesh.generated) {
    const auto generated = std::find_if(scene.generated.begin(), scene.generated.end(),
                                        [&](const Generated& g) { return g.output == mesh.path.string(); });
    ShapeSettings shape;
    shape.name = generated->shape;
    if (generated->resolution) shape.resolution = *generated->resolution;
    BAKE_ASSIGN_OR_RETURN(triangles, makeShape(shape));
  } else {
    BAKE_ASSIGN_OR_RETURN(triangles, readMesh(mesh.path));
  }
  double radius = 0;
  for (const Vec3f& p : triangles.positions)
    radius = std::max(radius, std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]));
  return radius;
}

// At the least depth along the view axis of the object's bounding sphere (formats/scene.md). A
// pinhole camera maps a segment at depth z off the axis by angle theta to at most f / (z cos theta)
// pixels per unit (a segment parallel to the image plane gets f / z; one turned toward the axis more),
// so the scale at the nearest depth is divided by the cosine of the image corner's angle.
Result<double> ObjectPlanner::pixelsPerUnit(const Object& object, double radius) const {
  if (scene.pixelsPerUnit) return (*scene.pixelsPerUnit)[1] * object.scale;
  double most = 0;
  for (const Camera& camera : scene.cameras) {
    double axis[3], length = 0, depth = 0;
    for (int k = 0; k < 3; ++k) {
      axis[k] = camera.target[k] - camera.eye[k];
      length += axis[k] * axis[k];
    }
    length = std::sqrt(length);
    for (int k = 0; k < 3; ++k) depth += (object.position[k] - camera.eye[k]) * axis[k] / length;
    const double nearest = depth - radius * object.scale;
    if (nearest <= 0) return HUGE_VAL;
    const double tanHalf = std::tan(camera.yfovDegrees * std::numbers::pi / 360.0);
    const double aspect = double(camera.width) / camera.height;
    const double cornerSecant = std::sqrt(1 + tanHalf * tanHalf * (1 + aspect * aspect));
    most = std::max(most, camera.height / (2 * tanHalf * nearest) * cornerSecant * object.scale);
  }
  return most;
}

fs::path locateTool(const std::string& tool, const fs::path& directory) {
  if (directory.empty()) return tool;
  std::error_code ec;
  if (fs::is_regular_file(directory / tool, ec)) return directory / tool;
  const fs::path buildTree = (directory / ".." / tool / tool).lexically_normal();
  if (fs::is_regular_file(buildTree, ec)) return buildTree;
  return tool;
}

std::string shellQuote(const std::string& word) {
  bool plain = !word.empty();
  for (const char c : word)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || std::string("_./=:,+-").find(c) != std::string::npos);
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string commandLine(const Step& step, const fs::path& toolDirectory) {
  std::string line = shellQuote(locateTool(step.tool, toolDirectory).string());
  for (const std::string& argument : step.arguments) line += " " + shellQuote(argument);
  return line;
}

json Plan::toJson() const {
  json steps = json::array();
  for (const Step& step : this->steps)
    steps.push_back({{"id", step.id},
                     {"tool", step.tool},
                     {"arguments", step.arguments},
                     {"inputs", pathList(step.inputs)},
                     {"outputs", pathList(step.outputs)},
                     {"object", step.object}});
  json left = json::array();
  for (const LeftOut& item : leftOut) left.push_back({{"object", item.object}, {"what", item.what}, {"why", item.why}});
  json result = {{"steps", steps}, {"leftOut", left}, {"packages", pathList(packages)}};
  if (maxPixelsPerUnit > 0) result["maxPixelsPerUnit"] = std::isfinite(maxPixelsPerUnit) ? json(maxPixelsPerUnit) : json(nullptr);
  return result;
}

Result<Plan> makePlan(const Scene& scene, const PlanSettings& settings) {
  Planner planner{{scene, settings, {}, {}}};
  for (const Object& object : scene.objects) {
    Status status = planner.object(object);
    if (!status.isOk()) return status.atElement("object \"" + object.name + "\"");
  }
  planner.generatedSteps();
  // No two steps may write one file (a generated file named like a baked one, say), whether or not
  // the generated file is needed.
  std::map<fs::path, std::string> writers;
  for (const Generated& g : scene.generated) writers.emplace(settings.outputDirectory / g.output, "bakeshape:" + g.output);
  for (const Step& step : planner.plan.steps)
    for (const fs::path& output : step.outputs) {
      const auto [at, added] = writers.emplace(output, step.id);
      if (!added && at->second != step.id)
        return invalidInput("both " + at->second + " and " + step.id + " would write " + output.string(),
                            {scene.file.string(), "/objects"});
    }
  return std::move(planner.plan);
}

}  // namespace bake::pipe
