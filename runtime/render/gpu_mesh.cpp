#include "render/gpu_mesh.h"

#include <GL/glcorearb.h>

#include <utility>

namespace bake::play {
namespace {

GLenum glType(glb::ComponentType type) {
  switch (type) {
    case glb::ComponentType::I8: return GL_BYTE;
    case glb::ComponentType::U8: return GL_UNSIGNED_BYTE;
    case glb::ComponentType::I16: return GL_SHORT;
    case glb::ComponentType::U16: return GL_UNSIGNED_SHORT;
    case glb::ComponentType::U32: return GL_UNSIGNED_INT;
    case glb::ComponentType::F32: return GL_FLOAT;
  }
  return GL_FLOAT;
}

GLuint makeBuffer(const void* data, std::size_t bytes) {
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(bytes ? bytes : 4), data, 0);
  return buffer;
}

}  // namespace

Result<GpuPrimitive> GpuPrimitive::upload(const glb::Primitive& primitive, const std::map<std::string, int>& locations) {
  if (primitive.mode < 0 || primitive.mode > 6) return unsupported("glTF primitive mode " + std::to_string(primitive.mode) + " does not exist");
  GpuPrimitive gpu;
  glCreateVertexArrays(1, &gpu.vao_);
  GLuint binding = 0;
  for (const glb::Attribute& attribute : primitive.attributes) {
    const auto location = locations.find(attribute.name);
    if (location == locations.end()) continue;
    const GLuint buffer = makeBuffer(attribute.bytes.data(), attribute.bytes.size());
    gpu.buffers_.push_back(buffer);
    gpu.attributes_.push_back(attribute.name);
    gpu.bytes_ += attribute.bytes.size();
    const GLuint index = GLuint(location->second);
    glVertexArrayVertexBuffer(gpu.vao_, binding, buffer, 0, GLsizei(attribute.elementSize()));
    glVertexArrayAttribFormat(gpu.vao_, index, attribute.components, glType(attribute.componentType),
                              attribute.normalized ? GL_TRUE : GL_FALSE, 0);
    glVertexArrayAttribBinding(gpu.vao_, index, binding);
    glEnableVertexArrayAttrib(gpu.vao_, index);
    ++binding;
  }
  if (!primitive.indices.empty()) {
    const GLuint buffer = makeBuffer(primitive.indices.data(), primitive.indices.size() * 4);
    gpu.buffers_.push_back(buffer);
    gpu.bytes_ += primitive.indices.size() * 4;
    glVertexArrayElementBuffer(gpu.vao_, buffer);
    gpu.indexed_ = true;
    gpu.count_ = int(primitive.indices.size());
  } else {
    gpu.count_ = int(primitive.vertexCount());
  }
  // glTF modes 0-6 are GL's own enumerants (POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLES, ...).
  static const GLenum kModes[] = {GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN};
  gpu.mode_ = kModes[primitive.mode];
  return gpu;
}

GpuPrimitive::GpuPrimitive(GpuPrimitive&& other) noexcept { *this = std::move(other); }

GpuPrimitive& GpuPrimitive::operator=(GpuPrimitive&& other) noexcept {
  if (this != &other) {
    release();
    vao_ = std::exchange(other.vao_, 0);
    buffers_ = std::move(other.buffers_);
    attributes_ = std::move(other.attributes_);
    mode_ = other.mode_;
    count_ = other.count_;
    indexed_ = other.indexed_;
    bytes_ = other.bytes_;
  }
  return *this;
}

GpuPrimitive::~GpuPrimitive() { release(); }

void GpuPrimitive::release() {
  if (!buffers_.empty()) glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  if (vao_) glDeleteVertexArrays(1, &vao_);
  buffers_.clear();
  vao_ = 0;
}

void GpuPrimitive::draw() const {
  glBindVertexArray(vao_);
  if (indexed_) {
    glDrawElements(mode_, count_, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawArrays(mode_, 0, count_);
  }
}

void GpuPrimitive::drawAsPatches() const {
  glBindVertexArray(vao_);
  if (indexed_) {
    glDrawElements(GL_PATCHES, count_, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawArrays(GL_PATCHES, 0, count_);
  }
}

bool GpuPrimitive::has(const std::string& attribute) const {
  for (const std::string& name : attributes_) {
    if (name == attribute) return true;
  }
  return false;
}

}  // namespace bake::play
