// bakeplay: the reference runtime. `render` draws a scene headless to PNG/EXR; more commands below.
#include "core/cli.h"
#include "play/render.h"
#include "play/validate.h"
#include "play/view.h"

namespace {

void addViewOptions(CLI::App& command, bake::play::ViewSettings& view, std::string& size) {
  command.add_option("scenes", view.scenes, "Packages (.glb/.gltf) that together make the scene; none: the bundled example");
  command.add_option("--size", size, "Frame or window size WIDTHxHEIGHT")->capture_default_str();
  command.add_option("--camera", view.camera, "Camera eye x,y,z or eye:target x,y,z:x,y,z (default: the file's camera, else framed)");
  command.add_option("--light", view.light, "Direction towards the light x,y,z (default: the file's light, else upper right)");
}

}  // namespace

int main(int argc, char** argv) {
  bake::Diagnostics diagnostics("bakeplay");
  CLI::App app{"The reference OpenGL runtime of the bake toolchain: renders and validates packages.", "bakeplay"};
  app.require_subcommand(0, 1);  // no command: view the bundled example scene
  app.set_version_flag("--version", std::string("bakeplay ") + bake::toolkitVersion());

  bake::play::RenderSettings render;
  std::string renderSize = "512x512";
  CLI::App* renderCommand = app.add_subcommand("render", "Render a scene headless (EGL) to a PNG or EXR image");
  addViewOptions(*renderCommand, render.view, renderSize);
  renderCommand->add_option("-o,--output", render.output, "Image to write (.png: sRGB 8-bit, .exr: linear half)")->required();
  renderCommand->add_option("--frames", render.frames, "Render this many frames and report median and p95 frame times");
  bake::addCommonOptions(*renderCommand, render.common, {.version = false, .report = true, .depfile = true, .threads = false, .printInputs = false});

  bake::play::ValidateSettings validate;
  CLI::App* validateCommand = app.add_subcommand(
      "validate", "Check packages: structure, values, extensions, shader compilation, reference views (exit 3 on failure)");
  validateCommand->add_option("packages", validate.packages, "Packages to validate")->required();
  validateCommand->add_option("--golden", validate.goldens, "Expected image of each package's first reference view (one per package)");
  validateCommand->add_option("--tolerance", validate.tolerance.rmse, "Largest RMSE allowed against the golden (0..1 units)")
      ->default_val(validate.tolerance.rmse);
  validateCommand->add_option("--pixel-threshold", validate.tolerance.threshold, "Channel difference that counts a pixel as off")
      ->default_val(validate.tolerance.threshold);
  validateCommand->add_option("--max-off-percent", validate.tolerance.percentOver, "Largest share of off pixels allowed, in percent")
      ->default_val(validate.tolerance.percentOver);
  validateCommand->add_option("--views", validate.viewsDirectory, "Write the rendered reference views into this directory");
  validateCommand->add_option("--size", validate.size, "Reference view size in pixels (square)")->default_val(validate.size);
  bake::addCommonOptions(*validateCommand, validate.common, {.version = false, .report = true, .depfile = false, .threads = false, .printInputs = false});

  bake::play::WindowSettings view;
  std::string viewSize = "960x720";
  CLI::App* viewCommand = app.add_subcommand("view", "Show a scene in a window (drag: orbit, scroll: zoom, right drag or arrows: light)");
  addViewOptions(*viewCommand, view.view, viewSize);
  viewCommand->add_option("--screenshot", view.screenshot, "Write the window's picture (.png) after --frames frames and close");
  viewCommand->add_option("--frames", view.frames, "Frames to show before --screenshot")->default_val(view.frames);
  viewCommand->add_flag("-q,--quiet", view.view.quiet, "Print nothing but errors");

  return bake::runTool(app, diagnostics, argc, argv, [&]() -> bake::Status {
    if (viewCommand->parsed() || app.get_subcommands().empty()) {
      diagnostics.setQuiet(view.view.quiet);
      BAKE_RETURN_IF_ERROR(bake::play::parseSize(viewSize, view.view));
      return bake::play::runView(view, diagnostics);
    }
    if (validateCommand->parsed()) {
      diagnostics.setQuiet(validate.common.quiet);
      return bake::play::runValidate(validate, diagnostics);
    }
    if (renderCommand->parsed()) {
      diagnostics.setQuiet(render.common.quiet);
      BAKE_RETURN_IF_ERROR(bake::play::parseSize(renderSize, render.view));
      return bake::play::runRender(render, diagnostics);
    }
    return bake::internalError("unhandled command");
  });
}
