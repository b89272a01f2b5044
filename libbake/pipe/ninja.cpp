// Ninja file writer (pipe/ninja.h). Paths are absolute, as the tools' depfiles write them, so Ninja
// matches every depfile target with the edge's outputs. One rule runs every bake step (its command
// line is a variable of the edge); restat lets an unchanged output stop the rebuild there. Commands
// never use Ninja's $in/$out, which reach the shell unquoted: each edge carries its paths shell-quoted
// (q* variables), so no file name is ever read as shell syntax.
#include "pipe/ninja.h"

#include <sstream>

#include "bake_formats/scene.h"
#include "core/build_syntax.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;

// Every path and value goes through the one escaper (core/build_syntax.h), which refuses what Ninja
// cannot hold; the first refusal stops the file.
class Escaper {
 public:
  std::string path(const fs::path& path) { return take(ninjaEscapedPath(path.string())); }
  std::string value(const std::string& text) { return take(ninjaEscapedValue(text)); }
  std::string paths(const std::vector<fs::path>& paths) {
    std::string out;
    for (const fs::path& p : paths) out += " " + path(p);
    return out;
  }
  const Status& status() const { return status_; }

 private:
  std::string take(Result<std::string> escaped) {
    if (escaped.isOk()) return *escaped;
    if (status_.isOk()) status_ = escaped.status();
    return {};
  }
  Status status_;
};

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

Result<std::string> ninjaFile(const Scene& scene, const Plan& plan, const NinjaSettings& settings) {
  Escaper e;
  const std::string bakepipe = shellQuote(settings.bakepipe.string());
  const std::string options = pipeOptions(scene, plan, settings, settings.keepUnused);
  const fs::path assembled = settings.assembled;
  const fs::path validated = fs::path(assembled.string() + ".validated");
  std::ostringstream n;
  n << "# Bake steps of the scene " << commentSafe(scene.name) << " (" << commentSafe(scene.file.string())
    << "), written by bakepipe ninja.\n"
    << "# Run: ninja -f THIS_FILE. Edit the scene, not this file: it is rewritten when the scene changes.\n"
    << "ninja_required_version = 1.10\n"
    // Ninja's log and dependency database live beside the outputs, not in whatever directory it
    // was started from.
    << "builddir = " << e.value(plan.packages.empty() ? std::string(".") : plan.packages.front().parent_path().string())
    << "\n\n"
    << "pool " << format::scene::kGlPool << "\n  depth = 1\n\n"
    << "rule bake\n  command = $cmd --depfile $quoteddep\n  depfile = $dep\n  deps = gcc\n  restat = 1\n"
    << "  description = $desc\n\n"
    << "rule assemble\n  command = " << e.value(bakepipe) << " assemble " << e.value(options)
    << " -q -o $qout --depfile $qdep\n  depfile = $out.d\n  deps = gcc\n  restat = 1\n  description = ASSEMBLE $out\n\n"
    << "rule validate\n  command = " << e.value(bakepipe) << " validate " << e.value(options)
    << " -q --package $qin && touch $qout\n  pool = " << format::scene::kGlPool << "\n  description = VALIDATE $in\n\n"
    << "rule regenerate\n  command = " << e.value(bakepipe) << " ninja " << e.value(options)
    << " -q -o $qout\n  generator = 1\n  description = REGENERATE $out\n\n";
  if (!settings.ninjaFile.empty())
    n << "build " << e.path(settings.ninjaFile) << ": regenerate " << e.path(scene.file) << "\n"
      << "  qout = " << e.value(shellQuote(settings.ninjaFile.string())) << "\n\n";
  for (const Step& step : plan.steps) {
    n << "build" << e.paths(step.outputs) << ": bake" << e.paths(step.inputs) << "\n"
      << "  cmd = " << e.value(commandLine(step, settings.toolDirectory)) << "\n"
      << "  dep = " << e.value(step.outputs.front().string() + ".d") << "\n"
      << "  quoteddep = " << e.value(shellQuote(step.outputs.front().string() + ".d")) << "\n"
      << "  desc = " << e.value(step.id) << "\n\n";
  }
  n << "build " << e.path(assembled) << ": assemble" << e.paths(plan.packages) << " | " << e.path(scene.file) << "\n"
    << "  qout = " << e.value(shellQuote(assembled.string())) << "\n"
    << "  qdep = " << e.value(shellQuote(assembled.string() + ".d")) << "\n\n"
    << "build " << e.path(validated) << ": validate " << e.path(assembled) << "\n"
    << "  qin = " << e.value(shellQuote(assembled.string())) << "\n"
    << "  qout = " << e.value(shellQuote(validated.string())) << "\n\n"
    << "build validate: phony " << e.path(validated) << "\n"
    << "default " << e.path(validated) << "\n";
  if (!e.status().isOk()) return e.status();
  return n.str();
}

}  // namespace bake::pipe
