// OpenGL 4.5 core contexts: headless through EGL (Mesa's surfaceless platform first, then the EGL
// device platform), so frames render on llvmpipe with no GPU and no display; and a GLFW window for
// people. When no context can be made, the error lists each platform tried and why it failed.
#pragma once

#include <memory>
#include <string>

#include "bake/core/status.h"

struct GLFWwindow;

namespace bake::gl {

class Context {
 public:
  virtual ~Context() = default;
  virtual void makeCurrent() = 0;
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;   // GL_VERSION
  const std::string& platform() const { return platform_; }  // "egl-surfaceless", "egl-device", "glfw"

 protected:
  std::string platform_;
};

// Renders into framebuffer objects only (no default framebuffer).
Result<std::unique_ptr<Context>> createHeadlessContext();

// True when one of our contexts (EGL or GLFW) is current on this thread, so GL calls are safe.
bool contextIsCurrent();

class WindowContext : public Context {
 public:
  static Result<std::unique_ptr<WindowContext>> create(int width, int height, const std::string& title);
  ~WindowContext() override;
  void makeCurrent() override;
  GLFWwindow* window() const { return window_; }
  bool shouldClose() const;
  void swapBuffers();

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace bake::gl
