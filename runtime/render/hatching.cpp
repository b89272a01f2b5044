// Hatching renderer (seed 004; formats/tam.md). Per instance: read and check the material's
// BAKE_hatching object (hatching_params.cpp), build the triangle-adjacency index buffer from the
// primitive's positions (hatching_adjacency.cpp), upload positions and that buffer, upload the TAM as a
// GL_TEXTURE_2D_ARRAY with every mip level it carries (R8 or RGBA8, trilinear, repeating: the tiles
// wrap), and compile the variant of shaders/hatching/ for its texel format and orientation. A TAM
// shared by several instances of one package is uploaded once. Drawing is one
// glDrawElements(GL_TRIANGLES_ADJACENCY) per instance; the geometry and fragment stages do the rest.
#include "render/hatching.h"

#include <GL/glcorearb.h>
#include <bake_formats/tam.h>

#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace bake::play {
namespace {

namespace fmt = format::tam;

constexpr int kPositionLocation = 0;
constexpr GLuint kTamUnit = 0, kThresholdUnit = 1;
// Webb et al. 2002: the darkness over which a texel goes from paper to ink around its threshold
// (a little more than one 8-bit step), so the tone changes continuously as the light moves.
constexpr float kThresholdSoftness = 0.02f;

GLuint makeBuffer(const void* data, std::size_t bytes) {
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, GLsizeiptr(bytes ? bytes : 4), data, 0);
  return buffer;
}

// Trilinear filtering over the mip chain, repeating both ways: how the TAM tiles the surface.
void trilinearRepeating(GLuint texture) {
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

// Every level of the TAM, layers as array slices.
GLuint uploadTam(const ktx2::Texture& tam) {
  const bool rgba = tam.format == ktx2::Format::RGBA8;
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
  glTextureStorage3D(texture, GLsizei(tam.levels.size()), rgba ? GL_RGBA8 : GL_R8, GLsizei(tam.width),
                     GLsizei(tam.height), GLsizei(tam.layers));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::uint32_t level = 0; level < tam.levels.size(); ++level) {
    glTextureSubImage3D(texture, GLint(level), 0, 0, 0, GLsizei(tam.levelWidth(level)), GLsizei(tam.levelHeight(level)),
                        GLsizei(tam.layers), rgba ? GL_RGBA : GL_RED, GL_UNSIGNED_BYTE, tam.levels[level].data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  trilinearRepeating(texture);
  return texture;
}

// The threshold texture: one channel, every level, trilinear and repeating like the TAM.
GLuint uploadThreshold(const ktx2::Texture& threshold) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, GLsizei(threshold.levels.size()), GL_R8, GLsizei(threshold.width), GLsizei(threshold.height));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (std::uint32_t level = 0; level < threshold.levels.size(); ++level) {
    glTextureSubImage2D(texture, GLint(level), 0, 0, GLsizei(threshold.levelWidth(level)),
                        GLsizei(threshold.levelHeight(level)), GL_RED, GL_UNSIGNED_BYTE, threshold.levels[level].data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  trilinearRepeating(texture);
  return texture;
}

std::string floatText(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", double(v));
  std::string s = text;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

void setMatrix4(unsigned program, const char* name, const Mat4& m) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

}  // namespace

HatchingRenderer::~HatchingRenderer() {
  if (!textures_.empty()) glDeleteTextures(GLsizei(textures_.size()), textures_.data());
  if (!buffers_.empty()) glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
  if (!vaos_.empty()) glDeleteVertexArrays(GLsizei(vaos_.size()), vaos_.data());
}

Status HatchingRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                 gl::ShaderLibrary& shaders) {
  std::map<std::pair<std::size_t, int>, GLuint> uploadedTams;  // (package, image) -> texture
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Package& package = scene.packages[instance.package];
    const glb::Primitive& primitive = scene.primitive(instance);
    const Location where{scene.files.empty() ? "" : scene.files[instance.package],
                         "material " + std::to_string(primitive.material)};
    Item item;
    BAKE_ASSIGN_OR_RETURN(item.params,
                          parseHatching(scene.material(instance)["extensions"][fmt::kExtension], package, where));
    item.world = instance.world;

    if (primitive.mode != 4) {
      return unsupported("hatching draws triangle lists only (the primitive has glTF mode " +
                             std::to_string(primitive.mode) + ")",
                         where);
    }
    const glb::Attribute* position = primitive.find("POSITION");
    if (!position || position->componentType != glb::ComponentType::F32 || position->components != 3) {
      return invalidInput("the hatched primitive needs float VEC3 POSITION", where);
    }
    const std::vector<float> positions = position->toFloats();
    std::vector<std::uint32_t> triangles = primitive.indices;
    if (triangles.empty()) {
      triangles.resize(positions.size() / 3);
      std::iota(triangles.begin(), triangles.end(), 0u);
    }
    triangles.resize(triangles.size() / 3 * 3);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      if (triangles[i] >= positions.size() / 3) {
        return invalidInput("index " + std::to_string(i) + " (" + std::to_string(triangles[i]) +
                                ") is past the last vertex",
                            where);
      }
    }
    const TriangleAdjacency adjacency = buildTriangleAdjacency(positions, triangles);

    glCreateVertexArrays(1, &item.vao);
    vaos_.push_back(item.vao);
    const GLuint positionBuffer = makeBuffer(positions.data(), positions.size() * sizeof(float));
    const GLuint indexBuffer = makeBuffer(adjacency.indices.data(), adjacency.indices.size() * 4);
    buffers_.insert(buffers_.end(), {positionBuffer, indexBuffer});
    bytes_ += positions.size() * sizeof(float) + adjacency.indices.size() * 4;
    glVertexArrayVertexBuffer(item.vao, 0, positionBuffer, 0, 3 * sizeof(float));
    glVertexArrayAttribFormat(item.vao, kPositionLocation, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(item.vao, kPositionLocation, 0);
    glEnableVertexArrayAttrib(item.vao, kPositionLocation);
    glVertexArrayElementBuffer(item.vao, indexBuffer);
    item.indexCount = int(adjacency.indices.size());

    const auto key = std::make_pair(instance.package, item.params.tamImage);
    if (auto found = uploadedTams.find(key); found != uploadedTams.end()) {
      item.tamTexture = found->second;
    } else {
      item.tamTexture = uploadTam(item.params.tam);
      textures_.push_back(item.tamTexture);
      uploadedTams[key] = item.tamTexture;
      for (const auto& level : item.params.tam.levels) bytes_ += level.size();
    }
    item.params.tam.levels.clear();  // on the GPU now
    if (tone_ == HatchingTone::Threshold && item.params.threshold) {
      item.thresholdTexture = uploadThreshold(*item.params.threshold);
      textures_.push_back(item.thresholdTexture);
      for (const auto& level : item.params.threshold->levels) bytes_ += level.size();
    }
    item.params.threshold.reset();

    gl::Variant variant{{"hatching/hatching.vert", "hatching/hatching.frag", "hatching/hatching.geom", "", ""}, {}};
    variant.defines.push_back("MAX_TONES " + std::to_string(fmt::kMaxTones));
    variant.defines.push_back("MIN_BLEND_COSINE " + floatText(fmt::kMinBlendCosine));
    if (item.params.tam.format == ktx2::Format::RGBA8) variant.defines.push_back("TAM_RGBA");
    if (item.params.orientation == HatchingOrientation::AcrossLight) variant.defines.push_back("ACROSS_LIGHT");
    if (item.thresholdTexture) variant.defines.push_back("THRESHOLD_TONE");
    BAKE_ASSIGN_OR_RETURN(item.program, shaders.program(variant));
    items_.push_back(std::move(item));
  }
  return {};
}

void HatchingRenderer::draw(const FrameContext& frame) {
  const Mat4 viewProjection = multiply(frame.projection, frame.view);
  for (const Item& item : items_) {
    const unsigned program = item.program;
    const HatchingParams& p = item.params;
    glUseProgram(program);
    setMatrix4(program, "uModel", item.world);
    setMatrix4(program, "uViewProj", viewProjection);
    const Mat3 normal = normalMatrix(item.world);
    glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, normal.data());
    const Light& light = frame.light;
    glProgramUniform3fv(program, glGetUniformLocation(program, "uLightDir"), 1, light.direction.data());
    const int kind = light.kind == LightKind::Point ? 1 : light.kind == LightKind::Spot ? 2 : 0;
    glProgramUniform1i(program, glGetUniformLocation(program, "uLightKind"), kind);
    glProgramUniform3fv(program, glGetUniformLocation(program, "uLightPos"), 1, light.position.data());
    const Vec3 objectLight = inverseTransformPoint(item.world, light.position);
    glProgramUniform3fv(program, glGetUniformLocation(program, "uLightPosObject"), 1, objectLight.data());
    glProgramUniform3fv(program, glGetUniformLocation(program, "uSpotDirection"), 1, light.spotDirection.data());
    glProgramUniform1f(program, glGetUniformLocation(program, "uSpotCosCutoff"), std::cos(light.cutoff));
    glProgramUniform1f(program, glGetUniformLocation(program, "uSpotExponent"), light.exponent);
    glProgramUniform1f(program, glGetUniformLocation(program, "uTilesPerUnit"), p.tilesPerUnit);
    glProgramUniform2f(program, glGetUniformLocation(program, "uRotation"), std::cos(p.rotation), std::sin(p.rotation));
    glProgramUniform2fv(program, glGetUniformLocation(program, "uTranslation"), 1, p.translation.data());
    glProgramUniform1i(program, glGetUniformLocation(program, "uToneCount"), GLint(p.tones.size()));
    glProgramUniform1fv(program, glGetUniformLocation(program, "uTones"), GLsizei(p.tones.size()), p.tones.data());
    glProgramUniform3fv(program, glGetUniformLocation(program, "uBaseColor"), 1, p.baseColor.data());
    glProgramUniform1i(program, glGetUniformLocation(program, "uTam"), GLint(kTamUnit));
    glBindTextureUnit(kTamUnit, item.tamTexture);
    if (item.thresholdTexture) {
      glProgramUniform1i(program, glGetUniformLocation(program, "uThreshold"), GLint(kThresholdUnit));
      glProgramUniform1f(program, glGetUniformLocation(program, "uThresholdSoftness"), kThresholdSoftness);
      glBindTextureUnit(kThresholdUnit, item.thresholdTexture);
    }
    glBindVertexArray(item.vao);
    glDrawElements(GL_TRIANGLES_ADJACENCY, item.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindTextureUnit(kTamUnit, 0);
  glBindTextureUnit(kThresholdUnit, 0);
  glBindVertexArray(0);
}

std::size_t HatchingRenderer::gpuBytes() const { return bytes_; }

std::unique_ptr<TechniqueRenderer> hatchingRenderer() { return std::make_unique<HatchingRenderer>(); }

}  // namespace bake::play
