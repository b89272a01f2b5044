// Revolution mapping renderer (seed 001; formats/revolution.md). Per instance: read the material's
// BAKE_revolution object, upload the shape map as a 2D texture in its own encoding (RGBA32F, RGBA16
// or RGBA8; linear filtering; S mirrored at the axis, T clamped), the optional displacement (RG16,
// repeating) and arc-length (R16) maps and the base colour image (sRGB, mipmapped), and compile the
// variant of shaders/revolution/ for its encoding, projection and maps. The drawn box is the mesh's
// bounding box within the shape map's own box, rebuilt here with outward winding so its back faces
// can be drawn: every ray through the box then gets exactly one fragment, even from inside it.
#include "render/revolution.h"

#include <GL/glcorearb.h>
#include <bake_formats/revolution.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "bake/io/image.h"
#include "render/standard.h"

namespace bake::play {
namespace {

namespace fmt = format::revolution;

constexpr int kPositionLocation = 0;
constexpr GLuint kShapeUnit = 0, kDisplacementUnit = 1, kArcLengthUnit = 2, kBaseColourUnit = 3;

// ---------------------------------------------------------------------------------------------
// Matrices

double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Inverse by cofactors, in double (the clip-to-object matrix spans near and far planes).
Mat4 inverse(const Mat4& m) {
  auto at = [&](int r, int c) { return double(m[std::size_t(c * 4 + r)]); };
  double cof[4][4];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      double minor[3][3];
      for (int i = 0, mi = 0; i < 4; ++i) {
        if (i == r) continue;
        for (int j = 0, mj = 0; j < 4; ++j) {
          if (j == c) continue;
          minor[mi][mj++] = at(i, j);
        }
        ++mi;
      }
      cof[r][c] = ((r + c) % 2 ? -1.0 : 1.0) * det3(minor);
    }
  }
  double det = 0;
  for (int c = 0; c < 4; ++c) det += at(0, c) * cof[0][c];
  Mat4 out{};
  if (det == 0) return out;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out[std::size_t(r * 4 + c)] = float(cof[r][c] / det);  // transpose of cofactors
  }
  return out;
}

bool mirrors(const Mat4& m) {
  const double a[3][3] = {{m[0], m[4], m[8]}, {m[1], m[5], m[9]}, {m[2], m[6], m[10]}};
  return det3(a) < 0;
}

// ---------------------------------------------------------------------------------------------
// The shape box

struct Box {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

// The box the march is rasterised over: the shape map's own (r <= rMax, h in the map's rows), where
// every sample lies, grown to hold every copy when the package has replicas. The node's mesh is the
// package's preview for viewers without BAKE_revolution (a coarse revolved mesh), never the march's
// bound: its chords cut inside convex arcs.
Result<Box> drawnBox(const RevolutionParams& params, const Location& where) {
  const auto lo = params.boxMin(), hi = params.boxMax();
  const Box box{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
  for (std::size_t k = 0; k < 3; ++k)
    if (!(box.lo[k] < box.hi[k])) return invalidInput("the shape map's box is empty", where);
  return box;
}

// Twelve counter-clockwise (seen from outside) triangles of an axis-aligned box.
glb::Primitive boxPrimitive(const Box& box) {
  std::vector<float> corners;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(i & 1 ? box.hi[0] : box.lo[0]);
    corners.push_back(i & 2 ? box.hi[1] : box.lo[1]);
    corners.push_back(i & 4 ? box.hi[2] : box.lo[2]);
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, corners));
  primitive.indices = {0, 4, 6, 0, 6, 2,   // -x
                       1, 3, 7, 1, 7, 5,   // +x
                       0, 1, 5, 0, 5, 4,   // -y
                       2, 6, 7, 2, 7, 3,   // +y
                       0, 2, 3, 0, 3, 1,   // -z
                       4, 5, 7, 4, 7, 6};  // +z
  return primitive;
}

// ---------------------------------------------------------------------------------------------
// Textures

struct TextureFormat {
  GLenum internal, format, type;
};

TextureFormat shapeFormat(ShapeEncoding encoding) {
  switch (encoding) {
    case ShapeEncoding::Float: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case ShapeEncoding::Unorm16: return {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT};
    case ShapeEncoding::Sqrt8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
  }
  return {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT};
}

GLuint makeTexture(int width, int height, const TextureFormat& f, const void* texels, GLenum wrapS, GLenum wrapT,
                   bool mipmapped = false) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  int levels = 1;
  if (mipmapped) {
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  }
  glTextureStorage2D(texture, levels, f.internal, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture, 0, 0, 0, width, height, f.format, f.type, texels);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (mipmapped) glGenerateTextureMipmap(texture);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, mipmapped ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GLint(wrapS));
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GLint(wrapT));
  return texture;
}

std::string extensionOfMimeType(const std::string& mime) {
  if (mime == "image/jpeg") return ".jpg";
  if (mime == "image/ktx2") return ".ktx2";
  return ".png";
}

// The material's base colour image (decoded), if it has one.
Result<std::optional<Image>> baseColourImage(const nlohmann::json& material, const glb::Package& package,
                                             const Location& where) {
  BAKE_ASSIGN_OR_RETURN(const std::optional<EmbeddedImage> embedded, baseColourTextureOf(material, package, where));
  if (!embedded) return std::optional<Image>();
  const std::string name = where.file + " image " + std::to_string(embedded->image);
  BAKE_ASSIGN_OR_RETURN(Image decoded, readImageFromMemory(package.blobs[embedded->bufferView].bytes, name,
                                                           extensionOfMimeType(embedded->mimeType)));
  return std::optional<Image>(std::move(decoded));
}

// RGBA8 texels of an image with 1 to 4 channels (grey repeats, missing alpha is opaque).
std::vector<std::uint8_t> rgba8(const Image& image) {
  std::vector<std::uint8_t> out(std::size_t(image.width) * std::size_t(image.height) * 4);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        float v = 1.0f;
        if (c < 3) v = image.at(x, y, image.channels >= 3 ? c : 0);
        if (c == 3 && (image.channels == 4 || image.channels == 2)) v = image.at(x, y, image.channels - 1);
        out[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 + std::size_t(c)] =
            std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
    }
  }
  return out;
}

const char* encodingDefine(ShapeEncoding encoding) {
  switch (encoding) {
    case ShapeEncoding::Float: return "ENCODING_FLOAT";
    case ShapeEncoding::Unorm16: return "ENCODING_UNORM16";
    case ShapeEncoding::Sqrt8: return "ENCODING_SQRT8";
  }
  return "ENCODING_UNORM16";
}

const char* projectionDefine(RevolutionProjection projection) {
  switch (projection) {
    case RevolutionProjection::Cylindrical: return "PROJECTION_CYLINDRICAL";
    case RevolutionProjection::Spherical: return "PROJECTION_SPHERICAL";
    case RevolutionProjection::ArcLength: return "PROJECTION_ARC_LENGTH";
  }
  return "PROJECTION_CYLINDRICAL";
}

void setMatrix(unsigned program, const char* name, const Mat4& m) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

}  // namespace

RevolutionRenderer::~RevolutionRenderer() {
  if (!textures_.empty()) glDeleteTextures(GLsizei(textures_.size()), textures_.data());
}

Status RevolutionRenderer::prepare(const Scene& scene, const std::vector<std::size_t>& instances,
                                   gl::ShaderLibrary& shaders) {
  // Maps shared by several instances of one package are uploaded once: (package, bufferView or
  // material, kind) -> texture.
  std::map<std::tuple<std::size_t, int, int>, GLuint> uploaded;
  auto texture = [&](std::size_t package, int view, int kind, const auto& make) {
    const auto key = std::make_tuple(package, view, kind);
    if (auto found = uploaded.find(key); found != uploaded.end()) return found->second;
    const GLuint made = make();
    textures_.push_back(made);
    uploaded[key] = made;
    return made;
  };
  for (std::size_t index : instances) {
    const Instance& instance = scene.instances[index];
    const glb::Package& package = scene.packages[instance.package];
    const nlohmann::json& material = scene.material(instance);
    const Location where{scene.files.empty() ? "" : scene.files[instance.package],
                         "material " + std::to_string(scene.primitive(instance).material)};
    Item item;
    BAKE_ASSIGN_OR_RETURN(item.params, parseRevolution(material["extensions"][fmt::kExtension], package, where));
    const RevolutionParams& p = item.params;
    BAKE_ASSIGN_OR_RETURN(const Box box, drawnBox(p, where));
    item.boxMin = box.lo;
    item.boxMax = box.hi;
    BAKE_ASSIGN_OR_RETURN(item.box, GpuPrimitive::upload(boxPrimitive(box), {{"POSITION", kPositionLocation}}));
    item.world = instance.world;
    item.baseColour = baseColourOf(material);

    gl::Variant variant{{"revolution/revolution.vert", "revolution/revolution.frag", "", "", ""}, {}};
    variant.defines.push_back(encodingDefine(p.shapeMap.encoding));
    variant.defines.push_back(projectionDefine(p.projection));
    variant.defines.push_back("MAX_PROXY_BANDS " + std::to_string(fmt::kMaxProxyBands));
    if (p.replicas.layout == RevolutionParams::Replicas::Layout::Grid) variant.defines.push_back("REPLICAS_GRID");
    if (p.replicas.layout == RevolutionParams::Replicas::Layout::Ring) variant.defines.push_back("REPLICAS_RING");
    if (p.selfShadow) variant.defines.push_back("SELF_SHADOW");

    const auto& shapeBlob = package.blobs[std::size_t(p.shapeMap.bufferView)].bytes;
    item.shapeTexture = texture(instance.package, p.shapeMap.bufferView, 0, [&] {
      bytes_ += shapeBlob.size();
      return makeTexture(p.shapeMap.width, p.shapeMap.height, shapeFormat(p.shapeMap.encoding), shapeBlob.data(),
                         GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE);
    });
    if (p.displacement) {
      variant.defines.push_back("HAS_DISPLACEMENT");
      const auto& blob = package.blobs[std::size_t(p.displacement->bufferView)].bytes;
      item.displacementTexture = texture(instance.package, p.displacement->bufferView, 1, [&] {
        bytes_ += blob.size();
        return makeTexture(p.displacement->width, p.displacement->height, {GL_RG16, GL_RG, GL_UNSIGNED_SHORT},
                           blob.data(), GL_REPEAT, GL_REPEAT);
      });
    }
    if (p.projection == RevolutionProjection::ArcLength) {  // parseRevolution made sure the map is there
      const auto& blob = package.blobs[std::size_t(*p.arcLengthBufferView)].bytes;
      item.arcLengthTexture = texture(instance.package, *p.arcLengthBufferView, 2, [&] {
        bytes_ += blob.size();
        return makeTexture(p.shapeMap.width, p.shapeMap.height, {GL_R16, GL_RED, GL_UNSIGNED_SHORT}, blob.data(),
                           GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE);
      });
    }
    BAKE_ASSIGN_OR_RETURN(const std::optional<Image> colour, baseColourImage(material, package, where));
    if (colour) {
      variant.defines.push_back("HAS_BASE_COLOR_TEXTURE");
      const std::vector<std::uint8_t> texels = rgba8(*colour);
      item.colourTexture = texture(instance.package, scene.primitive(instance).material, 3, [&] {
        bytes_ += texels.size() * 4 / 3;  // with its mip chain
        return makeTexture(colour->width, colour->height, {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE},
                           texels.data(), GL_REPEAT, GL_REPEAT, true);
      });
    }
    BAKE_ASSIGN_OR_RETURN(item.program, shaders.program(variant));
    items_.push_back(std::move(item));
  }
  return {};
}

void RevolutionRenderer::setUniforms(const Item& item, const FrameContext& frame) const {
  const unsigned program = item.program;
  const RevolutionParams& p = item.params;
  const Mat4 objectToClip = multiply(multiply(frame.projection, frame.view), item.world);
  setMatrix(program, "uObjectToClip", objectToClip);
  setMatrix(program, "uClipToObject", inverse(objectToClip));
  setMatrix(program, "uModel", item.world);
  const Mat3 normal = normalMatrix(item.world);
  glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "uNormalMatrix"), 1, GL_FALSE, normal.data());
  glProgramUniform2f(program, glGetUniformLocation(program, "uViewport"), float(frame.width), float(frame.height));
  glProgramUniform4f(program, glGetUniformLocation(program, "uShapeGrid"), float(p.shapeMap.width),
                     float(p.shapeMap.height), p.shapeMap.texelSize, p.shapeMap.hMin);
  glProgramUniform1f(program, glGetUniformLocation(program, "uDistanceScale"), p.shapeMap.distanceScale);
  glProgramUniform1f(program, glGetUniformLocation(program, "uSafetyMargin"), p.safetyMargin);
  glProgramUniform1f(program, glGetUniformLocation(program, "uHitEpsilon"), p.hitEpsilon);
  glProgramUniform1f(program, glGetUniformLocation(program, "uOverRelaxation"), p.overRelaxation);
  glProgramUniform1i(program, glGetUniformLocation(program, "uIterations"), p.iterations);
  // One copy's box (the march's), and every copy's (the cells' walk).
  const float rMax = p.shapeMap.rMax();
  glProgramUniform3f(program, glGetUniformLocation(program, "uBoxMin"), -rMax, p.shapeMap.hMin, -rMax);
  glProgramUniform3f(program, glGetUniformLocation(program, "uBoxMax"), rMax, p.shapeMap.hMax(), rMax);
  glProgramUniform3fv(program, glGetUniformLocation(program, "uReplicaBoxMin"), 1, item.boxMin.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uReplicaBoxMax"), 1, item.boxMax.data());
  const auto& replicas = p.replicas;
  glProgramUniform3i(program, glGetUniformLocation(program, "uGridCount"), replicas.count[0], replicas.count[1],
                     replicas.count[2]);
  glProgramUniform3fv(program, glGetUniformLocation(program, "uGridSpacing"), 1, replicas.spacing.data());
  glProgramUniform3i(program, glGetUniformLocation(program, "uGridMirror"), replicas.mirror[0], replicas.mirror[1],
                     replicas.mirror[2]);
  glProgramUniform1i(program, glGetUniformLocation(program, "uRingCount"), replicas.ringCount);
  glProgramUniform1f(program, glGetUniformLocation(program, "uRingRadius"), replicas.ringRadius);
  glProgramUniform1i(program, glGetUniformLocation(program, "uCellBudget"), replicas.mostCellsCrossed());
  glProgramUniform1i(program, glGetUniformLocation(program, "uBandCount"), GLint(p.proxyBands.size()));
  if (!p.proxyBands.empty()) {
    glProgramUniform3fv(program, glGetUniformLocation(program, "uBands"), GLsizei(p.proxyBands.size()),
                        p.proxyBands[0].data());
  }
  glProgramUniform2f(program, glGetUniformLocation(program, "uRepeat"), p.repeat[0], p.repeat[1]);
  glProgramUniform1f(program, glGetUniformLocation(program, "uSphereCentreH"), p.sphereCentreH);
  glProgramUniform1f(program, glGetUniformLocation(program, "uDerivativeScale"),
                     p.displacement ? p.displacement->derivativeScale : 0.0f);
  glProgramUniform4fv(program, glGetUniformLocation(program, "uBaseColor"), 1, item.baseColour.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uLightDir"), 1, frame.light.direction.data());
  // Directions go to object space by the inverse of the model's linear part: the transpose of the
  // normal matrix (its inverse transpose).
  Vec3 lightObject{0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) lightObject[i] += normal[i * 3 + j] * frame.light.direction[j];
  lightObject = normalize(lightObject);
  glProgramUniform3fv(program, glGetUniformLocation(program, "uLightDirObject"), 1, lightObject.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uLightColour"), 1, frame.light.colour.data());
  glProgramUniform3fv(program, glGetUniformLocation(program, "uCameraPos"), 1, frame.camera.eye.data());
}

void RevolutionRenderer::draw(const FrameContext& frame) {
  glEnable(GL_CULL_FACE);
  for (const Item& item : items_) {
    setUniforms(item, frame);
    glUseProgram(item.program);
    glBindTextureUnit(kShapeUnit, item.shapeTexture);
    glBindTextureUnit(kDisplacementUnit, item.displacementTexture);
    glBindTextureUnit(kArcLengthUnit, item.arcLengthTexture);
    glBindTextureUnit(kBaseColourUnit, item.colourTexture);
    // Back faces: a mirroring transform turns the box's winding inside out.
    glCullFace(mirrors(item.world) ? GL_BACK : GL_FRONT);
    item.box.draw();
  }
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  for (GLuint unit : {kShapeUnit, kDisplacementUnit, kArcLengthUnit, kBaseColourUnit}) glBindTextureUnit(unit, 0);
}

std::size_t RevolutionRenderer::gpuBytes() const {
  std::size_t total = bytes_;
  for (const Item& item : items_) total += item.box.uploadedBytes();
  return total;
}

std::unique_ptr<TechniqueRenderer> revolutionRenderer() { return std::make_unique<RevolutionRenderer>(); }

}  // namespace bake::play
