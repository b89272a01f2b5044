// The bakepipe commands behind tools/bakepipe: plan, ninja, assemble, validate. Each reads the scene,
// makes the plan and acts on it; the tool only parses options into these settings.
#pragma once

#include <filesystem>
#include <string>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"

namespace bake::pipe {

struct PipeSettings {
  std::filesystem::path scene;
  std::filesystem::path outputDirectory;  // default: out/<scene name> beside the current directory
  std::filesystem::path toolDirectory;    // default: the directory bakepipe runs from
  bool keepUnused = false;
  std::filesystem::path cacheDirectory;  // passed to every bake step as --cache-dir
  CommonOptions common;
};

struct PlanCommand {
  PipeSettings pipe;
  bool json = false;  // print the plan as JSON instead of text
};

struct NinjaCommand {
  PipeSettings pipe;
  std::filesystem::path output;  // build.ninja
};

struct AssembleCommand {
  PipeSettings pipe;
  std::filesystem::path output;  // the scene package (.glb)
};

struct ValidateCommand {
  PipeSettings pipe;
  std::filesystem::path package;  // default: the assembled package of the plan
};

Status runPlanCommand(const PlanCommand& command, Diagnostics& diagnostics);
Status runNinjaCommand(const NinjaCommand& command, Diagnostics& diagnostics);
Status runAssembleCommand(const AssembleCommand& command, Diagnostics& diagnostics);
Status runValidateCommand(const ValidateCommand& command, Diagnostics& diagnostics);

// The default output directory of a scene: <current directory>/out/<scene name>.
std::filesystem::path defaultOutputDirectory(const std::string& sceneName);
// The default assembled package: <output directory>/<scene name>.glb.
std::filesystem::path defaultAssembledPackage(const std::filesystem::path& outputDirectory, const std::string& sceneName);

}  // namespace bake::pipe
