// bakeinfo: describes packages (.glb/.gltf with BAKE_* extensions, .ktx2) as text or JSON.
#include <cstdio>

#include "bake/info/bakeinfo.h"
#include "common/cli.h"

int main(int argc, char** argv) {
  bake::info::Settings settings;
  bake::Diagnostics diagnostics("bakeinfo");
  CLI::App app{"Describes bake packages: glTF summary, attributes and their ranges, extensions and their\n"
               "versions (.glb/.gltf), or format, layers, levels and metadata (.ktx2).",
               "bakeinfo"};
  app.add_option("files", settings.files, "Packages to describe (.glb, .gltf, .ktx2)")->required();
  app.add_flag("--json", settings.json, "Print one JSON document (an array when several files are given)");
  bake::addCommonOptions(app, settings.common, {.version = true, .report = false, .depfile = false, .threads = false,
                                                .printInputs = false});
  return bake::runTool(app, diagnostics, argc, argv, [&] {
    diagnostics.setQuiet(settings.common.quiet);
    return bake::info::run(settings, diagnostics);
  });
}
