// See runtime_view.h. The projection maps the plane's x = u, y = v onto the view's pixels (GL row r is
// the view's row height - 1 - r, so the image read top row first is the view's); the camera stands
// 10^7 units away along E, so every pixel sees the plane along E to 1e-6 rad.
#include "runtime_view.h"

#include <GL/glcorearb.h>

#include "bake/core/diagnostics.h"
#include "bake/io/glb.h"
#include "gl/context.h"
#include "gl/shader.h"
#include "grooves/package/package.h"
#include "render/grooves.h"
#include "render/target.h"
#include "scene/scene.h"

namespace bake::grooves {

struct RuntimeViews::State {
  std::unique_ptr<gl::Context> context;
  std::unique_ptr<gl::ShaderLibrary> shaders;
  std::unique_ptr<play::Scene> scene;
};

RuntimeViews::RuntimeViews(std::unique_ptr<State> state) : state_(std::move(state)) {}

RuntimeViews::~RuntimeViews() {
  if (!state_) return;
  state_->scene.reset();
  state_->shaders.reset();  // the programs go before the context
}

Result<std::unique_ptr<RuntimeViews>> RuntimeViews::create() {
  auto state = std::make_unique<State>();
  BAKE_ASSIGN_OR_RETURN(state->context, gl::createHeadlessContext());
  state->shaders = std::make_unique<gl::ShaderLibrary>();
  return std::unique_ptr<RuntimeViews>(new RuntimeViews(std::move(state)));
}

Status RuntimeViews::load(const GrooveScene& scene, const GrooveGrid& grid, const std::filesystem::path& folder) {
  BAKE_ASSIGN_OR_RETURN(const glb::Package package, buildGroovePackage(scene, grid));
  std::filesystem::create_directories(folder);
  const std::filesystem::path file = folder / "bench-groove-scene.glb";
  BAKE_RETURN_IF_ERROR(glb::write(file, package));
  Diagnostics diagnostics("bench-groove", true);
  BAKE_ASSIGN_OR_RETURN(play::Scene loaded, play::loadScene({file}, diagnostics, [](const std::string&) { return true; }));
  state_->scene = std::make_unique<play::Scene>(std::move(loaded));
  return {};
}

Result<Image> RuntimeViews::render(const View& view, const Lighting& lighting, std::size_t* farFragments) {
  if (!state_->scene) return internalError("bench-groove: no scene loaded for the runtime");
  play::GroovesRenderer renderer({lighting.maxBounces, false, true, 0});
  BAKE_RETURN_IF_ERROR(renderer.prepare(*state_->scene, {0}, *state_->shaders));
  BAKE_ASSIGN_OR_RETURN(play::OffscreenTarget target, play::OffscreenTarget::create(view.width, view.height, play::ColourPrecision::Float32));
  const double pixel = view.axisX.u, w = pixel * view.width, h = pixel * view.height;
  const double left = view.origin.u, bottom = view.origin.v - h;
  play::Mat4 projection{};
  projection[0] = float(2 / w);
  projection[5] = float(2 / h);
  projection[12] = float(-1 - 2 * left / w);
  projection[13] = float(-1 - 2 * bottom / h);
  projection[15] = 1;
  const double far = 1e7;
  const play::Vec3 centre{float(left + 0.5 * w), float(bottom + 0.5 * h), 0};
  const play::Camera camera{{float(centre[0] + far * view.toViewer.u), float(centre[1] + far * view.toViewer.v),
                             float(far * view.toViewer.w)},
                            centre, {0, 1, 0}, 0.7f, 0.01f, 100.0f};
  const play::Light light{{float(lighting.toLight.u), float(lighting.toLight.v), float(lighting.toLight.w)},
                          {float(lighting.radiance[0]), float(lighting.radiance[1]), float(lighting.radiance[2])}};
  const play::FrameContext frame{*state_->scene, camera, light, play::identity(), projection, view.width, view.height};
  target.bind();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  renderer.draw(frame);
  glFinish();
  if (farFragments) *farFragments = renderer.statistics().value("grooveFarFragments", std::size_t(0));
  const Image rgba = target.readLinearRgba();
  Image rgb = rgbImage(view.width, view.height);
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x)
      for (int k = 0; k < 3; ++k) rgb.pixels[(std::size_t(y) * view.width + x) * 3 + k] = rgba.at(x, y, k);
  return rgb;
}

}  // namespace bake::grooves
