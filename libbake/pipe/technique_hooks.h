// What the scene pipeline needs of a technique beyond its registry row (techniques/registry.h): what
// its objects and materials may say in a scene file (formats/scene.md), the baker step that bakes one
// object with what the object's material does not read left out, and how its packages are assembled.
// Each technique's module defines its hooks (<module>/pipe/plan.cpp, <module>/pipe/assemble.cpp) and
// its registry row points at them; a technique without hooks is not offered in scene files.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "core/json_keys.h"
#include "pipe/plan.h"
#include "pipe/scene.h"

namespace bake::pipe {

namespace detail {
struct TechniqueRules;  // pipe/assemble_parts.h
}

// The scene file's strict reader, as the scene reader and the techniques' hooks use it: every error
// names the scene file and the JSON pointer of the element; input paths resolve against the scene's
// folder or name one of its generated files.
struct SceneReader : JsonReader {
  std::filesystem::path directory;
  const std::set<std::string>* generatedOutputs = nullptr;

  Status required(const nlohmann::json& node, const std::string& where, std::initializer_list<const char*> keys) const;
  Result<double> positive(const nlohmann::json& node, const std::string& where) const;
  Result<int> integer(const nlohmann::json& node, const std::string& where, int lowest, int highest) const;
  Result<bool> boolean(const nlohmann::json& node, const std::string& where) const;
  Result<std::array<double, 3>> vec3(const nlohmann::json& node, const std::string& where) const;
  Result<std::array<double, 4>> rotation(const nlohmann::json& node, const std::string& where) const;
  // Names become file names and node names: letters, digits, '-' and '_'.
  Result<std::string> name(const nlohmann::json& node, const std::string& where) const;
  Result<InputPath> path(const nlohmann::json& node, const std::string& where) const;
};

// The planner as a technique's plan hook sees it: the scene and the settings, the plan's output
// paths, and what a hook may add (inputs, options, the list of what was left out and why).
struct ObjectPlanner {
  const Scene& scene;
  const PlanSettings& settings;
  Plan plan;
  std::set<std::string> generatedUsed;  // generated outputs a kept step reads

  std::filesystem::path out(const std::string& name) const { return settings.outputDirectory / name; }
  // The files of an object's bake: OBJECT.TECHNIQUE.EXTENSION (formats/scene.md, "Paths").
  std::filesystem::path baked(const Object& object, const std::string& extension) const;
  // An input's path; a generated one is marked used, so its bakeshape step is planned.
  std::filesystem::path resolve(const InputPath& path);
  void leaveOut(const Object& object, std::string what, std::string why);
  // The input as the step's next positional argument, and among its inputs.
  void addInput(Step& step, const std::filesystem::path& path);
  // `flag VALUE` when the object's options give `key` (strings as they are, other values as JSON).
  static void option(Step& step, const nlohmann::json& options, const char* key, const char* flag);
  // A number as JSON writes it (the shortest text that reads back the same double).
  static std::string number(double x);
  // The bounding radius of a mesh about its origin, in object units (a generated one is made).
  Result<double> meshRadius(const InputPath& mesh) const;
  // The most on-screen pixels an object unit covers over the cameras (or the scene's pixelsPerUnit);
  // infinite when the object's bounding sphere reaches a camera's eye plane.
  Result<double> pixelsPerUnit(const Object& object, double radius) const;
};

// A material's "reads" flag: its key in the scene file and the Material member it sets.
struct ReadsFlag {
  const char* key;
  bool Material::*value;
};

struct TechniqueHooks {
  // The scene file. Keys an object's "options" may hold:
  std::vector<const char*> optionKeys = {};
  // Object keys only this technique's objects may carry, and their reader (checks and fills `object`).
  std::vector<const char*> objectKeys = {};
  Status (*readObject)(const SceneReader& reader, const nlohmann::json& node, const std::string& where,
                       Object& object) = nullptr;
  // Material keys only this technique's materials may carry (besides "reads"), and their reader.
  std::vector<const char*> materialKeys = {};
  Status (*readMaterial)(const SceneReader& reader, const nlohmann::json& node, const std::string& where,
                         Material& material) = nullptr;
  // The material's "reads" flags.
  std::vector<ReadsFlag> reads = {};

  // The plan: the step's arguments, inputs and outputs (the first output is the object's package),
  // with what the object's material does not read left out unless settings.keepUnused.
  Status (*plan)(ObjectPlanner& planner, const Object& object, Step& step) = nullptr;
  // Whether the planner ends the step with `-o` and the package (false: the hook names its outputs).
  bool outputOption = true;

  // How its packages are assembled (pipe/assemble_parts.h).
  const detail::TechniqueRules* assemble = nullptr;
};

// A JSON file beside the scene (a sources file, ...), parsed; `what` names it in the error when it
// cannot be read ("sources file").
Result<nlohmann::json> readJsonFile(const std::filesystem::path& path, const std::string& what);

// The hooks of the technique named so in the registry; null when there is no such technique or it
// has none.
const TechniqueHooks* hooksOf(std::string_view technique);
// The names of the techniques a scene file may use, in registry order.
std::vector<std::string> sceneTechniques();

}  // namespace bake::pipe
