#include "play/render.h"

#include <GL/glcorearb.h>
#include <bake_formats/tam.h>
#include <bake_formats/geodesic.h>
#include <bake_formats/grooves.h>
#include <bake_formats/paintstrokes.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bake/core/session.h"
#include "bake/core/vector_text.h"
#include "bake/io/image.h"
#include "core/output_plan.h"
#include "core/path.h"
#include "gl/context.h"
#include "render/geodesic.h"
#include "render/grooves.h"
#include "render/hatching.h"
#include "render/paintstrokes.h"
#include "render/renderer.h"
#include "render/standard.h"
#include "render/target.h"
#include "scene/scene.h"

namespace bake::play {
namespace {

FrameContext frameContext(const Scene& scene, const Camera& camera, const Light& light, const ViewSettings& view) {
  const float aspect = float(view.width) / float(view.height);
  return {scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
          perspective(camera.yfov, aspect, camera.znear, camera.zfar), view.width, view.height, view.time};
}

struct FrameTimes {
  std::vector<double> gpuMs, cpuMs;
};

// Draws `frames` frames after one untimed warm-up frame (drivers compile lazily on first draw),
// timing each on the GPU (timer query) and on the CPU (until the GPU is done). A GPU time longer than
// the wall time around it is impossible; when a driver reports one, the GPU times are dropped.
FrameTimes renderFrames(SceneRenderer& renderer, const FrameContext& frame, int frames) {
  FrameTimes times;
  renderer.drawFrame(frame);
  glFinish();
  GLuint query = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &query);
  bool plausible = true;
  for (int f = 0; f < frames; ++f) {
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query);
    renderer.drawFrame(frame);
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &nanoseconds);  // waits for the frame to finish
    times.cpuMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    times.gpuMs.push_back(double(nanoseconds) * 1e-6);
    plausible = plausible && times.gpuMs.back() <= times.cpuMs.back() * 1.01 + 0.01;
  }
  glDeleteQueries(1, &query);
  if (!plausible) times.gpuMs.clear();
  return times;
}

nlohmann::json timingJson(const std::vector<double>& samples) {
  if (samples.empty()) return nullptr;  // not measured (timer queries unreliable on this driver)
  const Percentiles p = percentiles(samples);
  return {{"medianMs", p.median}, {"p95Ms", p.p95}, {"frames", samples.size()}};
}

Status renderScene(const RenderSettings& settings, BakeSession& session) {
  const std::string extension = lowercaseExtension(settings.output);
  if (extension != ".png" && extension != ".exr") {
    return usageError("output " + settings.output + " must end in .png or .exr");
  }
  for (const std::string& file : settings.view.scenes) session.addInput(file);
  StageTimer loadTimer(&session.report(), "load");
  BAKE_ASSIGN_OR_RETURN(const ViewSetup setup, setUpView(settings.view, session.diagnostics()));
  loadTimer.stop();
  const Scene& scene = setup.scene;
  BAKE_ASSIGN_OR_RETURN(std::unique_ptr<gl::Context> context, gl::createHeadlessContext());
  gl::ShaderLibrary shaders;
  StageTimer prepareTimer(&session.report(), "prepare");
  BAKE_ASSIGN_OR_RETURN(const RendererRegistry registry, renderersFor(settings.view));
  BAKE_ASSIGN_OR_RETURN(SceneRenderer renderer, SceneRenderer::create(scene, registry, shaders));
  BAKE_ASSIGN_OR_RETURN(OffscreenTarget target, OffscreenTarget::create(settings.view.width, settings.view.height));
  prepareTimer.stop();

  const FrameContext frame = frameContext(scene, setup.camera, setup.light, settings.view);
  StageTimer renderTimer(&session.report(), "render");
  target.bind();
  const FrameTimes times = renderFrames(renderer, frame, settings.frames);
  const Image image = target.readLinearRgba();
  renderTimer.stop();
  session.report().setStatistic("techniques", renderer.techniques());
  session.report().setStatistic("gpuBytes", renderer.gpuBytes());
  session.report().setStatistic("shaderVariants", shaders.compiledVariants());
  session.report().setStatistic("renderer", context->renderer());
  session.report().setStatistic("glVersion", context->version());
  session.report().setStatistic("size", {settings.view.width, settings.view.height});
  session.report().setStatistic("frameTimeGpu", timingJson(times.gpuMs));
  session.report().setStatistic("frameTimeCpu", timingJson(times.cpuMs));
  // What techniques measured of the last frame (paintstrokes: polygons and vertices generated, mode).
  const nlohmann::json techniqueStatistics = renderer.statistics();
  for (const auto& [technique, statistics] : techniqueStatistics.items())
    for (const auto& [key, value] : statistics.items()) session.report().setStatistic(key, value);
  for (const std::string& warning : renderer.warnings()) session.diagnostics().warning("technique-fallback", warning);
  if (settings.compareStandard) {
    // The same scene, camera and light with every instance drawn by the standard renderer.
    RendererRegistry standardOnly;
    standardOnly.add("", [] { return std::make_unique<StandardRenderer>(); });
    BAKE_ASSIGN_OR_RETURN(SceneRenderer standard, SceneRenderer::create(scene, standardOnly, shaders));
    target.bind();
    const FrameTimes standardTimes = renderFrames(standard, frame, settings.frames);
    session.report().setStatistic("frameTimeStandardGpu", timingJson(standardTimes.gpuMs));
    session.report().setStatistic("frameTimeStandardCpu", timingJson(standardTimes.cpuMs));
    if (!session.diagnostics().quiet()) {
      const double techniques = percentiles(times.cpuMs).median, phong = percentiles(standardTimes.cpuMs).median;
      session.diagnostics().info("standard shading over " + std::to_string(settings.frames) + " frames: CPU median " +
                                 std::to_string(phong) + " ms; the scene's techniques take " +
                                 std::to_string(phong > 0 ? techniques / phong : 0.0) + " times as long");
    }
  }
  if (settings.frames > 1 && !session.diagnostics().quiet()) {
    const Percentiles gpu = percentiles(times.gpuMs), cpu = percentiles(times.cpuMs);
    const std::string gpuText = times.gpuMs.empty() ? "GPU not measured (unreliable timer queries)"
                                                    : "GPU median " + std::to_string(gpu.median) + " ms, p95 " +
                                                          std::to_string(gpu.p95) + " ms";
    session.diagnostics().info("frame time over " + std::to_string(settings.frames) + " frames: " + gpuText +
                               "; CPU median " + std::to_string(cpu.median) + " ms, p95 " + std::to_string(cpu.p95) +
                               " ms (" + context->renderer() + ")");
  }
  {
    StageTimer timer(&session.report(), "write");
    if (extension == ".png") {
      BAKE_RETURN_IF_ERROR(writeImage(settings.output, encodeSrgb(image), PixelType::U8));
    } else {
      BAKE_RETURN_IF_ERROR(writeImage(settings.output, image, PixelType::Half));
    }
    session.recordWrittenOutput(settings.output);
  }
  return {};
}

}  // namespace

Result<ViewSetup> setUpView(const ViewSettings& view, Diagnostics& diagnostics) {
  ViewSetup setup;
  if (view.scenes.empty()) {
    setup.scene = defaultScene();
  } else {
    const std::vector<std::filesystem::path> files(view.scenes.begin(), view.scenes.end());
    const RendererRegistry& registry = RendererRegistry::builtIn();
    BAKE_ASSIGN_OR_RETURN(setup.scene, loadScene(files, diagnostics, [&](const std::string& e) { return registry.has(e); }));
  }
  BAKE_RETURN_IF_ERROR(attachGeoTextures(setup.scene, view.geotexture));
  const float aspect = float(view.width) / float(view.height);
  setup.camera = setup.scene.fileCamera ? *setup.scene.fileCamera : frameBounds(setup.scene, aspect);
  if (!view.camera.empty()) {
    BAKE_ASSIGN_OR_RETURN(setup.camera, parseCamera(view.camera, setup.scene, aspect));
  }
  setup.light = setup.scene.fileLight ? *setup.scene.fileLight : Light{};
  if (!view.light.empty()) {
    BAKE_ASSIGN_OR_RETURN(setup.light, parseLight(view.light));
    aimAtScene(setup.light, setup.scene);
  }
  if (!view.environment.empty()) {
    using Triple = std::array<double, 3>;
    BAKE_ASSIGN_OR_RETURN(const Triple rgb, parseTriple(view.environment, "--environment", "R,G,B"));
    for (int c = 0; c < 3; ++c) {
      if (!(rgb[std::size_t(c)] >= 0)) return usageError("--environment: a colour's channels must be >= 0");
      setup.light.environment[std::size_t(c)] = float(rgb[std::size_t(c)]);
    }
  }
  setup.light.direction = normalize(setup.light.direction);
  return setup;
}

Result<RendererRegistry> renderersFor(const ViewSettings& view) {
  BAKE_ASSIGN_OR_RETURN(const PaintstrokeOptions strokes,
                        makePaintstrokeOptions(view.strokeQuality, view.strokeTolerance, view.strokeTubes));
  RendererRegistry registry = RendererRegistry::builtIn();
  registry.add(format::paintstrokes::kExtension, [strokes] { return std::make_unique<PaintstrokesRenderer>(strokes); });
  if (view.hatchingTone != "blend" && view.hatchingTone != "threshold")
    return usageError("--hatching-tone must be blend or threshold, not '" + view.hatchingTone + "'");
  const HatchingTone tone = view.hatchingTone == "threshold" ? HatchingTone::Threshold : HatchingTone::Blend;
  registry.add(format::tam::kExtension, [tone] { return std::make_unique<HatchingRenderer>(tone); });
  if (view.grooveReflections != "traced" && view.grooveReflections != "environment")
    return usageError("--groove-reflections must be traced or environment, not '" + view.grooveReflections + "'");
  GroovesOptions grooves;
  grooves.areaReflections = view.grooveReflections == "traced";
  grooves.retryDraws = view.grooveRetries;
  registry.add(format::grooves::kExtension, [grooves] { return std::make_unique<GroovesRenderer>(grooves); });
  if (!view.environmentMap.empty()) {
    BAKE_ASSIGN_OR_RETURN(Image image, readImage(view.environmentMap));
    if (image.width < 2 || image.height < 1 || image.width > 16384 || image.height > 16384)
      return invalidInput("the environment map is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                              " pixels; it must be 2 to 16384 wide and 1 to 16384 high",
                          {view.environmentMap, ""});
    const auto environment = std::make_shared<const Image>(std::move(image));
    registry.add(format::geodesic::kExtension, [environment] { return std::make_unique<GeodesicRenderer>(environment); });
  }
  return registry;
}

Status parseSize(const std::string& text, ViewSettings& view) {
  int width = 0, height = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || (x != 'x' && x != 'X') || width < 1 ||
      height < 1 || width > 16384 || height > 16384) {
    return usageError("--size \"" + text + "\" must be WIDTHxHEIGHT, each 1 to 16384");
  }
  view.width = width;
  view.height = height;
  return {};
}

Percentiles percentiles(std::vector<double> samples) {
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  auto rank = [&](double q) { return samples[std::size_t(std::ceil(q * double(samples.size()))) - 1]; };
  return {rank(0.5), rank(0.95)};
}

Status runRender(const RenderSettings& settings, Diagnostics& diagnostics) {
  if (settings.frames < 1) return usageError("--frames must be at least 1");
  BAKE_RETURN_IF_ERROR(renderersFor(settings.view).status());  // bad stroke options are usage errors
  const OutputPlanScope planScope;
  BAKE_RETURN_IF_ERROR(planOutputs({settings.view.scenes, {settings.output}}, settings.common));
  BakeSession session("bakeplay", settings.common, diagnostics);
  session.report().setOptions({{"command", "render"},
                               {"output", settings.output},
                               {"size", {settings.view.width, settings.view.height}},
                               {"camera", settings.view.camera},
                               {"light", settings.view.light},
                               {"environment", settings.view.environment},
                               {"frames", settings.frames},
                               {"compareStandard", settings.compareStandard},
                               {"geotexture", settings.view.geotexture},
                               {"time", settings.view.time},
                               {"strokeQuality", settings.view.strokeQuality},
                               {"strokeTolerance", settings.view.strokeTolerance},
                               {"strokeTubes", settings.view.strokeTubes},
                               {"hatchingTone", settings.view.hatchingTone},
                               {"grooveReflections", settings.view.grooveReflections},
                               {"environmentMap", settings.view.environmentMap}});
  return session.finish(renderScene(settings, session));
}

}  // namespace bake::play
