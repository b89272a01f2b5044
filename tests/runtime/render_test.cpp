// Render smoke test: one lit triangle through the standard program into an RGBA8 framebuffer object,
// read back with glReadPixels. Checks the whole path (context, FBO, embedded shaders, uniforms,
// vertex layout) and that llvmpipe renders deterministically.
#include <GL/glcorearb.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "gl/shader.h"
#include "runtime/gl_test.h"

namespace bake {
namespace {

constexpr int kSize = 64;
constexpr std::array<std::uint8_t, 4> kClearBytes = {51, 102, 153, 255};  // the clear colour in RGBA8

// A triangle in the z = 0 plane covering the centre of the view, normals towards the camera (+z).
// Per vertex: position xyz, normal xyz.
constexpr float kTriangle[] = {
    -0.6f, -0.6f, 0.0f, 0.0f, 0.0f, 1.0f,  //
    0.6f,  -0.6f, 0.0f, 0.0f, 0.0f, 1.0f,  //
    0.0f,  0.7f,  0.0f, 0.0f, 0.0f, 1.0f,  //
};

// GL objects for one render target and one triangle, deleted at the end of the test.
class TriangleScene {
 public:
  TriangleScene() {
    glCreateRenderbuffers(1, &colour_);
    glNamedRenderbufferStorage(colour_, GL_RGBA8, kSize, kSize);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferRenderbuffer(framebuffer_, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    glCreateBuffers(1, &vertices_);
    glNamedBufferStorage(vertices_, sizeof(kTriangle), kTriangle, 0);
    glCreateVertexArrays(1, &vertexArray_);  // core profile draws nothing without a vertex array
    glVertexArrayVertexBuffer(vertexArray_, 0, vertices_, 0, 6 * sizeof(float));
    for (GLuint attribute : {0u, 1u}) {  // 0 POSITION, 1 NORMAL
      glEnableVertexArrayAttrib(vertexArray_, attribute);
      glVertexArrayAttribFormat(vertexArray_, attribute, 3, GL_FLOAT, GL_FALSE, attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(vertexArray_, attribute, 0);
    }
  }
  ~TriangleScene() {
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteBuffers(1, &vertices_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(1, &colour_);
  }
  bool complete() const {
    return glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  }

  // Clears, draws the triangle with `program` (identity transforms, camera at z = 2, light from the
  // camera's side) and returns the pixels, bottom row first.
  std::vector<std::uint8_t> render(GLuint program) const {
    const float identity4[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float identity3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    // Uniforms a variant does not use have location -1, which glProgramUniform* ignores.
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uModel"), 1, GL_FALSE, identity4);
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uViewProj"), 1, GL_FALSE, identity4);
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, identity3);
    glProgramUniform3f(program, glGetUniformLocation(program, "uLightDir"), 0.0f, 0.0f, 1.0f);
    glProgramUniform3f(program, glGetUniformLocation(program, "uCameraPos"), 0.0f, 0.0f, 2.0f);
    glProgramUniform4f(program, glGetUniformLocation(program, "uBaseColor"), 0.8f, 0.2f, 0.1f, 1.0f);

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, kSize, kSize);
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(program);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<std::uint8_t> pixels(std::size_t(kSize * kSize * 4));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return pixels;
  }

 private:
  GLuint colour_ = 0, framebuffer_ = 0, vertices_ = 0, vertexArray_ = 0;
};

std::array<std::uint8_t, 4> pixelAt(const std::vector<std::uint8_t>& pixels, int x, int y) {
  const std::size_t at = std::size_t((y * kSize + x) * 4);
  return {pixels[at], pixels[at + 1], pixels[at + 2], pixels[at + 3]};
}

using RenderSmokeTest = test::GlTest;

TEST_F(RenderSmokeTest, StandardProgramLightsATriangle) {
  gl::ShaderLibrary library;
  TriangleScene scene;
  ASSERT_TRUE(scene.complete());
  for (const auto& defines : std::vector<std::vector<std::string>>{{"HAS_NORMALS"}, {}}) {
    SCOPED_TRACE(defines.empty() ? "flat normals" : "HAS_NORMALS");
    auto program = library.program({{"standard/mesh.vert", "standard/mesh.frag"}, defines});
    ASSERT_TRUE(program.isOk()) << program.status().describe();
    const std::vector<std::uint8_t> first = scene.render(*program);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    const auto centre = pixelAt(first, kSize / 2, kSize / 2);
    // Lit head-on: base colour red 0.8 plus ambient and a white highlight saturates red.
    EXPECT_GE(centre[0], 250);
    EXPECT_GT(centre[1], centre[2]) << "green base 0.2 above blue base 0.1";
    EXPECT_EQ(centre[3], 255);
    EXPECT_EQ(pixelAt(first, 0, 0), kClearBytes);
    EXPECT_EQ(pixelAt(first, kSize - 1, kSize - 1), kClearBytes);

    const std::vector<std::uint8_t> second = scene.render(*program);
    EXPECT_TRUE(first == second) << "rendering the same frame twice gave different pixels";
  }
}

// For a flat triangle whose normals face the camera, the derivative normal is the same normal.
TEST_F(RenderSmokeTest, FlatNormalsMatchGivenNormalsOnAPlane) {
  gl::ShaderLibrary library;
  TriangleScene scene;
  auto smooth = library.program({{"standard/mesh.vert", "standard/mesh.frag"}, {"HAS_NORMALS"}});
  auto flat = library.program({{"standard/mesh.vert", "standard/mesh.frag"}, {}});
  ASSERT_TRUE(smooth.isOk() && flat.isOk());
  const auto a = pixelAt(scene.render(*smooth), kSize / 2, kSize / 2);
  const auto b = pixelAt(scene.render(*flat), kSize / 2, kSize / 2);
  for (int channel = 0; channel < 4; ++channel) EXPECT_NEAR(a[channel], b[channel], 1) << "channel " << channel;
}

}  // namespace
}  // namespace bake
