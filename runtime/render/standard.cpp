#include "render/standard.h"

#include <GL/glcorearb.h>

#include "core/json_keys.h"

namespace bake::play {

std::array<float, 4> baseColourOf(const nlohmann::json& material) {
  // A material without baseColorFactor has glTF's default, white (glTF 2.0, 5.22); a primitive with no
  // material at all is drawn light grey, so bare meshes keep some contrast against white paper.
  const float fallback = material.is_object() ? 1.0f : 0.8f;
  std::array<float, 4> colour{fallback, fallback, fallback, 1.0f};
  const nlohmann::json& factor = jsonMember(jsonMember(material, "pbrMetallicRoughness"), "baseColorFactor");
  if (factor.is_array() && factor.size() == 4) {
    for (std::size_t i = 0; i < 4; ++i) {
      if (factor[i].is_number()) colour[i] = factor[i].get<float>();
    }
  }
  return colour;
}

namespace {

constexpr int kPositionLocation = 0;
constexpr int kNormalLocation = 1;

void setMatrix4(unsigned program, const char* name, const Mat4& m) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

}  // namespace

Status StandardRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                 gl::ShaderLibrary& shaders) {
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Primitive& primitive = scene.primitive(instance);
    gl::Variant variant{{"standard/mesh.vert", "standard/mesh.frag", "", "", ""}, {}};
    std::map<std::string, int> locations = {{"POSITION", kPositionLocation}};
    // Points and lines (e.g. the centrelines of a paintstroke package) have no surface to light.
    if (primitive.mode < 4) {
      variant.defines.push_back("UNLIT");
    } else if (primitive.find("NORMAL")) {
      variant.defines.push_back("HAS_NORMALS");
      locations["NORMAL"] = kNormalLocation;
    }
    BAKE_ASSIGN_OR_RETURN(const unsigned program, shaders.program(variant));
    BAKE_ASSIGN_OR_RETURN(GpuPrimitive gpu, GpuPrimitive::upload(primitive, locations));
    items_.push_back({std::move(gpu), program, instance.world, baseColourOf(scene.material(instance))});
  }
  return {};
}

void StandardRenderer::draw(const FrameContext& frame) {
  const Mat4 viewProjection = multiply(frame.projection, frame.view);
  for (const Item& item : items_) {
    glUseProgram(item.program);
    setMatrix4(item.program, "uModel", item.world);
    setMatrix4(item.program, "uViewProj", viewProjection);
    const Mat3 normal = normalMatrix(item.world);
    glProgramUniformMatrix3fv(item.program, glGetUniformLocation(item.program, "uNormalMatrix"), 1, GL_FALSE, normal.data());
    glProgramUniform3fv(item.program, glGetUniformLocation(item.program, "uLightDir"), 1, frame.light.direction.data());
    glProgramUniform3fv(item.program, glGetUniformLocation(item.program, "uLightColour"), 1, frame.light.colour.data());
    glProgramUniform3fv(item.program, glGetUniformLocation(item.program, "uCameraPos"), 1, frame.camera.eye.data());
    glProgramUniform4fv(item.program, glGetUniformLocation(item.program, "uBaseColor"), 1, item.baseColour.data());
    item.gpu.draw();
  }
}

std::size_t StandardRenderer::gpuBytes() const {
  std::size_t total = 0;
  for (const Item& item : items_) total += item.gpu.uploadedBytes();
  return total;
}

}  // namespace bake::play
