// The bake plan of a scene (formats/scene.md): the bakeshape steps for generated inputs, one baker
// step per object with the options that leave out what no material reads, and the list of what was
// left out and why. Ninja files, Makefiles and `bakepipe plan` are views of this one plan.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "pipe/scene.h"

namespace bake::pipe {

struct PlanSettings {
  std::filesystem::path outputDirectory;  // where generated files and packages go
  bool keepUnused = false;                // leave nothing out (the full bakes, for comparison)
  std::filesystem::path cacheDirectory;   // given to every step as --cache-dir (empty: none)
};

// One tool run. Paths are absolute; `tool` is a tool name ("geobake"), resolved by whoever runs it.
struct Step {
  std::string id;    // "bakeshape:pretzel.glb", "geobake:pretzel"
  std::string tool;
  std::vector<std::string> arguments;  // after the tool name, without --depfile
  std::vector<std::filesystem::path> inputs;   // files it reads (as --print-inputs lists them)
  std::vector<std::filesystem::path> outputs;  // files it writes; the first is the main one
  std::string object;  // the object it bakes; empty for generated inputs
};

struct LeftOut {
  std::string object;
  std::string what;  // "field 'rims'", "displacement map", "TAM levels 0-1", ...
  std::string why;
};

struct Plan {
  std::vector<Step> steps;  // in an order that runs every step after the steps making its inputs
  std::vector<LeftOut> leftOut;
  // Per object (Scene::objects order): the package its step writes.
  std::vector<std::filesystem::path> packages;
  // The largest on-screen pixels per object unit over the cameras (or the scene's pixelsPerUnit).
  double maxPixelsPerUnit = 0;

  nlohmann::json toJson() const;
};

Result<Plan> makePlan(const Scene& scene, const PlanSettings& settings);

// Where a tool is: `directory`/TOOL (an installed bin directory), else `directory`/../TOOL/TOOL (the
// build tree, tools/<tool>/<tool>), else the bare name (found on PATH when run).
std::filesystem::path locateTool(const std::string& tool, const std::filesystem::path& directory);

// A POSIX-shell word: quoted when it holds anything but [A-Za-z0-9_./=:,+-].
std::string shellQuote(const std::string& word);

// The command line of a step with its tool located in `toolDirectory`, every word quoted.
std::string commandLine(const Step& step, const std::filesystem::path& toolDirectory);

}  // namespace bake::pipe
