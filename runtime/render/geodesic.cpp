// GeoTextures renderer (seed 003 sections 5.2.3-5.3, Appendix C). Per material: parse the preset and
// its parameters (geodesic_params.cpp), pick the field attributes it reads (slot i <- _GEODESIC_fields[i]), compile the
// variant (PRESET_*, FIELD_COUNT, FIELD_UNORM16, COMBINE_MIN, HAS_NORMALS, DISPLACE with the
// tessellation stages) and upload only those attributes. Per frame: uniforms, then opaque fragments
// of every item, then the translucent ones (opacity-front) blended without depth writes.
// Noise coordinates are object positions over the bounding radius, so parameters do not depend on the
// model's size.
#include "render/geodesic.h"

#include <GL/glcorearb.h>
#include <bake_formats/geodesic.h>

#include <algorithm>
#include <cmath>
#include <map>


namespace bake::play {
namespace {

using namespace geodesic::material_detail;
namespace fmt = format::geodesic;

constexpr int kPositionLocation = 0;
constexpr int kNormalLocation = 1;
constexpr int kFirstFieldLocation = 3;

// ---------------------------------------------------------------------------------------------
// Geometry helpers

struct Bounds {
  Vec3 centre{0, 0, 0};
  float radius = 1;
};

Bounds boundsOf(const glb::Primitive& primitive) {
  const glb::Attribute* position = primitive.find("POSITION");
  if (!position) return {};
  const std::vector<float> p = position->toFloats();
  if (p.size() < 3) return {};
  Vec3 lo{p[0], p[1], p[2]}, hi = lo;
  for (std::size_t v = 0; v + 2 < p.size(); v += 3) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[v + k]);
      hi[k] = std::max(hi[k], p[v + k]);
    }
  }
  Bounds bounds{(lo + hi) * 0.5f, 0};
  for (std::size_t v = 0; v + 2 < p.size(); v += 3) {
    bounds.radius = std::max(bounds.radius, length(Vec3{p[v], p[v + 1], p[v + 2]} - bounds.centre));
  }
  if (!(bounds.radius > 0)) bounds.radius = 1;
  return bounds;
}

float largestAxisScale(const Mat4& m) {
  float scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, length(Vec3{m[c * 4], m[c * 4 + 1], m[c * 4 + 2]}));
  return scale > 0 ? scale : 1;
}

// Area-weighted vertex normals of a triangle list, summed over every vertex at the same position, so
// vertices split at seams agree: displacement along them opens no cracks between patches.
glb::Attribute smoothNormals(const glb::Primitive& primitive) {
  const std::vector<float> p = primitive.find("POSITION")->toFloats();
  const std::size_t vertices = p.size() / 3;
  auto corner = [&](std::size_t i) {
    return primitive.indices.empty() ? i : std::size_t(primitive.indices[i]);
  };
  const std::size_t corners = primitive.indices.empty() ? vertices : primitive.indices.size();
  auto at = [&](std::size_t v) { return Vec3{p[3 * v], p[3 * v + 1], p[3 * v + 2]}; };
  std::map<Vec3, Vec3> byPosition;
  for (std::size_t c = 0; c + 2 < corners; c += 3) {
    const std::size_t a = corner(c), b = corner(c + 1), d = corner(c + 2);
    if (a >= vertices || b >= vertices || d >= vertices) continue;
    const Vec3 n = cross(at(b) - at(a), at(d) - at(a));  // length = twice the area
    for (std::size_t v : {a, b, d}) byPosition[at(v)] = byPosition[at(v)] + n;
  }
  std::vector<float> normals(vertices * 3, 0.0f);
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3 n = normalize(byPosition[at(v)]);
    std::copy(n.begin(), n.end(), normals.begin() + std::ptrdiff_t(3 * v));
  }
  return glb::Attribute::fromFloats("NORMAL", 3, normals);
}


void setFloat(unsigned program, const char* name, float value) {
  glProgramUniform1f(program, glGetUniformLocation(program, name), value);
}
void setVec3(unsigned program, const char* name, const std::array<float, 3>& v) {
  glProgramUniform3fv(program, glGetUniformLocation(program, name), 1, v.data());
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Scene preparation

Status attachGeoTextures(Scene& scene, const std::string& preset) {
  if (!preset.empty() && !geoPresetFromName(preset)) {
    std::string known;
    for (const std::string& n : geoPresetNames()) known += (known.empty() ? "" : ", ") + n;
    return usageError("--geotexture \"" + preset + "\" is not a preset (known: " + known + ")");
  }
  std::map<std::pair<std::size_t, int>, int> added;  // (package, old material) -> new material
  for (const Instance& instance : scene.instances) {
    glb::Package& package = scene.packages[instance.package];
    glb::Primitive& primitive = package.meshes[instance.mesh].primitives[instance.primitive];
    if (geodesicFieldsOf(primitive).empty()) continue;
    const std::string technique = scene.technique(instance);
    if (technique == fmt::kExtension) {
      if (!preset.empty())
        package.materials[std::size_t(primitive.material)]["extensions"][fmt::kExtension]["texture"] = preset;
      continue;
    }
    // A bare primitive gets the default only in a BAKE_geodesic package (else _GEODESIC_k is just an
    // application attribute); --geotexture asks for it explicitly.
    if (!technique.empty() || (preset.empty() && !package.extensions.contains(fmt::kExtension))) continue;
    const auto key = std::make_pair(instance.package, primitive.material);
    if (auto found = added.find(key); found != added.end()) {
      primitive.material = found->second;
      continue;
    }
    nlohmann::json material =
        scene.material(instance).is_object() ? scene.material(instance) : nlohmann::json::object();
    material["extensions"][fmt::kExtension] = {{"version", fmt::kVersion},
                                               {"texture", preset.empty() ? "isolines" : preset}};
    package.materials.push_back(std::move(material));
    primitive.material = int(package.materials.size()) - 1;
    added[key] = primitive.material;
  }
  return {};
}

// ---------------------------------------------------------------------------------------------
// The renderer

constexpr GLuint kEnvironmentUnit = 0;

// The equirectangular environment as an RGB float texture: repeating across (the longitude wraps),
// clamped down (the poles), linear, no mipmaps (the reflected direction's derivatives jump at the
// seam).
GLuint uploadEnvironment(const Image& image) {
  std::vector<float> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3 + std::size_t(c)] =
            image.at(x, y, image.channels >= 3 ? c : 0);
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, GL_RGB32F, image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture, 0, 0, 0, image.width, image.height, GL_RGB, GL_FLOAT, rgb.data());
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

GeodesicRenderer::~GeodesicRenderer() {
  if (environmentTexture_) glDeleteTextures(1, &environmentTexture_);
}

Status GeodesicRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                 gl::ShaderLibrary& shaders) {
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Primitive& primitive = scene.primitive(instance);
    const Location where{
        scene.files.empty() ? "" : scene.files[instance.package],
        "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(instance.primitive)};
    const nlohmann::json& material = scene.material(instance);
    Item item;
    BAKE_ASSIGN_OR_RETURN(item.params, parseGeoTexture(material["extensions"][fmt::kExtension], where));
    GeoTextureParams& params = item.params;
    BAKE_ASSIGN_OR_RETURN(const std::vector<int> fields, resolveFields(params, primitive, where));
    params.fields = fields;

    gl::Variant variant{{"geodesic/geotexture.vert", "geodesic/geotexture.frag", "", "", ""}, {}};
    variant.defines.push_back(infoOf(params.preset).define);
    variant.defines.push_back("FIELD_COUNT " + std::to_string(fields.size()));
    if (params.combineMin) variant.defines.push_back("COMBINE_MIN");
    // Patches need triangle lists; strips and fans fall back to bump-only waves.
    item.tessellated =
        params.preset == GeoPreset::WaveDisplacement && params.wave.displace && primitive.mode == 4;
    // Displacement needs one normal per position; a primitive without normals gets smooth ones.
    std::optional<glb::Primitive> withNormals;
    if (item.tessellated && !primitive.find("NORMAL")) {
      withNormals = primitive;
      withNormals->attributes.push_back(smoothNormals(primitive));
    }
    const glb::Primitive& drawn = withNormals ? *withNormals : primitive;
    std::map<std::string, int> locations = {{"POSITION", kPositionLocation}};
    if (drawn.find("NORMAL")) {
      variant.defines.push_back("HAS_NORMALS");
      locations["NORMAL"] = kNormalLocation;
    }
    bool unorm = false;
    const glb::Package& package = scene.packages[instance.package];
    for (std::size_t slot = 0; slot < fields.size(); ++slot) {
      const glb::Attribute& attribute = *primitive.find(attributeName(fields[slot]));
      BAKE_RETURN_IF_ERROR(checkFieldAttribute(attribute, where, storesModelUnits(package)));
      item.fieldScale[slot] = normalisingFactor(package, attribute.name);
      const bool isUnorm = attribute.componentType == glb::ComponentType::U16;
      if (slot > 0 && isUnorm != unorm)
        return invalidInput("the fields a material reads mix encodings", where);
      unorm = isUnorm;
      locations[attribute.name] = kFirstFieldLocation + int(slot);
    }
    if (unorm) variant.defines.push_back("FIELD_UNORM16");
    if (item.tessellated) {
      variant.program.tessControl = "geodesic/geotexture.tesc";
      variant.program.tessEvaluation = "geodesic/geotexture.tese";
      variant.defines.push_back("DISPLACE");
    }
    if (environment_ && params.preset == GeoPreset::WaveDisplacement) {
      if (!environmentTexture_) environmentTexture_ = uploadEnvironment(*environment_);
      variant.defines.push_back("ENVIRONMENT_MAP");
    }
    item.translucent = params.preset == GeoPreset::OpacityFront;
    if (item.translucent) variant.defines.push_back("TRANSLUCENT");

    BAKE_ASSIGN_OR_RETURN(item.program, shaders.program(variant));
    BAKE_ASSIGN_OR_RETURN(item.gpu, GpuPrimitive::upload(drawn, locations));
    const Bounds bounds = boundsOf(primitive);
    item.objectCentre = bounds.centre;
    item.objectRadius = bounds.radius;
    item.world = instance.world;
    item.worldScale = largestAxisScale(instance.world);
    items_.push_back(std::move(item));
  }
  return {};
}

void GeodesicRenderer::setUniforms(const Item& item, const FrameContext& frame) const {
  const unsigned program = item.program;
  const GeoTextureParams& p = item.params;
  const Mat4 viewProjection = multiply(frame.projection, frame.view);
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uModel"), 1, GL_FALSE, item.world.data());
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "uViewProj"), 1, GL_FALSE,
                            viewProjection.data());
  const Mat3 normal = normalMatrix(item.world);
  glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE,
                            normal.data());
  setVec3(program, "uLightDir", frame.light.direction);
  setVec3(program, "uLightColour", frame.light.colour);
  setVec3(program, "uCameraPos", frame.camera.eye);
  setVec3(program, "uObjectCentre", item.objectCentre);
  setFloat(program, "uObjectRadius", item.objectRadius);
  setFloat(program, "uHeightScale", item.objectRadius * item.worldScale);
  glProgramUniform4fv(program, glGetUniformLocation(program, "uFieldScale"), 1, item.fieldScale.data());

  setFloat(program, "uTime", frame.time);
  setFloat(program, "uSpeed", p.speed);
  glProgramUniform4fv(program, glGetUniformLocation(program, "uThresholds"), 1, p.thresholds.data());
  glProgramUniform4fv(program, glGetUniformLocation(program, "uWidths"), 1, p.widths.data());
  glProgramUniform2f(program, glGetUniformLocation(program, "uFrontNoise"), p.noiseFrequency,
                     p.noiseAmplitude);
  setFloat(program, "uPatternScale", p.patternScale);
  setFloat(program, "uBumpScale", p.bumpScale);
  glProgramUniform3fv(program, glGetUniformLocation(program, "uColours"), 4, p.colours[0].data());
  setVec3(program, "uUnreachableColour", p.unreachableColour);
  setFloat(program, "uIsolineSpacing", p.isolineSpacing);
  setFloat(program, "uIsolineWidth", p.isolineWidth);
  setVec3(program, "uIsolineColour", p.isolineColour);
  setFloat(program, "uOpacity", p.opacity);

  glProgramUniform4f(program, glGetUniformLocation(program, "uWave"), p.wave.amplitude, p.wave.wavelength,
                     p.wave.reach, 0);
  setFloat(program, "uWaveFront0", p.thresholds[0] + p.speed * frame.time);
  setFloat(program, "uWaveFront1", p.thresholds[1] + p.speed * frame.time);
  glProgramUniform2f(program, glGetUniformLocation(program, "uViewport"), float(frame.width),
                     float(frame.height));
  setFloat(program, "uPixelsPerEdge", p.wave.pixelsPerEdge);
  setFloat(program, "uMaxLevel", p.wave.maxLevel);
}

void GeodesicRenderer::drawItem(const Item& item, int pass) const {
  glUseProgram(item.program);
  if (environmentTexture_) {
    glProgramUniform1i(item.program, glGetUniformLocation(item.program, "uEnvironmentMap"), GLint(kEnvironmentUnit));
    glBindTextureUnit(kEnvironmentUnit, environmentTexture_);
  }
  glProgramUniform1i(item.program, glGetUniformLocation(item.program, "uPass"), pass);
  if (item.tessellated) {
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    item.gpu.drawAsPatches();
  } else {
    item.gpu.draw();
  }
}

void GeodesicRenderer::draw(const FrameContext& frame) {
  for (const Item& item : items_) {
    setUniforms(item, frame);
    drawItem(item, 0);
  }
  // Translucent parts after every opaque one, blended over them; they test depth but do not write it.
  // Destination alpha is kept, so the frame stays opaque.
  bool any = false;
  for (const Item& item : items_) any = any || item.translucent;
  if (!any) return;
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  glDepthMask(GL_FALSE);
  for (const Item& item : items_) {
    if (item.translucent) drawItem(item, 1);
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

std::size_t GeodesicRenderer::gpuBytes() const {
  std::size_t total = 0;
  if (environmentTexture_) total += std::size_t(environment_->width) * std::size_t(environment_->height) * 12;
  for (const Item& item : items_) total += item.gpu.uploadedBytes();
  return total;
}

std::unique_ptr<TechniqueRenderer> geodesicRenderer() { return std::make_unique<GeodesicRenderer>(); }

}  // namespace bake::play
