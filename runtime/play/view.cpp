#include "play/view.h"

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE  // glcorearb.h already declares GL; glfw3.h would pull in GL/gl.h
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bake/io/image.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "render/target.h"

namespace bake::play {
namespace {

constexpr float kPi = 3.14159265358979f;

// An orbit around the target: azimuth and elevation in radians, distance from the target.
struct Orbit {
  Vec3 target;
  float azimuth = 0, elevation = 0, distance = 1;

  static Orbit around(const Camera& camera) {
    Orbit orbit;
    orbit.target = camera.target;
    const Vec3 offset = camera.eye - camera.target;
    orbit.distance = std::max(length(offset), 1e-6f);
    orbit.azimuth = std::atan2(offset[0], offset[2]);
    orbit.elevation = std::asin(std::clamp(offset[1] / orbit.distance, -1.0f, 1.0f));
    return orbit;
  }
  Camera apply(Camera camera) const {
    const Vec3 direction = {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
    camera.target = target;
    camera.eye = target + direction * distance;
    camera.up = {0, 1, 0};
    camera.znear = distance * 1e-3f;
    camera.zfar = distance * 100.0f;
    return camera;
  }
};

// Spherical angles of a light direction, so the arrow keys and right drag can turn it.
struct LightAngles {
  float azimuth = 0, elevation = 0;
  static LightAngles of(const Vec3& d) { return {std::atan2(d[0], d[2]), std::asin(std::clamp(d[1], -1.0f, 1.0f))}; }
  Vec3 direction() const {
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
  }
};

struct Interaction {
  Orbit orbit, initialOrbit;
  LightAngles light, initialLight;
  double lastX = 0, lastY = 0;
};

void clampElevation(float& elevation) { elevation = std::clamp(elevation, -kPi / 2 + 0.01f, kPi / 2 - 0.01f); }

void handleInput(GLFWwindow* window, Interaction& state) {
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  const float dx = float(x - state.lastX), dy = float(y - state.lastY);
  state.lastX = x;
  state.lastY = y;
  if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
    state.orbit.azimuth -= dx * 0.01f;
    state.orbit.elevation += dy * 0.01f;
    clampElevation(state.orbit.elevation);
  }
  if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) {
    state.light.azimuth -= dx * 0.01f;
    state.light.elevation -= dy * 0.01f;
  }
  const float step = 0.03f;
  if (glfwGetKey(window, GLFW_KEY_LEFT) == GLFW_PRESS) state.light.azimuth -= step;
  if (glfwGetKey(window, GLFW_KEY_RIGHT) == GLFW_PRESS) state.light.azimuth += step;
  if (glfwGetKey(window, GLFW_KEY_UP) == GLFW_PRESS) state.light.elevation += step;
  if (glfwGetKey(window, GLFW_KEY_DOWN) == GLFW_PRESS) state.light.elevation -= step;
  clampElevation(state.light.elevation);
  if (glfwGetKey(window, GLFW_KEY_R) == GLFW_PRESS) {
    state.orbit = state.initialOrbit;
    state.light = state.initialLight;
  }
  if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

void onScroll(GLFWwindow* window, double, double offset) {
  auto* state = static_cast<Interaction*>(glfwGetWindowUserPointer(window));
  state->orbit.distance *= std::pow(0.9f, float(offset));
}

Image readWindow(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.channels = 4;
  std::vector<std::uint8_t> rows(std::size_t(width) * std::size_t(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  image.pixels.resize(rows.size());
  const std::size_t stride = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y) {
    for (std::size_t i = 0; i < stride; ++i) {
      image.pixels[std::size_t(y) * stride + i] = float(rows[std::size_t(height - 1 - y) * stride + i]) / 255.0f;
    }
  }
  return image;
}

}  // namespace

Status runView(const WindowSettings& settings, Diagnostics& diagnostics) {
  if (settings.frames < 1) return usageError("--frames must be at least 1");
  BAKE_ASSIGN_OR_RETURN(const RendererRegistry registry, renderersFor(settings.view));
  BAKE_ASSIGN_OR_RETURN(const ViewSetup setup, setUpView(settings.view, diagnostics));
  BAKE_ASSIGN_OR_RETURN(std::unique_ptr<gl::WindowContext> window,
                        gl::WindowContext::create(settings.view.width, settings.view.height, "bakeplay"));
  // Destroyed before the window: they hold GL objects of its context.
  gl::ShaderLibrary shaders;
  BAKE_ASSIGN_OR_RETURN(SceneRenderer renderer, SceneRenderer::create(setup.scene, registry, shaders));
  BAKE_ASSIGN_OR_RETURN(const unsigned present, shaders.program({{"common/present.vert", "common/present.frag", "", "", ""}, {}}));
  GLuint emptyVertexArray = 0;
  glCreateVertexArrays(1, &emptyVertexArray);

  Interaction state;
  state.orbit = state.initialOrbit = Orbit::around(setup.camera);
  state.light = state.initialLight = LightAngles::of(setup.light.direction);
  glfwSetWindowUserPointer(window->window(), &state);
  glfwSetScrollCallback(window->window(), onScroll);
  glfwSwapInterval(settings.screenshot.empty() ? 1 : 0);

  OffscreenTarget target;
  double smoothedMs = 0;
  const double startSeconds = glfwGetTime();
  for (int frameIndex = 1; !window->shouldClose(); ++frameIndex) {
    const auto start = std::chrono::steady_clock::now();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window->window(), &width, &height);
    if (width < 1 || height < 1) {  // minimised
      glfwWaitEvents();
      continue;
    }
    if (target.width() != width || target.height() != height) {
      BAKE_ASSIGN_OR_RETURN(target, OffscreenTarget::create(width, height));
    }
    const Camera camera = state.orbit.apply(setup.camera);
    Light light = setup.light;
    light.direction = state.light.direction();
    const float aspect = float(width) / float(height);
    // Animation runs in real time from --time; a screenshot keeps --time, to match `render`.
    const float time = settings.view.time + (settings.screenshot.empty() ? float(glfwGetTime() - startSeconds) : 0.0f);
    const FrameContext frame{setup.scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, aspect, camera.znear, camera.zfar), width, height, time};
    target.bind();
    renderer.drawFrame(frame);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(present);
    glBindTextureUnit(0, target.colourTexture());
    glBindVertexArray(emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    if (!settings.screenshot.empty() && frameIndex >= settings.frames) {
      BAKE_RETURN_IF_ERROR(writeImage(settings.screenshot, readWindow(width, height), PixelType::U8));
      glfwSetWindowShouldClose(window->window(), GLFW_TRUE);
    }
    window->swapBuffers();
    glfwPollEvents();
    handleInput(window->window(), state);

    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    smoothedMs = frameIndex == 1 ? ms : 0.9 * smoothedMs + 0.1 * ms;
    char title[160];
    std::snprintf(title, sizeof title, "bakeplay - %.2f ms/frame (%.0f fps) - drag: orbit, right drag/arrows: light, R: reset",
                  smoothedMs, 1000.0 / std::max(smoothedMs, 1e-3));
    glfwSetWindowTitle(window->window(), title);
  }
  glDeleteVertexArrays(1, &emptyVertexArray);
  return {};
}

}  // namespace bake::play
