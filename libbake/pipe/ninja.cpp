// Ninja file writer (pipe/ninja.h). Paths are absolute, as the tools' depfiles write them, so Ninja
// matches every depfile target with the edge's outputs. One rule runs every bake step (its command
// line is a variable of the edge); restat lets an unchanged output stop the rebuild there.
#include "pipe/ninja.h"

#include <sstream>

#include "bake_formats/scene.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;

// A path in a build statement: '$', ' ', ':' and newlines are escaped with '$'.
std::string ninjaPath(const fs::path& path) {
  std::string out;
  for (const char c : path.string()) {
    if (c == '$' || c == ' ' || c == ':' || c == '\n') out += '$';
    out += c;
  }
  return out;
}

// A variable value: only '$' and newlines need escaping.
std::string ninjaValue(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '$' || c == '\n') out += '$';
    out += c;
  }
  return out;
}

std::string joinPaths(const std::vector<fs::path>& paths) {
  std::string out;
  for (const fs::path& p : paths) out += " " + ninjaPath(p);
  return out;
}

// The options that make bakepipe plan the same steps again (for assemble, validate, regenerate).
std::string pipeOptions(const Scene& scene, const Plan& plan, const NinjaSettings& settings, bool keepUnused) {
  std::string line = shellQuote(scene.file.string());
  if (!plan.packages.empty()) line += " --out-dir " + shellQuote(plan.packages.front().parent_path().string());
  if (!settings.toolDirectory.empty()) line += " --tools " + shellQuote(settings.toolDirectory.string());
  if (keepUnused) line += " --keep-unused";
  if (!settings.cacheDirectory.empty()) line += " --cache-dir " + shellQuote(settings.cacheDirectory.string());
  return line;
}

}  // namespace

std::string ninjaFile(const Scene& scene, const Plan& plan, const NinjaSettings& settings) {
  const std::string bakepipe = shellQuote(settings.bakepipe.string());
  const std::string options = pipeOptions(scene, plan, settings, settings.keepUnused);
  const fs::path assembled = settings.assembled;
  const fs::path validated = fs::path(assembled.string() + ".validated");
  std::ostringstream n;
  n << "# Bake steps of the scene " << scene.name << " (" << scene.file.string() << "), written by bakepipe ninja.\n"
    << "# Run: ninja -f THIS_FILE. Edit the scene, not this file: it is rewritten when the scene changes.\n"
    << "ninja_required_version = 1.10\n"
    // Ninja's log and dependency database live beside the outputs, not in whatever directory it
    // was started from.
    << "builddir = " << ninjaValue(plan.packages.empty() ? std::string(".") : plan.packages.front().parent_path().string())
    << "\n\n"
    << "pool " << format::scene::kGlPool << "\n  depth = 1\n\n"
    << "rule bake\n  command = $cmd --depfile $quoteddep\n  depfile = $dep\n  deps = gcc\n  restat = 1\n"
    << "  description = $desc\n\n"
    << "rule assemble\n  command = " << ninjaValue(bakepipe) << " assemble " << ninjaValue(options)
    << " -q -o $out --depfile $out.d\n  depfile = $out.d\n  deps = gcc\n  restat = 1\n  description = ASSEMBLE $out\n\n"
    << "rule validate\n  command = " << ninjaValue(bakepipe) << " validate " << ninjaValue(options)
    << " -q --package $in && touch $out\n  pool = " << format::scene::kGlPool << "\n  description = VALIDATE $in\n\n"
    << "rule regenerate\n  command = " << ninjaValue(bakepipe) << " ninja " << ninjaValue(options)
    << " -q -o $out\n  generator = 1\n  description = REGENERATE $out\n\n";
  if (!settings.ninjaFile.empty())
    n << "build " << ninjaPath(settings.ninjaFile) << ": regenerate " << ninjaPath(scene.file) << "\n\n";
  for (const Step& step : plan.steps) {
    n << "build" << joinPaths(step.outputs) << ": bake" << joinPaths(step.inputs) << "\n"
      << "  cmd = " << ninjaValue(commandLine(step, settings.toolDirectory)) << "\n"
      << "  dep = " << ninjaValue(step.outputs.front().string() + ".d") << "\n"
      << "  quoteddep = " << ninjaValue(shellQuote(step.outputs.front().string() + ".d")) << "\n"
      << "  desc = " << ninjaValue(step.id) << "\n\n";
  }
  n << "build " << ninjaPath(assembled) << ": assemble" << joinPaths(plan.packages) << " | " << ninjaPath(scene.file)
    << "\n\n"
    << "build " << ninjaPath(validated) << ": validate " << ninjaPath(assembled) << "\n\n"
    << "build validate: phony " << ninjaPath(validated) << "\n"
    << "default " << ninjaPath(validated) << "\n";
  return n.str();
}

}  // namespace bake::pipe
