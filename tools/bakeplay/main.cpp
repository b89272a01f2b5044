// bakeplay: the reference runtime. `render` draws a scene headless to PNG/EXR; more commands below.
#include "core/cli.h"
#include "play/render.h"

namespace {

void addViewOptions(CLI::App& command, bake::play::ViewSettings& view, std::string& size) {
  command.add_option("scenes", view.scenes, "Packages (.glb/.gltf) that together make the scene; none: the bundled example");
  command.add_option("--size", size, "Frame size WIDTHxHEIGHT")->default_str("512x512");
  command.add_option("--camera", view.camera, "Camera eye x,y,z or eye:target x,y,z:x,y,z (default: the file's camera, else framed)");
  command.add_option("--light", view.light, "Direction towards the light x,y,z (default: the file's light, else upper right)");
}

}  // namespace

int main(int argc, char** argv) {
  bake::Diagnostics diagnostics("bakeplay");
  CLI::App app{"The reference OpenGL runtime of the bake toolchain: renders and validates packages.", "bakeplay"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("bakeplay ") + bake::toolkitVersion());

  bake::play::RenderSettings render;
  std::string renderSize = "512x512";
  CLI::App* renderCommand = app.add_subcommand("render", "Render a scene headless (EGL) to a PNG or EXR image");
  addViewOptions(*renderCommand, render.view, renderSize);
  renderCommand->add_option("-o,--output", render.output, "Image to write (.png: sRGB 8-bit, .exr: linear half)")->required();
  renderCommand->add_option("--frames", render.frames, "Render this many frames and report median and p95 frame times");
  bake::addCommonOptions(*renderCommand, render.common, {.version = false, .report = true, .depfile = true, .threads = false, .printInputs = false});

  return bake::runTool(app, diagnostics, argc, argv, [&]() -> bake::Status {
    if (renderCommand->parsed()) {
      diagnostics.setQuiet(render.common.quiet);
      BAKE_RETURN_IF_ERROR(bake::play::parseSize(renderSize, render.view));
      return bake::play::runRender(render, diagnostics);
    }
    return bake::usageError("no command given");
  });
}
