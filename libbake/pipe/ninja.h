// Writes a plan as a Ninja file: one build edge per step with its depfile (deps = gcc) and restat, the
// scene assembly, and a `validate` edge in a pool of depth 1 (one GL context at a time). Ninja is the
// executor; regenerating the file from the scene is an edge of its own.
#pragma once

#include <filesystem>
#include <string>

#include "pipe/plan.h"
#include "pipe/scene.h"

namespace bake::pipe {

struct NinjaSettings {
  std::filesystem::path toolDirectory;  // where geobake etc. are (empty: PATH)
  std::filesystem::path bakepipe;       // this tool, for the assemble and validate edges
  std::filesystem::path assembled;      // the scene package (default: <out>/<scene>.glb)
  std::filesystem::path ninjaFile;      // the file being written: rewritten when the scene changes
  bool keepUnused = false;              // the plan was made with --keep-unused (passed on)
  std::filesystem::path cacheDirectory; // the plan's --cache-dir (passed on)
};

Result<std::string> ninjaFile(const Scene& scene, const Plan& plan, const NinjaSettings& settings);

}  // namespace bake::pipe
