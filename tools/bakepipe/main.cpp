// bakepipe: bakes only what a scene needs (formats/scene.md). `plan` prints the bake steps and what
// they leave out, `ninja` writes them as a Ninja file, `assemble` merges the baked packages into one
// scene package, `validate` runs bakeplay validate on it.
#include "bake/pipe/commands.h"
#include "common/cli.h"

namespace {

const bake::CommonOptionSet kNoOutputs = {.version = false, .report = false, .depfile = false, .threads = false,
                                          .printInputs = false};
const bake::CommonOptionSet kOutputs = {.version = false, .report = true, .depfile = true, .threads = false,
                                        .printInputs = true};

void addPipeOptions(CLI::App& command, bake::pipe::PipeSettings& pipe) {
  command.add_option("scene", pipe.scene, "Scene description (.json, formats/scene.schema.json)")->required();
  command.add_option("--out-dir", pipe.outputDirectory, "Where baked packages and generated files go (default: out/SCENE)");
  command.add_option("--tools", pipe.toolDirectory,
                     "Directory of the bakers (default: bakepipe's own; the build tree's tools/<tool>/ also works)");
  command.add_flag("--keep-unused", pipe.keepUnused, "Leave nothing out: full bakes, every baked part assembled");
  command.add_option("--cache-dir", pipe.cacheDirectory,
                     "Give every bake step this content-addressed cache (--cache-dir of the bakers)");
}

}  // namespace

int main(int argc, char** argv) {
  bake::Diagnostics diagnostics("bakepipe");
  CLI::App app{"Bakes only what a scene needs: plans the bake steps of a scene description with the options\n"
               "that leave out what no material reads, writes them as a Ninja file, merges the baked\n"
               "packages into one scene package and validates it with bakeplay.",
               "bakepipe"};
  app.set_version_flag("--version", std::string("bakepipe ") + bake::toolkitVersion());
  app.require_subcommand(1, 1);

  bake::pipe::PlanCommand plan;
  CLI::App* planCommand = app.add_subcommand("plan", "Print the bake steps the scene needs and what they leave out");
  addPipeOptions(*planCommand, plan.pipe);
  planCommand->add_flag("--json", plan.json, "Print the plan as JSON");
  bake::addCommonOptions(*planCommand, plan.pipe.common, kNoOutputs);

  bake::pipe::NinjaCommand ninja;
  CLI::App* ninjaCommand = app.add_subcommand("ninja", "Write the plan as a Ninja file (depfiles, restat, a GL pool)");
  addPipeOptions(*ninjaCommand, ninja.pipe);
  ninjaCommand->add_option("-o,--output", ninja.output, "Ninja file to write (build.ninja)")->required();
  bake::addCommonOptions(*ninjaCommand, ninja.pipe.common, kOutputs);

  bake::pipe::AssembleCommand assemble;
  CLI::App* assembleCommand =
      app.add_subcommand("assemble", "Merge the baked packages into one scene package without the unused parts");
  addPipeOptions(*assembleCommand, assemble.pipe);
  assembleCommand->add_option("-o,--output", assemble.output, "Scene package to write (default: OUT-DIR/SCENE.glb)");
  bake::addCommonOptions(*assembleCommand, assemble.pipe.common, kOutputs);

  bake::pipe::ValidateCommand validate;
  CLI::App* validateCommand = app.add_subcommand("validate", "Run bakeplay validate on the assembled scene package");
  addPipeOptions(*validateCommand, validate.pipe);
  validateCommand->add_option("--package", validate.package, "Package to validate (default: OUT-DIR/SCENE.glb)");
  bake::addCommonOptions(*validateCommand, validate.pipe.common, kNoOutputs);

  return bake::runTool(app, diagnostics, argc, argv, [&]() -> bake::Status {
    if (planCommand->parsed()) return bake::pipe::runPlanCommand(plan, diagnostics);
    if (ninjaCommand->parsed()) {
      diagnostics.setQuiet(ninja.pipe.common.quiet);
      return bake::pipe::runNinjaCommand(ninja, diagnostics);
    }
    if (assembleCommand->parsed()) {
      diagnostics.setQuiet(assemble.pipe.common.quiet);
      return bake::pipe::runAssembleCommand(assemble, diagnostics);
    }
    diagnostics.setQuiet(validate.pipe.common.quiet);
    return bake::pipe::runValidateCommand(validate, diagnostics);
  });
}
