// Paintstroke renderer (seed 002; formats/paintstrokes.md). Per package drawn: read and check the
// BAKE_paintstrokes arrays (paintstrokes_params.cpp), upload strokes, points, styles and shadows as
// they are into one immutable storage buffer (each array at an offset aligned for
// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT), followed by the runtime's index of segments (stroke,
// first control point), one per pair of consecutive control points. Each frame draws every segment as
// a 4-point patch (shaders/paintstrokes/paintstroke.tesc/.tese/.frag) with no vertex attributes;
// the vertex stage names the segment (gl_VertexID / 4) and the control stage fetches its points.
//
// With --stroke-tubes the same package is drawn as fixed tubes built on the CPU at load
// (buildStrokeTubes), back faces culled, through the same fragment shading (the TUBES variant).
//
// Strokes are translucent: blended over what is behind them in a fixed order (stroke by stroke, as
// the package stores them, segment by segment), with the depth test and depth writes on.
//
// Counting: a GL_PRIMITIVES_GENERATED query around the strokes' draw gives the triangles the
// tessellator (or the tube mesh) produced; the control stage adds the vertices of each tessellated
// grid to a small counter buffer. Both are read only when asked (lastFrameCounts), so timed frames do
// not wait for them.
#include "render/paintstrokes.h"

#include <GL/glcorearb.h>
#include <bake_formats/paintstrokes.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>

#include "core/json_keys.h"

namespace bake::play {
namespace {

namespace fmt = format::paintstrokes;

constexpr GLuint kCountersBinding = 5;  // after the package's arrays (bindings 0-4)

std::size_t alignUp(std::size_t x, std::size_t alignment) { return (x + alignment - 1) / alignment * alignment; }

float largestAxisScale(const Mat4& m) {
  float scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, length(Vec3{m[c * 4], m[c * 4 + 1], m[c * 4 + 2]}));
  return scale > 0 ? scale : 1;
}

// Weights of the baked shadow directions for a light direction in model space (formats: weights
// max(dot(L, d_k), 0)^kShadowBlendExponent, normalised; the nearest direction when all are 0).
std::vector<float> shadowWeights(const std::vector<float>& directions, const Vec3& light) {
  const std::size_t count = directions.size() / 3;
  std::vector<float> weights(count, 0.0f);
  if (count == 0) return weights;
  double sum = 0;
  std::size_t nearest = 0;
  float best = -2;
  for (std::size_t k = 0; k < count; ++k) {
    const float d = dot(light, Vec3{directions[3 * k], directions[3 * k + 1], directions[3 * k + 2]});
    if (d > best) best = d, nearest = k;
    weights[k] = float(std::pow(double(std::max(d, 0.0f)), double(fmt::kShadowBlendExponent)));
    sum += weights[k];
  }
  if (!(sum > 1e-30)) {
    std::fill(weights.begin(), weights.end(), 0.0f);
    weights[nearest] = 1;
    return weights;
  }
  for (float& w : weights) w = float(w / sum);
  return weights;
}

// The direction towards the light in the item's model space (the table's directions are there).
Vec3 lightInModel(const Mat4& world, const Vec3& light) {
  const Mat3 n = normalMatrix(world);  // inverse transpose: its transpose is the inverse
  return normalize(Vec3{n[0] * light[0] + n[1] * light[1] + n[2] * light[2], n[3] * light[0] + n[4] * light[1] + n[5] * light[2],
                        n[6] * light[0] + n[7] * light[1] + n[8] * light[2]});
}

Vec3 rotate(const Mat4& m, const Vec3& v) {
  return {m[0] * v[0] + m[4] * v[1] + m[8] * v[2], m[1] * v[0] + m[5] * v[1] + m[9] * v[2], m[2] * v[0] + m[6] * v[1] + m[10] * v[2]};
}

GLint location(unsigned program, const char* name) { return glGetUniformLocation(program, name); }

}  // namespace

PaintstrokesRenderer::~PaintstrokesRenderer() {
  for (const Upload& upload : uploads_) {
    glDeleteBuffers(1, &upload.storage);
    if (upload.tubeVao) {
      glDeleteBuffers(2, upload.tubeBuffers);
      glDeleteVertexArrays(1, &upload.tubeVao);
    }
  }
  if (emptyVao_) glDeleteVertexArrays(1, &emptyVao_);
  if (counters_) glDeleteBuffers(1, &counters_);
  if (query_) glDeleteQueries(1, &query_);
}

Status PaintstrokesRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                     gl::ShaderLibrary& shaders) {
  GLint storageAlignment = 256;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &storageAlignment);
  const std::size_t alignment = std::max<std::size_t>(fmt::kBufferAlignment, std::size_t(std::max(1, storageAlignment)));
  // Keyed by (package, material): one upload however many instances draw it.
  std::map<std::pair<std::size_t, int>, std::size_t> uploadOf;
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Package& package = scene.packages[instance.package];
    const glb::Primitive& primitive = scene.primitive(instance);
    const std::string file = scene.files.empty() ? "" : scene.files[instance.package];
    const auto key = std::make_pair(instance.package, primitive.material);
    if (!uploadOf.count(key)) {
      const nlohmann::json& extension = scene.material(instance)["extensions"][fmt::kExtension];
      BAKE_ASSIGN_OR_RETURN(const paintstrokes::PaintstrokePackage p,
                            readPaintstrokes(package, extension, {file, "material " + std::to_string(primitive.material)}));
      // Segments: one per pair of consecutive control points, in stroke order.
      std::vector<std::uint32_t> segments;
      for (std::size_t s = 0; s < p.strokes.size(); ++s)
        for (std::uint32_t i = 0; i + 1 < p.strokes[s].info[1]; ++i) segments.insert(segments.end(), {std::uint32_t(s), i});
      std::vector<std::uint8_t> shadows = p.shadows;
      shadows.resize(alignUp(std::max<std::size_t>(shadows.size(), 4), 4), 0);
      const std::pair<const void*, std::size_t> arrays[5] = {
          {p.strokes.data(), p.strokes.size() * sizeof(fmt::Stroke)},
          {p.points.data(), p.points.size() * sizeof(fmt::ControlPoint)},
          {p.styles.data(), p.styles.size() * sizeof(fmt::Style)},
          {shadows.data(), shadows.size()},
          {segments.data(), segments.size() * 4}};
      Upload upload;
      std::size_t total = 0;
      for (int k = 0; k < 5; ++k) {
        upload.offset[k] = total;
        upload.size[k] = std::max<std::size_t>(arrays[k].second, 16);  // a binding range is never empty
        total = alignUp(total + upload.size[k], alignment);
      }
      std::vector<std::uint8_t> bytes(total, 0);
      for (int k = 0; k < 5; ++k)
        if (arrays[k].second) std::memcpy(bytes.data() + upload.offset[k], arrays[k].first, arrays[k].second);
      glCreateBuffers(1, &upload.storage);
      glNamedBufferStorage(upload.storage, GLsizeiptr(bytes.size()), bytes.data(), 0);
      bytes_ += bytes.size();
      upload.segmentCount = std::uint32_t(segments.size() / 2);
      upload.shadowDirections = std::uint32_t(p.shadowDirections.size());
      for (const auto& d : p.shadowDirections) upload.directions.insert(upload.directions.end(), d.begin(), d.end());
      upload.strokes = p.strokes.size();
      upload.points = p.points.size();
      if (options_.tubes()) {
        const TubeMesh tubes = buildStrokeTubes(p, options_.tubeSides, options_.tubeSteps);
        glCreateVertexArrays(1, &upload.tubeVao);
        glCreateBuffers(2, upload.tubeBuffers);
        glNamedBufferStorage(upload.tubeBuffers[0], GLsizeiptr(std::max<std::size_t>(tubes.vertices.size() * sizeof(TubeVertex), 4)),
                             tubes.vertices.data(), 0);
        glNamedBufferStorage(upload.tubeBuffers[1], GLsizeiptr(std::max<std::size_t>(tubes.indices.size() * 4, 4)),
                             tubes.indices.data(), 0);
        bytes_ += tubes.vertices.size() * sizeof(TubeVertex) + tubes.indices.size() * 4;
        const GLuint vao = upload.tubeVao;
        glVertexArrayVertexBuffer(vao, 0, upload.tubeBuffers[0], 0, sizeof(TubeVertex));
        glVertexArrayElementBuffer(vao, upload.tubeBuffers[1]);
        const struct {
          GLuint location;
          GLint components;
          std::size_t offset;
          bool integer;
        } attributes[] = {{0, 3, offsetof(TubeVertex, position), false}, {1, 3, offsetof(TubeVertex, normal), false},
                          {2, 3, offsetof(TubeVertex, tangent), false},  {3, 1, offsetof(TubeVertex, t), false},
                          {4, 1, offsetof(TubeVertex, point), true},     {5, 1, offsetof(TubeVertex, stroke), true}};
        for (const auto& a : attributes) {
          if (a.integer) {
            glVertexArrayAttribIFormat(vao, a.location, a.components, GL_UNSIGNED_INT, GLuint(a.offset));
          } else {
            glVertexArrayAttribFormat(vao, a.location, a.components, GL_FLOAT, GL_FALSE, GLuint(a.offset));
          }
          glVertexArrayAttribBinding(vao, a.location, 0);
          glEnableVertexArrayAttrib(vao, a.location);
        }
        upload.tubeIndexCount = std::uint32_t(tubes.indices.size());
        upload.tubeVertexCount = std::uint32_t(tubes.vertices.size());
      }
      uploadOf[key] = uploads_.size();
      uploads_.push_back(std::move(upload));
    }
    items_.push_back({uploadOf[key], instance.world});
  }

  gl::Variant variant;
  variant.defines.push_back("MAX_SHADOW_DIRECTIONS " + std::to_string(fmt::kMaxShadowDirections));
  if (options_.tubes()) {
    variant.program = {"paintstrokes/tube.vert", "paintstrokes/paintstroke.frag", "", "", ""};
    variant.defines.push_back("TUBES");
  } else {
    variant.program = {"paintstrokes/paintstroke.vert", "paintstrokes/paintstroke.frag", "", "paintstrokes/paintstroke.tesc",
                       "paintstrokes/paintstroke.tese"};
    variant.defines.push_back("POLYGONS_ACROSS " + std::to_string(fmt::kPolygonsAcross[options_.quality]));
  }
  BAKE_ASSIGN_OR_RETURN(program_, shaders.program(variant));
  glCreateVertexArrays(1, &emptyVao_);
  glCreateBuffers(1, &counters_);
  glNamedBufferStorage(counters_, 8, nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
  glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query_);
  return {};
}

void PaintstrokesRenderer::draw(const FrameContext& frame) {
  if (items_.empty()) return;
  const unsigned program = program_;
  glUseProgram(program);
  const Mat4& projection = frame.projection;
  const bool orthographic = projection[15] == 1.0f && projection[11] == 0.0f;
  glProgramUniformMatrix4fv(program, location(program, "uProjection"), 1, GL_FALSE, projection.data());
  glProgramUniform1i(program, location(program, "uOrthographic"), orthographic ? 1 : 0);
  glProgramUniform2f(program, location(program, "uPixelScale"), projection[0] * float(frame.width) * 0.5f,
                     projection[5] * float(frame.height) * 0.5f);
  glProgramUniform1f(program, location(program, "uTolerance"), options_.tolerance);
  GLint maxLevel = 64;
  glGetIntegerv(GL_MAX_TESS_GEN_LEVEL, &maxLevel);
  glProgramUniform1f(program, location(program, "uMaxLevel"), float(maxLevel));
  const Vec3 lightView = normalize(rotate(frame.view, frame.light.direction));
  glProgramUniform3fv(program, location(program, "uLightView"), 1, lightView.data());
  glProgramUniform3fv(program, location(program, "uLightColour"), 1, frame.light.colour.data());

  const GLuint zero = 0;
  glClearNamedBufferData(counters_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, counters_);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // the frame stays opaque
  if (options_.tubes()) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
  } else {
    glPatchParameteri(GL_PATCH_VERTICES, 4);
  }
  glBeginQuery(GL_PRIMITIVES_GENERATED, query_);
  for (const Item& item : items_) {
    const Upload& upload = uploads_[item.upload];
    const Mat4 modelView = multiply(frame.view, item.world);
    glProgramUniformMatrix4fv(program, location(program, "uModelView"), 1, GL_FALSE, modelView.data());
    const Mat3 normalView = normalMatrix(modelView);
    glProgramUniformMatrix3fv(program, location(program, "uNormalView"), 1, GL_FALSE, normalView.data());
    glProgramUniform1f(program, location(program, "uRadiusScale"), largestAxisScale(item.world));
    const std::vector<float> weights = shadowWeights(upload.directions, lightInModel(item.world, frame.light.direction));
    glProgramUniform1i(program, location(program, "uShadowCount"), GLint(weights.size()));
    if (!weights.empty())
      glProgramUniform1fv(program, location(program, "uShadowWeight"), GLsizei(weights.size()), weights.data());
    for (GLuint k = 0; k < 5; ++k)
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, k, upload.storage, GLintptr(upload.offset[k]), GLsizeiptr(upload.size[k]));
    if (options_.tubes()) {
      glBindVertexArray(upload.tubeVao);
      glDrawElements(GL_TRIANGLES, GLsizei(upload.tubeIndexCount), GL_UNSIGNED_INT, nullptr);
    } else if (upload.segmentCount > 0) {
      glBindVertexArray(emptyVao_);
      glDrawArrays(GL_PATCHES, 0, GLsizei(4 * upload.segmentCount));
    }
  }
  glEndQuery(GL_PRIMITIVES_GENERATED);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glBindVertexArray(0);
  for (GLuint k = 0; k <= kCountersBinding; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, 0);
  drawn_ = true;
}

PaintstrokeCounts PaintstrokesRenderer::lastFrameCounts() const {
  PaintstrokeCounts counts;
  if (!drawn_) return counts;
  GLuint64 primitives = 0;
  glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &primitives);
  counts.polygons = primitives;
  for (const Item& item : items_) counts.segments += uploads_[item.upload].segmentCount;
  if (options_.tubes()) {
    for (const Item& item : items_) {
      counts.vertices += uploads_[item.upload].tubeVertexCount;
      counts.predictedPolygons += uploads_[item.upload].tubeIndexCount / 3;
    }
  } else {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint values[2] = {0, 0};
    glGetNamedBufferSubData(counters_, 0, sizeof values, values);
    counts.predictedPolygons = values[0];
    counts.vertices = values[1];
  }
  return counts;
}

nlohmann::json PaintstrokesRenderer::statistics() const {
  const PaintstrokeCounts counts = lastFrameCounts();
  std::size_t strokes = 0, points = 0;
  for (const Item& item : items_) strokes += uploads_[item.upload].strokes, points += uploads_[item.upload].points;
  nlohmann::json out = {{"strokeMode", options_.tubes() ? "tubes" : "tessellated"},
                        {"strokePolygons", counts.polygons},
                        {"strokeVertices", counts.vertices},
                        {"strokeSegments", counts.segments},
                        {"strokeCount", strokes},
                        {"strokeControlPoints", points}};
  if (options_.tubes()) {
    out["strokeTubes"] = {options_.tubeSides, options_.tubeSteps};
  } else {
    out["strokeQuality"] = options_.quality;
    out["strokePolygonsAcross"] = fmt::kPolygonsAcross[options_.quality];
    out["strokeTolerancePx"] = std::round(double(options_.tolerance) * 1e6) / 1e6;  // as given, not float noise
  }
  return out;
}

std::size_t PaintstrokesRenderer::gpuBytes() const { return bytes_; }

std::unique_ptr<TechniqueRenderer> paintstrokesRenderer() { return std::make_unique<PaintstrokesRenderer>(); }

}  // namespace bake::play
