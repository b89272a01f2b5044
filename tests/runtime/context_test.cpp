#include <GL/glcorearb.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "gl/context.h"

namespace bake {
namespace {

void expectCurrent45Core() {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}

TEST(HeadlessContext, IsOpenGL45CoreAndReportsItsRenderer) {
  auto context = gl::createHeadlessContext();
  ASSERT_TRUE(context.isOk()) << context.status().describe();
  const gl::Context& made = **context;
  std::cout << "headless context: " << made.platform() << ", " << made.renderer() << ", " << made.version() << "\n";
  EXPECT_TRUE(made.platform() == "egl-surfaceless" || made.platform() == "egl-device") << made.platform();
  EXPECT_FALSE(made.renderer().empty());
  EXPECT_NE(made.version().find("Core Profile"), std::string::npos) << made.version();
  EXPECT_TRUE(gl::contextIsCurrent());
  expectCurrent45Core();
}

TEST(HeadlessContext, NoContextIsCurrentAfterItIsDestroyed) {
  {
    auto context = gl::createHeadlessContext();
    ASSERT_TRUE(context.isOk()) << context.status().describe();
  }
  EXPECT_FALSE(gl::contextIsCurrent());
}

// Both contexts share one EGLDisplay; destroying the first must not terminate it under the second.
TEST(HeadlessContext, SecondContextOutlivesTheFirst) {
  auto first = gl::createHeadlessContext();
  auto second = gl::createHeadlessContext();
  ASSERT_TRUE(first.isOk() && second.isOk());
  first->reset();
  (*second)->makeCurrent();
  EXPECT_TRUE(gl::contextIsCurrent());
  EXPECT_FALSE((*second)->renderer().empty());
  expectCurrent45Core();
}

// With no EGL vendor at all (glvnd pointed at a file that does not exist) every platform fails, and
// the error says why for each. glvnd reads the variable once per process, hence a fresh process.
TEST(HeadlessContextDeathTest, FailureListsEveryPlatformTried) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // re-executes the binary: a fresh glvnd
  setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json", 1);
  EXPECT_EXIT(
      {
        auto context = gl::createHeadlessContext();
        std::fprintf(stderr, "%s\n", context.status().describe().c_str());
        std::exit(context.isOk() ? 0 : int(context.status().code()));
      },
      ::testing::ExitedWithCode(int(ExitCode::Unsupported)), "egl-surfaceless: .*; egl-device: .*");
  unsetenv("__EGL_VENDOR_LIBRARY_FILENAMES");
}

// Mesa can be told to offer less than 4.5; the context request must then fail with EGL's reason.
TEST(HeadlessContextDeathTest, TooOldAVersionIsReportedWithTheEglError) {
  {
    // The threadsafe style re-runs this whole test in the child, where the override is already set
    // and this context fails: only a context that works and is not Mesa's means "skip".
    auto context = gl::createHeadlessContext();
    if (context && (*context)->version().find("Mesa") == std::string::npos) GTEST_SKIP() << "needs Mesa";
  }
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
  EXPECT_EXIT(
      {
        auto context = gl::createHeadlessContext();
        std::fprintf(stderr, "%s\n", context.status().describe().c_str());
        std::exit(context.isOk() ? 0 : int(context.status().code()));
      },
      ::testing::ExitedWithCode(int(ExitCode::Unsupported)), "egl-surfaceless: [^;]*EGL_BAD_MATCH");
  unsetenv("MESA_GL_VERSION_OVERRIDE");
}

// Windows need a display; without one the error must carry GLFW's own description.
TEST(WindowContext, OpensOrExplainsWhyNot) {
  auto window = gl::WindowContext::create(64, 64, "bake test");
  if (!window) {
    std::cout << "no window: " << window.status().describe() << "\n";
    EXPECT_EQ(window.status().code(), ExitCode::Unsupported);
    EXPECT_NE(window.status().message().find("glfw: "), std::string::npos);
    EXPECT_EQ(window.status().message().find("no error reported"), std::string::npos) << window.status().message();
    return;
  }
  EXPECT_EQ((*window)->platform(), "glfw");
  EXPECT_NE((*window)->window(), nullptr);
  expectCurrent45Core();
}

}  // namespace
}  // namespace bake
