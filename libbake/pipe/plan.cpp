// Bake plans (pipe/plan.h; formats/scene.md, "What the plan leaves out, and why"). One step per
// generated file a kept step reads, then one baker step per object, with the options that leave out
// what the object's material does not read. Every omission is listed with its reason, so a test (and
// a person) can check it; --keep-unused plans the full bakes instead.
#include "pipe/plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "bake_formats/scene.h"
#include "core/json_keys.h"
#include "groove/bake/grid.h"
#include "groove/input/scene.h"
#include "io/mesh.h"
#include "mesh/shapes.h"
#include "tam/style.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string number(double x) {
  json j = x;
  return j.dump();
}

struct Planner {
  const Scene& scene;
  const PlanSettings& settings;
  Plan plan;
  std::set<std::string> generatedUsed;  // generated outputs a kept step reads

  fs::path out(const std::string& name) const { return settings.outputDirectory / name; }
  // The files of an object's bake: OBJECT.TECHNIQUE.EXTENSION (formats/scene.md, "Paths").
  fs::path baked(const Object& object, const std::string& extension) const {
    return out(object.name + "." + techniqueName(object.technique) + extension);
  }
  fs::path resolve(const InputPath& path) {
    if (!path.generated) return path.path;
    generatedUsed.insert(path.path.string());
    return out(path.path.string());
  }
  void leaveOut(const Object& object, std::string what, std::string why) {
    plan.leftOut.push_back({object.name, std::move(what), std::move(why)});
  }
  static void option(Step& step, const json& options, const char* key, const char* flag) {
    if (!options.contains(key)) return;
    const json& value = options[key];
    step.arguments.push_back(flag);
    step.arguments.push_back(value.is_string() ? value.get<std::string>() : value.dump());
  }
  Step stepFor(const Object& object) const {
    Step step;
    step.id = std::string(bakerName(object.technique)) + ":" + object.name;
    step.tool = bakerName(object.technique);
    step.object = object.name;
    return step;
  }
  void addInput(Step& step, const fs::path& path) {
    step.arguments.push_back(path.string());
    step.inputs.push_back(path);
  }

  Status geodesic(const Object& object, Step& step) {
    addInput(step, resolve(object.input));
    const fs::path sources = resolve(*object.sources);
    step.arguments.insert(step.arguments.end(), {"--sources", sources.string()});
    step.inputs.push_back(sources);
    const std::vector<std::string> read = scene.fieldsRead(object);
    const bool global = jsonStringOr(object.options, "normalize", "") == "global";
    if (!settings.keepUnused && read.size() < object.fieldNames.size()) {
      if (global) {
        leaveOut(object, "nothing of its fields", "normalize: global divides every field by the largest of all, so all are baked");
      } else {
        std::string list;
        for (const std::string& name : object.fieldNames) {
          if (std::find(read.begin(), read.end(), name) != read.end()) {
            list += (list.empty() ? "" : ",") + name;
            continue;
          }
          leaveOut(object, "field '" + name + "'", "material '" + scene.materialOf(object).name + "' does not read it");
        }
        step.arguments.insert(step.arguments.end(), {"--fields", list});
      }
    }
    option(step, object.options, "method", "--method");
    option(step, object.options, "encoding", "--encoding");
    option(step, object.options, "normalize", "--normalize");
    step.outputs.push_back(baked(object, ".glb"));
    return {};
  }

  Status revolution(const Object& object, Step& step) {
    const Material& material = scene.materialOf(object);
    addInput(step, resolve(object.input));
    const auto texture = [&](const std::optional<InputPath>& path, bool read, const char* flag, const char* what) {
      if (!path) return false;
      if (!read && !settings.keepUnused) {
        leaveOut(object, what, "material '" + material.name + "' does not read it");
        return false;
      }
      const fs::path file = resolve(*path);
      step.arguments.insert(step.arguments.end(), {flag, file.string()});
      step.inputs.push_back(file);
      return true;
    };
    texture(object.baseColor, material.readsBaseColor, "--base-color", "base colour texture");
    if (texture(object.heightMap, material.readsDisplacement, "--height-map", "displacement map"))
      option(step, object.options, "heightScale", "--height-scale");
    option(step, object.options, "resolution", "--resolution");
    option(step, object.options, "encoding", "--encoding");
    option(step, object.options, "projection", "--projection");
    step.outputs.push_back(baked(object, ".glb"));
    return {};
  }

  // The bounding radius of the object's mesh about its origin, in object units.
  Result<double> meshRadius(const InputPath& mesh) const {
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

  // The most on-screen pixels an object unit of this object covers, over the cameras: at the least
  // depth along the view axis of its bounding sphere (formats/scene.md; a pinhole camera's scale
  // depends on the depth, not the distance). Infinite when the sphere reaches the eye's plane.
  Result<double> pixelsPerUnit(const Object& object, double radius) const {
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
      const double halfHeight = std::tan(camera.yfovDegrees * std::numbers::pi / 360.0) * nearest;
      most = std::max(most, camera.height / (2 * halfHeight) * object.scale);
    }
    return most;
  }

  Status hatching(const Object& object, Step& step) {
    const Material& material = scene.materialOf(object);
    const fs::path style = resolve(object.input);
    addInput(step, style);
    const fs::path mesh = resolve(*object.mesh);
    step.inputs.push_back(mesh);
    const fs::path package = baked(object, ".glb");
    step.arguments.insert(step.arguments.end(), {"-o", baked(object, ".ktx2").string(), "--apply-to", mesh.string(),
                                                 "--package", package.string()});
    step.outputs = {package, baked(object, ".ktx2")};
    option(step, object.options, "tilesPerUnit", "--tiles-per-unit");
    option(step, object.options, "rotation", "--rotation");
    option(step, object.options, "orientation", "--orientation");
    if (object.options.contains("baseColour")) {
      const json& c = object.options["baseColour"];
      step.arguments.insert(step.arguments.end(),
                            {"--base-colour", number(c[0].get<double>()) + "," + number(c[1].get<double>()) + "," +
                                                  number(c[2].get<double>())});
    }
    if (material.readsThreshold || settings.keepUnused) {
      const fs::path threshold = baked(object, ".threshold.ktx2");
      step.arguments.insert(step.arguments.end(), {"--threshold", threshold.string()});
      step.outputs.push_back(threshold);
    } else {
      leaveOut(object, "threshold texture", "material '" + material.name + "' does not read it");
    }
    if (settings.keepUnused) return {};
    return skipFinestLevels(object, style, step);
  }

  // The finest TAM levels no view samples: level l is kept while a texel of it covers at least
  // kKeepLevelTexelPixels pixels at the object's largest pixels per unit (formats/scene.md).
  Status skipFinestLevels(const Object& object, const fs::path& stylePath, Step& step) {
    if (!scene.pixelsPerUnit && scene.cameras.empty()) return {};
    BAKE_ASSIGN_OR_RETURN(const tam::Style style, tam::readStyle(stylePath.string(), false));
    double radius = 0;
    if (!scene.pixelsPerUnit) { BAKE_ASSIGN_OR_RETURN(radius, meshRadius(*object.mesh)); }
    BAKE_ASSIGN_OR_RETURN(const double pixels, pixelsPerUnit(object, radius));
    plan.maxPixelsPerUnit = std::max(plan.maxPixelsPerUnit, pixels);
    if (!std::isfinite(pixels)) return {};
    const double tilesPerUnit = jsonNumberOr(object.options, "tilesPerUnit", 1.0);
    const double texelsPerUnit = style.resolution * tilesPerUnit;
    int skip = 0;
    const int levels = int(std::floor(std::log2(double(style.resolution)))) + 1;
    while (skip + 1 < levels && pixels * std::ldexp(1.0, skip) / texelsPerUnit < bake::format::scene::kKeepLevelTexelPixels)
      ++skip;
    if (skip == 0) return {};
    step.arguments.insert(step.arguments.end(), {"--skip-levels", std::to_string(skip)});
    const std::string sides = std::to_string(style.resolution) +
                              (skip > 1 ? " to " + std::to_string(style.resolution >> (skip - 1)) : std::string()) + " texels";
    leaveOut(object, (skip > 1 ? "TAM levels 0-" + std::to_string(skip - 1) : std::string("TAM level 0")) + " (" + sides + ")",
             "at most " + number(std::round(pixels * 10) / 10) + " pixels per unit on screen: their texels are below " +
                 number(bake::format::scene::kKeepLevelTexelPixels) + " pixel");
    return {};
  }

  Status grooves(const Object& object, Step& step) {
    const Material& material = scene.materialOf(object);
    const fs::path input = resolve(object.input);
    addInput(step, input);
    option(step, object.options, "cellSize", "--cell-size");
    option(step, object.options, "maxCells", "--max-cells");
    step.outputs.push_back(baked(object, ".glb"));
    if (!material.readsSpecialCases && !settings.keepUnused) {
      step.arguments.push_back("--no-special-cases");
      leaveOut(object, "special-case records", "material '" + material.name + "' line-samples everywhere");
      return {};
    }
    if (object.input.generated) return {};
    // Kinds of special case the pattern does not contain: nothing of them is baked (reported).
    BAKE_ASSIGN_OR_RETURN(const groove::GrooveScene grooves, groove::readGrooveScene(input.string()));
    groove::GridSettings grid;
    // Read leniently: an option of the wrong type is the baker's to refuse when the step runs.
    grid.cellSize = jsonNumberOr(object.options, "cellSize", 0.0);
    const std::int64_t maxCells = jsonIndexOr(object.options, "maxCells");
    if (maxCells > 0) grid.maxCells = std::uint64_t(maxCells);
    BAKE_ASSIGN_OR_RETURN(const groove::GrooveGrid built, groove::buildGrooveGrid(grooves, grid));
    const groove::GridStats stats = groove::gridStats(built);
    const std::pair<const char*, std::uint64_t> kinds[] = {
        {"intersection records", stats.intersections}, {"end records", stats.ends}, {"corner records", stats.corners}};
    for (const auto& [what, count] : kinds)
      if (count == 0) leaveOut(object, what, "the pattern has none");
    return {};
  }

  Status object(const Object& object) {
    Step step = stepFor(object);
    switch (object.technique) {
      case Technique::Geodesic: BAKE_RETURN_IF_ERROR(geodesic(object, step)); break;
      case Technique::Revolution: BAKE_RETURN_IF_ERROR(revolution(object, step)); break;
      case Technique::Hatching: BAKE_RETURN_IF_ERROR(hatching(object, step)); break;
      case Technique::Grooves: BAKE_RETURN_IF_ERROR(grooves(object, step)); break;
    }
    if (object.technique != Technique::Hatching) step.arguments.insert(step.arguments.end(), {"-o", step.outputs[0].string()});
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
  Planner planner{scene, settings, {}, {}};
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
