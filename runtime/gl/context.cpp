// OpenGL 4.5 core contexts. Headless contexts come from EGL with no surface at all: Mesa's
// surfaceless platform first (llvmpipe on any machine, no display, no GPU), then the EGL device
// platform (a GPU driver such as NVIDIA's, which has no surfaceless platform). Every attempt that
// fails leaves one line in the final error, so "no context" is explained rather than guessed at.
// Window contexts come from GLFW for interactive viewers. The core GL entry points are linked
// directly (GL_GLEXT_PROTOTYPES against glvnd's libOpenGL), so there is no loader to initialise.
#include "gl/context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE  // glfw3.h would otherwise include <GL/gl.h>, which clashes with glcorearb.h
#include <GLFW/glfw3.h>

#include <cstring>
#include <map>
#include <mutex>
#include <vector>

namespace bake::gl {
namespace {

// ---------------------------------------------------------------------------------------------
// EGL helpers

const char* eglErrorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
  }
  return "unknown EGL error";
}

// "what failed: EGL_ERROR_NAME", reading (and so clearing) EGL's error for this thread.
std::string eglFailure(const std::string& what) { return what + ": " + eglErrorName(eglGetError()); }

// Extension strings are space-separated names; a plain substring search would match prefixes.
bool hasExtension(const char* extensions, const char* name) {
  if (extensions == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = extensions; (at = std::strstr(at, name)) != nullptr; at += length) {
    const bool startsWord = at == extensions || at[-1] == ' ';
    const bool endsWord = at[length] == '\0' || at[length] == ' ';
    if (startsWord && endsWord) return true;
  }
  return false;
}

// eglTerminate acts on the display, not on one context: every eglGetPlatformDisplayEXT call with the
// same arguments returns the same EGLDisplay, so terminating it for one context would pull the
// display out from under every other context on it. Count our users and terminate with the last.
std::mutex displayMutex;
std::map<EGLDisplay, int> displayUsers;

void retainDisplay(EGLDisplay display) {
  std::lock_guard lock(displayMutex);
  ++displayUsers[display];
}

void releaseDisplay(EGLDisplay display) {
  std::lock_guard lock(displayMutex);
  auto found = displayUsers.find(display);
  if (found == displayUsers.end() || --found->second > 0) return;
  displayUsers.erase(found);
  eglTerminate(display);
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay display, EGLContext context, std::string platform)
      : display_(display), context_(context) {
    platform_ = std::move(platform);
  }
  ~EglContext() override {
    // A context that is current is only marked for deletion; release it so it really goes.
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    releaseDisplay(display_);
  }
  void makeCurrent() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

// Picks a config that can render OpenGL. The context never draws to an EGL surface, so the pbuffer
// bit is only a preference; Mesa's surfaceless platform may also offer no config at all, which
// EGL_KHR_no_config_context allows.
Result<EGLConfig> chooseConfig(EGLDisplay display) {
  const EGLint withPbuffer[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  const EGLint anySurface[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  for (const EGLint* attributes : {withPbuffer, anySurface}) {
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (eglChooseConfig(display, attributes, &config, 1, &count) && count > 0) return config;
  }
  if (hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
    return EGLConfig(EGL_NO_CONFIG_KHR);
  }
  return unsupported("no EGL config with EGL_OPENGL_BIT");
}

// Checks what the driver actually gave: EGL may hand out a compatible higher version, but a driver
// bug or an override (MESA_GL_VERSION_OVERRIDE) could also hand out less.
Status checkCoreVersion() {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if (major * 10 + minor < 45 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
    return unsupported("got OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                       ((profile & GL_CONTEXT_CORE_PROFILE_BIT) ? " core" : " non-core") + ", need 4.5 core");
  }
  return {};
}

// Initialises `display`, creates a 4.5 core context on it and makes it current with no surface.
// On failure everything made here is undone and the error says which step failed.
Result<std::unique_ptr<Context>> contextOnDisplay(EGLDisplay display, const std::string& platform) {
  if (display == EGL_NO_DISPLAY) return unsupported(eglFailure("no display"));
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return unsupported(eglFailure("eglInitialize failed"));
  retainDisplay(display);
  auto fail = [&](const std::string& why) -> Result<std::unique_ptr<Context>> {
    releaseDisplay(display);
    return unsupported(why);
  };
  if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return fail("EGL_KHR_surfaceless_context is missing (needed to render with no surface)");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) return fail(eglFailure("eglBindAPI(EGL_OPENGL_API) failed"));
  Result<EGLConfig> config = chooseConfig(display);
  if (!config) return fail(config.status().message());
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, *config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) return fail(eglFailure("no OpenGL 4.5 core context"));
  // From here the EglContext owns the context and its share of the display.
  auto result = std::make_unique<EglContext>(display, context, platform);
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    return unsupported(eglFailure("eglMakeCurrent with no surface failed"));
  }
  if (Status version = checkCoreVersion(); !version) return version;
  return std::unique_ptr<Context>(std::move(result));
}

// The entry points of client extensions must be looked up; glvnd's libEGL exports only EGL 1.5.
template <class Function>
Function clientFunction(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

Result<std::unique_ptr<Context>> trySurfaceless(const char* clientExtensions) {
  if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    return unsupported("EGL_MESA_platform_surfaceless is not offered by the EGL client");
  }
  auto getPlatformDisplay = clientFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (getPlatformDisplay == nullptr) return unsupported("eglGetPlatformDisplayEXT is missing");
  EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  return contextOnDisplay(display, "egl-surfaceless");
}

// Tries each EGL device in turn; the error collects why each one failed.
Result<std::unique_ptr<Context>> tryDevices(const char* clientExtensions) {
  if (!hasExtension(clientExtensions, "EGL_EXT_device_enumeration") &&
      !hasExtension(clientExtensions, "EGL_EXT_device_base")) {
    return unsupported("EGL_EXT_device_enumeration is not offered by the EGL client");
  }
  if (!hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
    return unsupported("EGL_EXT_platform_device is not offered by the EGL client");
  }
  auto queryDevices = clientFunction<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto getPlatformDisplay = clientFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (queryDevices == nullptr || getPlatformDisplay == nullptr) {
    return unsupported("eglQueryDevicesEXT or eglGetPlatformDisplayEXT is missing");
  }
  EGLint count = 0;
  if (!queryDevices(0, nullptr, &count)) return unsupported(eglFailure("eglQueryDevicesEXT failed"));
  if (count == 0) return unsupported("eglQueryDevicesEXT found no devices");
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!queryDevices(count, devices.data(), &count)) return unsupported(eglFailure("eglQueryDevicesEXT failed"));
  std::string failures;
  for (EGLint i = 0; i < count; ++i) {
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
    auto context = contextOnDisplay(display, "egl-device");
    if (context) return context;
    failures += (failures.empty() ? "" : "; ") + ("device " + std::to_string(i) + ": " + context.status().message());
  }
  return unsupported(failures);
}

// ---------------------------------------------------------------------------------------------
// GLFW helpers

// GLFW reports errors through a callback only; keep the latest description so a failed call can
// quote it. Called synchronously on the failing thread, so it must not take glfwMutex.
std::string lastGlfwError;
void onGlfwError(int code, const char* description) {
  lastGlfwError = (description ? description : "no description") + std::string(" (GLFW error ") +
                  std::to_string(code) + ")";
}

// glfwTerminate destroys every window, so GLFW stays initialised while any WindowContext lives.
std::mutex glfwMutex;
int glfwUsers = 0;

std::string takeGlfwError() {
  std::string error = lastGlfwError.empty() ? "no error reported" : lastGlfwError;
  lastGlfwError.clear();
  return error;
}

void releaseGlfw() {
  std::lock_guard lock(glfwMutex);
  if (--glfwUsers == 0) glfwTerminate();
}

}  // namespace

std::string Context::renderer() const {
  const GLubyte* text = glGetString(GL_RENDERER);
  return text ? reinterpret_cast<const char*>(text) : "";
}

std::string Context::version() const {
  const GLubyte* text = glGetString(GL_VERSION);
  return text ? reinterpret_cast<const char*>(text) : "";
}

Result<std::unique_ptr<Context>> createHeadlessContext() {
  // Client extensions (EGL_NO_DISPLAY) say which platforms exist before any display is opened.
  // Null (with EGL_BAD_DISPLAY) on an EGL without client extensions: both tries then say so.
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  std::string failures;
  auto surfaceless = trySurfaceless(clientExtensions);
  if (surfaceless) return surfaceless;
  failures += "egl-surfaceless: " + surfaceless.status().message();
  auto device = tryDevices(clientExtensions);
  if (device) return device;
  failures += "; egl-device: " + device.status().message();
  return unsupported("no headless OpenGL 4.5 core context (" + failures + ")");
}

bool contextIsCurrent() {
  if (eglGetCurrentContext() != EGL_NO_CONTEXT) return true;
  std::lock_guard lock(glfwMutex);
  return glfwUsers > 0 && glfwGetCurrentContext() != nullptr;
}

Result<std::unique_ptr<WindowContext>> WindowContext::create(int width, int height, const std::string& title) {
  {
    std::lock_guard lock(glfwMutex);
    glfwSetErrorCallback(onGlfwError);  // allowed before glfwInit, and needed to see why it fails
    if (glfwUsers == 0) {
      lastGlfwError.clear();
      if (!glfwInit()) return unsupported("glfw: glfwInit failed: " + takeGlfwError());
    }
    ++glfwUsers;
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  lastGlfwError.clear();
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::string error = takeGlfwError();
    releaseGlfw();
    return unsupported("glfw: no OpenGL 4.5 core window: " + error);
  }
  auto context = std::make_unique<WindowContext>();
  context->window_ = window;
  context->platform_ = "glfw";
  context->makeCurrent();
  return context;
}

WindowContext::~WindowContext() {
  if (window_ == nullptr) return;
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
  releaseGlfw();
}

void WindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

void WindowContext::swapBuffers() { glfwSwapBuffers(window_); }

}  // namespace bake::gl
