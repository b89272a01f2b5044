// bakeplay: the reference runtime. `render` draws a scene headless to PNG/EXR, `validate` checks
// packages, `view` opens a window (also what bakeplay does with no command).
#include "common/cli.h"
#include "play/render.h"
#include "play/validate.h"
#include "play/view.h"

namespace {

const bake::CommonOptionSet kReportOnly = {.version = false, .report = true, .depfile = false, .threads = false,
                                           .printInputs = false};

void addViewOptions(CLI::App& command, bake::play::ViewSettings& view, std::string& size) {
  command.add_option("scenes", view.scenes, "Packages (.glb/.gltf) that together make the scene; none: the bundled example");
  command.add_option("--size", size, "Frame or window size WIDTHxHEIGHT")->type_name("WxH")->capture_default_str();
  command.add_option("--camera", view.camera, "Camera eye x,y,z or eye:target x,y,z:x,y,z (default: the file's camera, else framed)")
      ->type_name("EYE[:TARGET]");
  command.add_option("--light", view.light, "Direction towards the light X,Y,Z, or point:X,Y,Z, or spot:X,Y,Z:DX,DY,DZ:CUTOFF_DEGREES[:EXPONENT] (hatching "
                     "takes point and spot lights as they are; other techniques light from the scene's centre toward "
                     "them; default: the file's light, else upper right)")
      ->type_name("LIGHT");
  command.add_option("--environment", view.environment,
                     "Grooves: the constant radiance R,G,B that mirror bounces leaving the surface see (default black)")
      ->type_name("R,G,B");
  command.add_option("--geotexture", view.geotexture,
                     "GeoTexture preset for every primitive with geodesic fields (isolines, sand-water, moss-granite, "
                     "paint-metal-rust, water-lava, opacity-front, wave-displacement)")
      ->type_name("PRESET");
  command.add_option("--time", view.time, "Animation time in seconds (GeoTexture fronts with a speed)")->capture_default_str();
  command.add_option("--stroke-quality", view.strokeQuality,
                     "Paintstrokes: polygons across each segment, 0: 1 (flat), 1: 2, 2: 4")
      ->capture_default_str();
  command.add_option("--stroke-tolerance", view.strokeTolerance,
                     "Paintstrokes: largest screen-space deviation of the tessellation from the path and radius, in "
                     "pixels (0.01 to 1000); smaller is finer")
      ->capture_default_str();
  command.add_option("--stroke-tubes", view.strokeTubes,
                     "Paintstrokes: draw fixed tubes tessellated on the CPU instead, SIDES around and STEPS per segment "
                     "(SIDESxSTEPS, e.g. 64x32 for the fine reference, 6x2 for coarse tubes)");
  command.add_option("--hatching-tone", view.hatchingTone,
                     "Hatching: blend (the two nearest TAM layers) or threshold (fine tone control by the package's "
                     "threshold texture, Webb et al. 2002; packages without one draw the blend)")
      ->capture_default_str()
      ->check(CLI::IsMember({"blend", "threshold"}));
  command.add_option("--groove-reflections", view.grooveReflections,
                     "Grooves: environment (a mirror piece in crossings, ends and corners reflects the environment "
                     "only) or traced (its bounces followed as beams, as the CPU method; tens of times slower on "
                     "software GL such as llvmpipe)")
      ->capture_default_str()
      ->check(CLI::IsMember({"traced", "environment"}));
  command.add_option("--groove-retries", view.grooveRetries,
                     "Grooves: the most retry draws per frame for special-case pixels whose area sample a driver's "
                     "loop cap cut short (llvmpipe); a pixel they do not finish is line sampled, with a warning")
      ->capture_default_str()
      ->check(CLI::Range(0u, 10000000u));
  command.add_option("--environment-map", view.environmentMap,
                     "GeoTextures' wave-displacement preset: an equirectangular image (linear RGB, e.g. EXR) the "
                     "displaced surface reflects (seed 003 C.6.4)")
      ->type_name("FILE");
}

CLI::App* addRenderCommand(CLI::App& app, bake::play::RenderSettings& render, std::string& size) {
  CLI::App* command = app.add_subcommand("render", "Render a scene headless (EGL) to a PNG or EXR image");
  addViewOptions(*command, render.view, size);
  command->add_option("-o,--output", render.output, "Image to write (.png: sRGB 8-bit, .exr: linear half)")->required();
  command->add_option("--frames", render.frames, "Render this many frames and report median and p95 frame times");
  command->add_flag("--compare-standard", render.compareStandard,
                    "Also time the scene with every technique replaced by standard (Blinn-Phong) shading");
  bake::CommonOptionSet options = kReportOnly;
  options.depfile = true;
  bake::addCommonOptions(*command, render.common, options);
  return command;
}

CLI::App* addValidateCommand(CLI::App& app, bake::play::ValidateSettings& validate) {
  CLI::App* command = app.add_subcommand(
      "validate", "Check packages: structure, values, extensions, shader compilation, reference views (exit 3 on failure)");
  command->add_option("packages", validate.packages, "Packages to validate")->required();
  command->add_option("--golden", validate.goldens, "Expected image of each package's first reference view (one per package)");
  command->add_option("--tolerance", validate.tolerance.rmse, "Largest RMSE allowed against the golden (0..1 units)")
      ->capture_default_str();
  command->add_option("--pixel-threshold", validate.tolerance.threshold, "Channel difference that counts a pixel as off")
      ->capture_default_str();
  command->add_option("--max-off-percent", validate.tolerance.percentOver, "Largest share of off pixels allowed, in percent")
      ->capture_default_str();
  command->add_option("--views", validate.viewsDirectory, "Write the rendered reference views into this directory");
  command->add_option("--size", validate.size, "Reference view size in pixels (square)")->capture_default_str();
  bake::addCommonOptions(*command, validate.common, kReportOnly);
  return command;
}

CLI::App* addViewCommand(CLI::App& app, bake::play::WindowSettings& view, std::string& size) {
  CLI::App* command = app.add_subcommand("view", "Show a scene in a window (drag: orbit, scroll: zoom, right drag or arrows: light)");
  addViewOptions(*command, view.view, size);
  command->add_option("--screenshot", view.screenshot, "Write the window's picture (.png) after --frames frames and close");
  command->add_option("--frames", view.frames, "Frames to show before --screenshot")->capture_default_str();
  command->add_flag("-q,--quiet", view.view.quiet, "Print nothing but errors");
  return command;
}

}  // namespace

int main(int argc, char** argv) {
  bake::Diagnostics diagnostics("bakeplay");
  CLI::App app{"The reference OpenGL runtime of the bake toolchain: renders and validates packages.", "bakeplay"};
  app.set_version_flag("--version", std::string("bakeplay ") + bake::toolkitVersion());
  app.require_subcommand(0, 1);  // no command: view the bundled example scene

  bake::play::RenderSettings render;
  bake::play::ValidateSettings validate;
  bake::play::WindowSettings view;
  std::string renderSize = "512x512", viewSize = "960x720";
  CLI::App* renderCommand = addRenderCommand(app, render, renderSize);
  CLI::App* validateCommand = addValidateCommand(app, validate);
  addViewCommand(app, view, viewSize);

  return bake::runTool(app, diagnostics, argc, argv, [&]() -> bake::Status {
    if (renderCommand->parsed()) {
      diagnostics.setQuiet(render.common.quiet);
      BAKE_RETURN_IF_ERROR(bake::play::parseSize(renderSize, render.view));
      return bake::play::runRender(render, diagnostics);
    }
    if (validateCommand->parsed()) {
      diagnostics.setQuiet(validate.common.quiet);
      return bake::play::runValidate(validate, diagnostics);
    }
    diagnostics.setQuiet(view.view.quiet);
    BAKE_RETURN_IF_ERROR(bake::play::parseSize(viewSize, view.view));
    return bake::play::runView(view, diagnostics);
  });
}
