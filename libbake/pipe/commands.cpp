// The bakepipe commands (pipe/commands.h): each reads the scene, makes the plan and prints it, writes
// it as Ninja, assembles the packages it names, or runs bakeplay validate on the result.
#include "bake/pipe/commands.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <set>
#include <unistd.h>

#include "bake/core/atomic_file.h"
#include "bake/core/session.h"
#include "bake/io/glb.h"
#include "core/output_plan.h"
#include "pipe/assemble.h"
#include "pipe/ninja.h"
#include "pipe/plan.h"
#include "pipe/scene.h"

extern char** environ;

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;

// The directory this process runs from (/proc/self/exe), where its sibling tools are.
fs::path ownDirectory() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

fs::path toolDirectoryOf(const PipeSettings& settings) {
  return settings.toolDirectory.empty() ? ownDirectory() : fs::absolute(settings.toolDirectory);
}

struct Loaded {
  Scene scene;
  Plan plan;
};

Result<Loaded> load(const PipeSettings& settings) {
  Loaded loaded;
  BAKE_ASSIGN_OR_RETURN(loaded.scene, readScene(settings.scene));
  PlanSettings planSettings;
  planSettings.outputDirectory = settings.outputDirectory.empty() ? defaultOutputDirectory(loaded.scene.name)
                                                                  : fs::absolute(settings.outputDirectory);
  planSettings.keepUnused = settings.keepUnused;
  if (!settings.cacheDirectory.empty()) planSettings.cacheDirectory = fs::absolute(settings.cacheDirectory);
  BAKE_ASSIGN_OR_RETURN(loaded.plan, makePlan(loaded.scene, planSettings));
  return loaded;
}

void printPlan(const Scene& scene, const Plan& plan, const fs::path& toolDirectory) {
  std::printf("# scene %s: %zu objects, %zu steps\n", scene.name.c_str(), scene.objects.size(), plan.steps.size());
  for (const Step& step : plan.steps) std::printf("%s\n", commandLine(step, toolDirectory).c_str());
  if (plan.leftOut.empty()) {
    std::printf("# left out: nothing\n");
    return;
  }
  std::printf("# left out:\n");
  for (const LeftOut& item : plan.leftOut)
    std::printf("#   %s: %s (%s)\n", item.object.c_str(), item.what.c_str(), item.why.c_str());
}

// Runs argv and waits; the child's exit status, or an I/O error when it cannot start.
Result<int> runProcess(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    return ioError("cannot run " + arguments[0]);
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return ioError("lost the process of " + arguments[0]);
  if (WIFSIGNALED(status)) return internalError(arguments[0] + " was killed by signal " + std::to_string(WTERMSIG(status)));
  return WEXITSTATUS(status);
}

}  // namespace

fs::path defaultOutputDirectory(const std::string& sceneName) { return fs::current_path() / "out" / sceneName; }

fs::path defaultAssembledPackage(const fs::path& outputDirectory, const std::string& sceneName) {
  return outputDirectory / (sceneName + ".glb");
}

Status runPlanCommand(const PlanCommand& command, Diagnostics&) {
  BAKE_ASSIGN_OR_RETURN(const Loaded loaded, load(command.pipe));
  if (command.json) {
    std::printf("%s\n", loaded.plan.toJson().dump(2).c_str());
    return {};
  }
  printPlan(loaded.scene, loaded.plan, toolDirectoryOf(command.pipe));
  return {};
}

Status runNinjaCommand(const NinjaCommand& command, Diagnostics& diagnostics) {
  BAKE_ASSIGN_OR_RETURN(const Loaded loaded, load(command.pipe));
  if (command.pipe.common.printInputs) {
    std::printf("%s\n", loaded.scene.file.c_str());
    return {};
  }
  NinjaSettings settings;
  settings.toolDirectory = toolDirectoryOf(command.pipe);
  settings.bakepipe = locateTool("bakepipe", settings.toolDirectory);
  settings.assembled = defaultAssembledPackage(loaded.plan.packages.front().parent_path(), loaded.scene.name);
  settings.ninjaFile = fs::absolute(command.output).lexically_normal();
  settings.keepUnused = command.pipe.keepUnused;
  if (!command.pipe.cacheDirectory.empty()) settings.cacheDirectory = fs::absolute(command.pipe.cacheDirectory);
  // The Ninja file must not replace anything the build it describes reads (each file once: thousands
  // of objects often share a few inputs).
  RunFiles files{{loaded.scene.file.string()}, {command.output.empty() ? std::string() : fs::absolute(command.output).string()}};
  std::set<std::string> stepInputs;
  for (const Step& step : loaded.plan.steps) {
    for (const fs::path& path : step.inputs) stepInputs.insert(path.lexically_normal().string());
  }
  files.inputs.insert(files.inputs.end(), stepInputs.begin(), stepInputs.end());
  const OutputPlanScope planScope;
  BAKE_RETURN_IF_ERROR(planOutputs(files, command.pipe.common));
  BakeSession session("bakepipe", command.pipe.common, diagnostics);
  session.addInput(loaded.scene.file);
  BAKE_ASSIGN_OR_RETURN(const std::string text, ninjaFile(loaded.scene, loaded.plan, settings));
  const std::vector<std::uint8_t> bytes(text.begin(), text.end());
  return session.finish(session.stageOutput(fs::absolute(command.output), bytes));
}

Status runAssembleCommand(const AssembleCommand& command, Diagnostics& diagnostics) {
  BAKE_ASSIGN_OR_RETURN(const Loaded loaded, load(command.pipe));
  if (command.pipe.common.printInputs) {
    std::printf("%s\n", loaded.scene.file.c_str());
    for (const fs::path& package : loaded.plan.packages) std::printf("%s\n", package.c_str());
    return {};
  }
  if (loaded.plan.packages.empty()) return invalidInput("the scene has no objects to assemble", {loaded.scene.file.string(), ""});
  const fs::path output = command.output.empty()
                              ? defaultAssembledPackage(loaded.plan.packages.front().parent_path(), loaded.scene.name)
                              : fs::absolute(command.output);
  const OutputPlanScope planScope;
  {
    RunFiles files{{loaded.scene.file.string()}, {output.string()}};
    for (const fs::path& package : loaded.plan.packages) files.inputs.push_back(package.string());
    BAKE_RETURN_IF_ERROR(planOutputs(files, command.pipe.common));
  }
  BakeSession session("bakepipe", command.pipe.common, diagnostics);
  const auto body = [&]() -> Status {
    session.addInput(loaded.scene.file);
    for (const fs::path& package : loaded.plan.packages) session.addInput(package);
    AssembleSettings settings;
    settings.keepUnused = command.pipe.keepUnused;
    AssembleReport report;
    BAKE_ASSIGN_OR_RETURN(const glb::Package package, assemble(loaded.scene, loaded.plan.packages, settings, &report));
    BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, glb::encode(package));
    for (const std::string& item : report.dropped) diagnostics.info("left out " + item);
    for (const std::string& item : report.kept) diagnostics.info("kept " + item);
    session.report().setStatistic("dropped", report.dropped);
    session.report().setStatistic("kept", report.kept);
    session.report().setStatistic("inputBytes", report.inputBytes);
    session.report().setStatistic("outputBytes", bytes.size());
    return session.stageOutput(output, bytes);
  };
  return session.finish(body());
}

Status runValidateCommand(const ValidateCommand& command, Diagnostics&) {
  BAKE_ASSIGN_OR_RETURN(const Loaded loaded, load(command.pipe));
  const fs::path package = command.package.empty()
                               ? defaultAssembledPackage(loaded.plan.packages.front().parent_path(), loaded.scene.name)
                               : command.package;
  const fs::path bakeplay = locateTool("bakeplay", toolDirectoryOf(command.pipe));
  std::vector<std::string> arguments{bakeplay.string(), "validate"};
  if (command.pipe.common.quiet) arguments.push_back("-q");
  arguments.push_back(package.string());
  BAKE_ASSIGN_OR_RETURN(const int code, runProcess(arguments));
  if (code != 0) {
    const ExitCode exit = code >= 1 && code <= int(ExitCode::Unsupported) ? ExitCode(code) : ExitCode::Internal;
    return Status(exit, "bakeplay validate failed on " + package.string());
  }
  return {};
}

}  // namespace bake::pipe
