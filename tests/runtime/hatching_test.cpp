// Hatching (seed 004; formats/tam.md) on llvmpipe. The packages are built here, independently of
// tambake: a sphere or torus from mesh/shapes.h and a synthetic tonal art map of four nested tones of
// stripes (horizontal lines, denser lines, a cross grid, a denser cross grid; darkness 0.125, 0.25,
// 0.4375, 0.625), box-filtered down a full mip chain and written with io/ktx2.h into a BAKE_hatching
// material with io/glb.h. Checked: the adjacency of closed, welded-by-position and open meshes;
// deterministic frames; no popping while the light moves in 0.5 degree steps (a strict per-pixel bound
// on a plane, where only the tone changes, and bounded mean changes on a sphere, where the strokes also
// turn with the light); darkness following the Lambert term; goldens; and validation of the extension.
#include <gtest/gtest.h>

#include <bake_formats/tam.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>

#include "bake/core/vec.h"
#include "bake/hatching/bake.h"
#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "bake/mesh/shapes.h"
#include "io/image_compare.h"
#include "io/ktx2.h"
#include "play/render.h"
#include "play/validate.h"
#include "render/hatching.h"
#include "render/renderer.h"
#include "render/target.h"
#include "runtime/gl_test.h"
#include "runtime/golden_image.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;
namespace fmt = format::tam;

constexpr int kSize = 128;
const std::vector<float> kTones = {0.125f, 0.25f, 0.4375f, 0.625f};

// ---------------------------------------------------------------------------------------------
// The synthetic TAM

bool inked(int tone, int x, int y) {
  switch (tone) {
    case 0: return y % 16 < 2;
    case 1: return y % 8 < 2;
    case 2: return y % 8 < 2 || x % 8 < 2;
    default: return y % 4 < 2 || x % 8 < 2;
  }
}

// `size` x `size` (a power of two), the tones' layers, full mip chain of 2x2 box averages; RGBA8 inks
// in dark blue on white (A = brightness).
ktx2::Texture stripeTam(int size = 64, bool rgba = false, int layers = 4) {
  ktx2::Texture tam;
  tam.format = rgba ? ktx2::Format::RGBA8 : ktx2::Format::R8;
  tam.width = tam.height = std::uint32_t(size);
  tam.layers = std::uint32_t(layers);
  // Brightness per level, layer after layer.
  std::vector<std::vector<float>> brightness(1, std::vector<float>(std::size_t(layers * size * size)));
  for (int k = 0; k < layers; ++k)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        brightness[0][std::size_t((k * size + y) * size + x)] = inked(std::min(k, 3), x, y) ? 0.0f : 1.0f;
  for (int s = size / 2; s >= 1; s /= 2) {
    const std::vector<float>& up = brightness.back();
    std::vector<float> down(std::size_t(layers * s * s));
    for (int k = 0; k < layers; ++k)
      for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x) {
          float sum = 0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) sum += up[std::size_t((k * 2 * s + 2 * y + dy) * 2 * s + 2 * x + dx)];
          down[std::size_t((k * s + y) * s + x)] = sum / 4;
        }
    brightness.push_back(std::move(down));
  }
  const std::array<float, 3> ink{0.1f, 0.15f, 0.45f};
  for (const std::vector<float>& level : brightness) {
    std::vector<std::uint8_t> bytes;
    for (float b : level) {
      if (rgba) {
        for (float c : ink) bytes.push_back(std::uint8_t(std::lround(255 * (c + (1 - c) * b))));
      }
      bytes.push_back(std::uint8_t(std::lround(255 * b)));
    }
    tam.levels.push_back(std::move(bytes));
  }
  tam.setText(fmt::kMetadataKey, nlohmann::json({{"version", 1}, {"tones", kTones}, {"style", "cross-hatching"}}).dump());
  return tam;
}

// ---------------------------------------------------------------------------------------------
// Packages

glb::Primitive meshPrimitive(const TriangleMesh& mesh) {
  std::vector<float> positions, normals(mesh.positions.size() * 3, 0.0f);
  std::vector<std::uint32_t> indices;
  for (const Vec3f& p : mesh.positions) positions.insert(positions.end(), p.begin(), p.end());
  for (const Triangle& t : mesh.triangles) {
    indices.insert(indices.end(), t.begin(), t.end());
    const Vec3f &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Vec3 n = cross(Vec3{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, Vec3{c[0] - a[0], c[1] - a[1], c[2] - a[2]});
    for (std::uint32_t v : t)
      for (int k = 0; k < 3; ++k) normals[3 * v + std::size_t(k)] += n[std::size_t(k)];
  }
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 n = normalize(Vec3{normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]});
    for (int k = 0; k < 3; ++k) normals[3 * v + std::size_t(k)] = n[std::size_t(k)];
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.indices = std::move(indices);
  primitive.material = 0;
  return primitive;
}

TriangleMesh shape(const std::string& name, int resolution = 40) {
  auto mesh = makeShape({name, resolution});
  EXPECT_TRUE(mesh.isOk()) << mesh.status().describe();
  return mesh.isOk() ? *mesh : TriangleMesh{};
}

struct Material {
  float tilesPerUnit = 3;
  float rotation = 0;
  std::array<float, 2> translation{0, 0};
  std::string orientation = fmt::kOrientationTowardLight;
  std::array<float, 3> baseColor{1, 1, 1};
  bool rgba = false;
};

nlohmann::json hatchingExtension(const Material& m) {
  return {{"version", fmt::kVersion},     {"tam", 0},
          {"tones", kTones},              {"tilesPerUnit", m.tilesPerUnit},
          {"rotation", m.rotation},       {"translation", m.translation},
          {"orientation", m.orientation}, {"baseColor", m.baseColor}};
}

glb::Package hatchingPackage(const glb::Primitive& primitive, const Material& m = {},
                             const ktx2::Texture* tam = nullptr) {
  glb::Package package;
  ktx2::WriteOptions options;
  options.writer = "hatching test";
  auto bytes = ktx2::encode(tam ? *tam : stripeTam(64, m.rgba), options);
  EXPECT_TRUE(bytes.isOk()) << bytes.status().describe();
  package.blobs.push_back({bytes.isOk() ? *bytes : std::vector<std::uint8_t>{}, 16});
  package.images = {{{"bufferView", 0}, {"mimeType", fmt::kKtx2MimeType}}};
  const std::array<float, 4> factor{m.baseColor[0], m.baseColor[1], m.baseColor[2], 1.0f};
  package.materials = nlohmann::json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", factor}}},
                                              {"extensions", {{fmt::kExtension, hatchingExtension(m)}}}}});
  package.meshes.push_back({"hatched", {primitive}});
  glb::Node node;
  node.mesh = 0;
  package.nodes.push_back(node);
  package.extensionsUsed = {fmt::kExtension};
  return package;
}

// A square in the plane z = 0, x and y in [-1, 1], facing +z, as two triangles.
glb::Primitive squarePrimitive() {
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}));
  primitive.indices = {0, 1, 2, 0, 2, 3};
  primitive.material = 0;
  return primitive;
}

fs::path writePackage(const glb::Package& package, const std::string& name) {
  const fs::path path = test::freshTempDir("hatching_" + name) / (name + ".glb");
  const Status status = glb::write(path, package);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return path;
}

// ---------------------------------------------------------------------------------------------
// Frames: one scene, one renderer, many lights

Vec3 lightAt(double azimuthDegrees, double elevationDegrees) {
  const double a = azimuthDegrees * kPi / 180, e = elevationDegrees * kPi / 180;
  return {float(std::cos(e) * std::sin(a)), float(std::sin(e)), float(std::cos(e) * std::cos(a))};
}

const Camera kFrontCamera{{0.0f, 0.0f, 3.2f}, {0, 0, 0}, {0, 1, 0}, 0.7f, 0.01f, 100.0f};

class HatchingFrames : public test::GlTest {
 protected:
  void load(const glb::Package& package, const std::string& name) {
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({writePackage(package, name)}, diagnostics, [](const std::string&) { return true; });
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    scene_ = std::move(scene).value();
    shaders_ = std::make_unique<gl::ShaderLibrary>();
    auto renderer = SceneRenderer::create(*scene_, RendererRegistry::builtIn(), *shaders_);
    ASSERT_TRUE(renderer.isOk()) << renderer.status().describe();
    renderer_ = std::move(renderer).value();
    auto target = OffscreenTarget::create(kSize, kSize);
    ASSERT_TRUE(target.isOk()) << target.status().describe();
    target_ = std::move(target).value();
  }
  // The frame as the PNG would hold it (sRGB-encoded values in [0, 1], top row first).
  Image frame(const Vec3& lightDirection, const Camera& camera = kFrontCamera) {
    Light light;
    light.direction = normalize(lightDirection);
    return frameLitBy(light, camera);
  }
  Image frameLitBy(const Light& light, const Camera& camera = kFrontCamera) {
    const FrameContext context{*scene_, camera, light, lookAt(camera.eye, camera.target, camera.up),
                               perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), kSize, kSize};
    target_->bind();
    renderer_->drawFrame(context);
    Image image = encodeSrgb(target_->readLinearRgba());
    for (float& v : image.pixels) v = std::round(v * 255.0f) / 255.0f;  // as 8-bit PNG
    return image;
  }
  std::optional<Scene> scene_;
  std::unique_ptr<gl::ShaderLibrary> shaders_;
  std::optional<SceneRenderer> renderer_;
  std::optional<OffscreenTarget> target_;
};

float grey(const Image& image, int x, int y) {
  return (image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2)) / 3.0f;
}

struct Change {
  double mean = 0, max = 0;
};

// Per-pixel change of grey between two frames over a mask (all pixels when empty).
Change change(const Image& a, const Image& b, const std::vector<bool>& mask = {}) {
  Change c;
  int count = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (!mask.empty() && !mask[std::size_t(y * kSize + x)]) continue;
      const double d = std::fabs(grey(a, x, y) - grey(b, x, y));
      c.mean += d;
      c.max = std::max(c.max, d);
      ++count;
    }
  }
  c.mean /= std::max(count, 1);
  return c;
}

// The ray through the centre of pixel (x, y), from lookAt and perspective's definitions.
Vec3 pixelDirection(const Camera& camera, int x, int y) {
  const Vec3 f = normalize(camera.target - camera.eye);
  const Vec3 s = normalize(cross(f, camera.up));
  const Vec3 u = cross(s, f);
  const float t = std::tan(camera.yfov / 2);
  const float nx = ((float(x) + 0.5f) / kSize * 2 - 1) * t, ny = (1 - (float(y) + 0.5f) / kSize * 2) * t;
  return normalize(s * nx + u * ny + f);
}

// Normal of the unit sphere at the first hit of pixel (x, y), if the ray meets a sphere of `radius`.
std::optional<Vec3> sphereNormal(const Camera& camera, int x, int y, float radius) {
  const Vec3 d = pixelDirection(camera, x, y), o = camera.eye;
  const float b = dot(o, d), c = dot(o, o) - radius * radius;
  const float disc = b * b - c;
  if (disc < 0) return std::nullopt;
  return normalize(o + d * (-b - std::sqrt(disc)));
}

// Pixels well inside the unit square's image (the plane z = 0 seen from kFrontCamera).
std::vector<bool> squareMask() {
  std::vector<bool> mask(std::size_t(kSize * kSize), false);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Vec3 d = pixelDirection(kFrontCamera, x, y);
      const Vec3 p = kFrontCamera.eye + d * (-kFrontCamera.eye[2] / d[2]);
      mask[std::size_t(y * kSize + x)] = std::fabs(p[0]) < 0.9f && std::fabs(p[1]) < 0.9f;
    }
  }
  return mask;
}

// ---------------------------------------------------------------------------------------------
// Adjacency

// The three positions of a triangle, as a set, for comparing triangles across split vertices.
std::set<std::array<float, 3>> cornerSet(const std::vector<float>& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::set<std::array<float, 3>> s;
  for (std::uint32_t v : {a, b, c}) s.insert({p[3 * v], p[3 * v + 1], p[3 * v + 2]});
  return s;
}

void expectClosedAdjacency(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices) {
  const TriangleAdjacency adjacency = buildTriangleAdjacency(positions, indices);
  ASSERT_EQ(adjacency.indices.size(), indices.size() * 2);
  EXPECT_EQ(adjacency.boundaryEdges, 0u);
  EXPECT_EQ(adjacency.nonManifoldEdges, 0u);
  std::set<std::set<std::array<float, 3>>> triangles;
  for (std::size_t t = 0; t < indices.size() / 3; ++t)
    triangles.insert(cornerSet(positions, indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]));
  auto at = [&](std::uint32_t v) { return std::array<float, 3>{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; };
  for (std::size_t t = 0; t < indices.size() / 3; ++t) {
    const std::uint32_t* a = &adjacency.indices[6 * t];
    const auto own = cornerSet(positions, a[0], a[2], a[4]);
    EXPECT_EQ(own, cornerSet(positions, indices[3 * t], indices[3 * t + 1], indices[3 * t + 2])) << "triangle " << t;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t v0 = a[2 * e], v1 = a[(2 * e + 2) % 6], opposite = a[2 * e + 1];
      const auto neighbour = cornerSet(positions, v1, v0, opposite);
      // Exactly the edge is shared: the opposite vertex is on neither end, the neighbour is another
      // triangle of the mesh, and it shares two corners with this one.
      EXPECT_NE(at(opposite), at(v0));
      EXPECT_NE(at(opposite), at(v1));
      EXPECT_TRUE(triangles.count(neighbour)) << "triangle " << t << " edge " << e;
      EXPECT_NE(neighbour, own);
      int shared = 0;
      for (const auto& corner : neighbour) shared += int(own.count(corner));
      EXPECT_EQ(shared, 2) << "triangle " << t << " edge " << e;
    }
  }
}

std::pair<std::vector<float>, std::vector<std::uint32_t>> flatten(const TriangleMesh& mesh) {
  std::vector<float> p;
  std::vector<std::uint32_t> i;
  for (const Vec3f& v : mesh.positions) p.insert(p.end(), v.begin(), v.end());
  for (const Triangle& t : mesh.triangles) i.insert(i.end(), t.begin(), t.end());
  return {p, i};
}

TEST(HatchingAdjacency, ClosedMeshHasNoBoundaryAndEachNeighbourSharesExactlyAnEdge) {
  for (const std::string name : {"sphere", "torus"}) {
    SCOPED_TRACE(name);
    const auto [p, i] = flatten(shape(name, 16));
    ASSERT_FALSE(i.empty());
    expectClosedAdjacency(p, i);
  }
}

// A triangle soup (every triangle with its own three vertices, as with split normals) still connects
// through welded positions.
TEST(HatchingAdjacency, SplitVerticesWeldByPosition) {
  const auto [p, i] = flatten(shape("torus", 12));
  std::vector<float> soup;
  std::vector<std::uint32_t> soupIndices;
  for (std::uint32_t v : i) {
    soup.insert(soup.end(), {p[3 * v], p[3 * v + 1], p[3 * v + 2]});
    soupIndices.push_back(std::uint32_t(soupIndices.size()));
  }
  expectClosedAdjacency(soup, soupIndices);
}

// An open square: the diagonal is shared, the four outer edges repeat the triangle's own opposite vertex.
TEST(HatchingAdjacency, BoundaryEdgesRepeatTheOppositeVertex) {
  const std::vector<float> p = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const TriangleAdjacency a = buildTriangleAdjacency(p, {0, 1, 2, 0, 2, 3});
  EXPECT_EQ(a.boundaryEdges, 4u);
  EXPECT_EQ(a.indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 2, 3, 0, 1, 2, 0, 3, 2}));
}

// ---------------------------------------------------------------------------------------------
// Frames

TEST_F(HatchingFrames, FrameIsByteIdenticalWhenRenderedTwice) {
  load(hatchingPackage(meshPrimitive(shape("torus"))), "twice");
  const Image a = frame(lightAt(30, 40));
  const Image b = frame(lightAt(30, 40));
  EXPECT_EQ(a.pixels, b.pixels);
  // And the frame is hatched: many distinct grey levels inside the object, not flat shading.
  std::set<int> levels;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) levels.insert(int(std::lround(grey(a, x, y) * 255)));
  EXPECT_GT(levels.size(), 20u);
}

// On a plane lit from a direction turning in the x-z plane, the projected light (B) keeps its
// direction, so the strokes stay put and only the tone changes: with the two nearest tones interpolated
// no pixel may jump. Each 0.5 degree step changes darkness by at most sin(theta) * 0.0087 < 0.0087,
// i.e. at most 0.0087 / 0.125 (the smallest tone gap) = 7 % of a layer's contrast; a renderer that
// snapped to the nearest tone would flip whole strokes (a change of 1). Bound: 0.1 per pixel.
TEST_F(HatchingFrames, LightMovingInHalfDegreeStepsNeverPopsOnAPlane) {
  load(hatchingPackage(squarePrimitive()), "plane_steps");
  const std::vector<bool> mask = squareMask();
  std::optional<Image> previous;
  double largest = 0, meanFirst = 0, meanLast = 0;
  for (int step = 0; step <= 120; ++step) {  // 15 to 75 degrees from the normal
    const double theta = (15.0 + 0.5 * step) * kPi / 180;
    Image image = frame({float(std::sin(theta)), 0.0f, float(std::cos(theta))});
    if (previous) {
      const Change c = change(*previous, image, mask);
      largest = std::max(largest, c.max);
      ASSERT_LT(c.max, 0.1) << "step " << step;
      ASSERT_LT(c.mean, 0.02) << "step " << step;
    }
    double mean = 0;
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        if (mask[std::size_t(y * kSize + x)]) mean += grey(image, x, y), ++n;
    (step == 0 ? meanFirst : meanLast) = mean / n;
    // The tones are darkness targets and darkness = 1 - Lambert: the mean brightness is the Lambert
    // term, down to the darkest tone's brightness (measured within 0.004).
    EXPECT_NEAR(mean / n, std::max(std::cos(theta), 1.0 - kTones.back()), 0.01) << "step " << step;
    previous = std::move(image);
  }
  ::testing::Test::RecordProperty("largestPixelStep", std::to_string(largest));
  // Over the sweep the plane gets clearly darker (Lambert from cos 15 to cos 75 degrees).
  EXPECT_GT(meanFirst - meanLast, 0.2) << meanFirst << " -> " << meanLast;
}

// Mean grey of each 8 x 8 block of pixels: the picture at the scale of tone, not of single strokes.
std::vector<double> blockMeans(const Image& image) {
  constexpr int kBlock = 8;
  std::vector<double> means;
  for (int by = 0; by < kSize; by += kBlock) {
    for (int bx = 0; bx < kSize; bx += kBlock) {
      double sum = 0;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) sum += grey(image, x, y);
      means.push_back(sum / (kBlock * kBlock));
    }
  }
  return means;
}

// On a sphere the strokes also turn with the light (B follows it), so single pixels may flip; the
// picture must still change progressively: at the scale of 8 x 8 blocks (where turning strokes keep
// their mean) no block changes by more than 0.03 per 0.5 degree step, every step's mean change is
// small, and no step's change is more than 3 times the median step's (no frame-to-frame jump).
// Measured: worst block change 0.007; the same renderer snapping to the nearest tone gives 0.08.
TEST_F(HatchingFrames, LightMovingInHalfDegreeStepsChangesTheSphereProgressively) {
  load(hatchingPackage(meshPrimitive(shape("sphere", 40))), "sphere_steps");
  std::vector<double> means;
  double worstBlock = 0;
  std::optional<Image> previous;
  for (int step = 0; step <= 40; ++step) {
    Image image = frame(lightAt(20 + 0.5 * step, 35));
    if (previous) {
      means.push_back(change(*previous, image).mean);
      const std::vector<double> a = blockMeans(*previous), b = blockMeans(image);
      for (std::size_t i = 0; i < a.size(); ++i) worstBlock = std::max(worstBlock, std::fabs(a[i] - b[i]));
    }
    previous = std::move(image);
  }
  std::vector<double> sorted = means;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2], worst = sorted.back();
  ::testing::Test::RecordProperty("medianMeanStep", std::to_string(median));
  ::testing::Test::RecordProperty("worstMeanStep", std::to_string(worst));
  ::testing::Test::RecordProperty("worstBlockStep", std::to_string(worstBlock));
  std::printf("sphere steps: median mean change %.4f, worst %.4f, worst 8x8 block change %.4f\n", median, worst,
              worstBlock);
  EXPECT_GT(median, 0.0) << "the light moved, the picture must change";
  EXPECT_LT(worst, 0.02);
  EXPECT_LT(worst, 3 * median + 1e-3) << "median " << median;
  EXPECT_LT(worstBlock, 0.03);
}

// Darker where the light grazes. The tones are darkness targets and darkness = 1 - Lambert, so the
// mean displayed brightness over pixels of similar Lambert term (from the exact sphere's normal at each
// pixel) follows that Lambert term, down to the darkest tone's brightness (1 - 0.625), where it stays.
// Only approximately on a sphere about the origin: there (V.T, V.B) of every triangle lies near (0, 0)
// (V is nearly along N), so all triangles sample the same corner of the tile, whose lines are not the
// tile's mean (measured: within 0.003 up to Lambert 0.75, 0.03 and 0.05 darker above; exact with a TAM
// of uniform layers). Hence 0.07, and brightness must rise bin after bin.
TEST_F(HatchingFrames, BrightnessFollowsTheLambertTerm) {
  load(hatchingPackage(meshPrimitive(shape("sphere", 48))), "lambert");
  const Vec3 light = normalize(lightAt(35, 30));
  const Image image = frame(light);
  constexpr int kBins = 8;
  std::array<double, kBins> sum{}, expected{}, count{};
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (!sphereNormal(kFrontCamera, x, y, 0.95f)) continue;  // away from the silhouette
      const Vec3 n = *sphereNormal(kFrontCamera, x, y, 1.0f);
      const float lambert = std::max(dot(n, light), 0.0f);
      const std::size_t bin = std::size_t(std::min(int(lambert * kBins), kBins - 1));
      sum[bin] += grey(image, x, y);
      expected[bin] += std::max(double(lambert), 1.0 - kTones.back());
      count[bin] += 1;
    }
  }
  std::string means;
  for (std::size_t b = 0; b < kBins; ++b) {
    means += std::to_string(sum[b] / std::max(count[b], 1.0)) + "/" + std::to_string(expected[b] / std::max(count[b], 1.0)) + " ";
  }
  ::testing::Test::RecordProperty("binMeansMeasuredOverExpected", means);
  double previous = 0;
  for (std::size_t b = 0; b < kBins; ++b) {
    if (count[b] < 50) continue;
    const double mean = sum[b] / count[b];
    EXPECT_NEAR(mean, expected[b] / count[b], 0.07) << "bin " << b << ": " << means;
    if (double(b) / kBins > 1.0 - kTones.back()) EXPECT_GT(mean, previous + 0.05) << "bin " << b << ": " << means;
    previous = mean;
  }
}

// Point and spot lights (seed 004 §3.2: L = Lp - G per triangle for the frame; §3.4: the fragment-
// light vector for the tone; the spot's cut-off and exponent) against the closed form. With a TAM
// whose layers are flat greys, the picture is the tones' interpolation of darkness = 1 - s (N.FL)
// exactly (s: the spot factor (cos of the angle off the axis)^exponent inside the cone, 0 outside),
// so every pixel of the plane z = 0 can be checked: within 2/255 of the 8-bit value, away from the
// cone's edge (a pixel there straddles the cut-off).
ktx2::Texture flatTam(int size = 16) {
  ktx2::Texture tam;
  tam.format = ktx2::Format::R8;
  tam.width = tam.height = std::uint32_t(size);
  tam.layers = std::uint32_t(kTones.size());
  for (int s = size; s >= 1; s /= 2) {
    std::vector<std::uint8_t> level;
    for (float tone : kTones) level.insert(level.end(), std::size_t(s * s), std::uint8_t(std::lround(255 * (1 - tone))));
    tam.levels.push_back(std::move(level));
  }
  tam.setText(fmt::kMetadataKey, nlohmann::json({{"version", 1}, {"tones", kTones}, {"style", "flat"}}).dump());
  return tam;
}

// The displayed value of darkness d with flatTam: white below the first tone's darkness, the layers'
// 8-bit greys interpolated between tones, the last layer beyond.
double flatTamValue(double d) {
  double lowTone = 0, low = 1;
  for (float tone : kTones) {
    const double high = std::lround(255 * (1 - tone)) / 255.0;
    if (d < tone) return low + (high - low) * std::clamp((d - lowTone) / (tone - lowTone), 0.0, 1.0);
    lowTone = tone;
    low = high;
  }
  return low;
}

struct LightCheck {
  int pixels = 0, over = 0;
  double worst = 0;
};

// Every pixel of the square's image against the closed form; `spot` gives the factor at a point and
// whether it lies near the cone's edge.
template <class Spot>
LightCheck checkAgainstClosedForm(const Image& image, const Vec3& lightPosition, Spot spot) {
  LightCheck check;
  const std::vector<bool> mask = squareMask();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (!mask[std::size_t(y * kSize + x)]) continue;
      const Vec3 d = pixelDirection(kFrontCamera, x, y);
      const Vec3 p = kFrontCamera.eye + d * (-kFrontCamera.eye[2] / d[2]);
      const Vec3 toLight = lightPosition - p;
      bool nearEdge = false;
      const double factor = spot(p, nearEdge);
      if (nearEdge) continue;
      const double lambert = std::max(0.0, double(toLight[2]) / double(length(toLight)));
      const double expected = flatTamValue(1 - factor * lambert);
      const double error = std::fabs(grey(image, x, y) - expected);
      check.worst = std::max(check.worst, error);
      check.over += error > 2.0 / 255 ? 1 : 0;
      ++check.pixels;
    }
  return check;
}

TEST_F(HatchingFrames, PointLightFollowsTheClosedForm) {
  ktx2::Texture tam = flatTam();
  load(hatchingPackage(squarePrimitive(), Material{}, &tam), "point_light");
  Light light;
  light.kind = LightKind::Point;
  light.position = {0.3f, -0.2f, 0.6f};
  const Image image = frameLitBy(light);
  const LightCheck check = checkAgainstClosedForm(image, light.position, [](const Vec3&, bool&) { return 1.0; });
  std::printf("[ hatching ] point light: %d pixels, worst %.4f (%d over 2/255)\n", check.pixels, check.worst, check.over);
  EXPECT_GT(check.pixels, 5000);
  EXPECT_EQ(check.over, 0) << "worst " << check.worst;
  // The tone changes across the plane (the closed form spans most of the tones): not a flat picture.
  const double centre = grey(image, kSize / 2 + 12, kSize / 2 + 8), corner = grey(image, 12, 12);
  EXPECT_GT(std::fabs(centre - corner), 0.2);
}

TEST_F(HatchingFrames, SpotLightCutOffAndExponentFollowTheClosedForm) {
  ktx2::Texture tam = flatTam();
  load(hatchingPackage(squarePrimitive(), Material{}, &tam), "spot_light");
  Light light;
  light.kind = LightKind::Spot;
  light.position = {0.1f, 0.1f, 1.5f};
  light.spotDirection = normalize(Vec3{0.1f, -0.1f, -1.0f});
  light.cutoff = float(30 * kPi / 180);
  light.exponent = 8;
  const Image image = frameLitBy(light);
  int inside = 0, outside = 0;
  const LightCheck check = checkAgainstClosedForm(image, light.position, [&](const Vec3& p, bool& nearEdge) {
    const double c = dot(normalize(p - light.position), light.spotDirection);
    nearEdge = std::fabs(c - std::cos(double(light.cutoff))) < 0.01;
    if (!nearEdge) (c >= std::cos(double(light.cutoff)) ? inside : outside) += 1;
    return c >= std::cos(double(light.cutoff)) ? std::pow(c, double(light.exponent)) : 0.0;
  });
  std::printf("[ hatching ] spot light: %d pixels (%d inside the cone, %d outside), worst %.4f (%d over 2/255)\n",
              check.pixels, inside, outside, check.worst, check.over);
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
  EXPECT_EQ(check.over, 0) << "worst " << check.worst;
}

// A KHR_lights_punctual spot light of the package is the one the frame gets, with its cone and the
// exponent from its extras; a point light's direction for the other techniques points from the scene's
// centre toward it.
TEST(HatchingLights, PunctualLightsOfAnyTypeAreRead) {
  glb::Package package = hatchingPackage(squarePrimitive());
  package.extensions["KHR_lights_punctual"] = {{"lights", {{{"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}}},
                                                            {"extras", {{"spotExponent", 4}}}}}}};
  glb::Node lamp;
  lamp.name = "lamp";
  lamp.translation = {0, 0, 2};
  lamp.extensions["KHR_lights_punctual"] = {{"light", 0}};
  package.nodes.push_back(lamp);
  package.extensionsUsed.push_back("KHR_lights_punctual");
  Diagnostics diagnostics("bakeplay", true);
  auto scene = loadScene({writePackage(package, "punctual_spot")}, diagnostics, [](const std::string&) { return true; });
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  ASSERT_TRUE(scene->fileLight.has_value());
  const Light& light = *scene->fileLight;
  EXPECT_EQ(light.kind, LightKind::Spot);
  EXPECT_NEAR(light.position[2], 2, 1e-6);
  EXPECT_NEAR(light.spotDirection[2], -1, 1e-6);  // spots shine down their local -Z
  EXPECT_NEAR(light.cutoff, 0.5, 1e-6);
  EXPECT_NEAR(light.exponent, 4, 1e-6);
  EXPECT_NEAR(light.direction[2], 1, 1e-6);  // from the square's centre up to the lamp
  auto parsed = parseLight("spot:0,0,2:0,0,-1:30:8");
  ASSERT_TRUE(parsed.isOk()) << parsed.status().describe();
  EXPECT_NEAR(parsed->cutoff, 30 * kPi / 180, 1e-6);
  EXPECT_FALSE(parseLight("spot:0,0,2:0,0,-1:120").isOk());
  EXPECT_FALSE(parseLight("point:0,0").isOk());
}

// The material's baseColor multiplies the hatching: a red material has no green or blue on paper.
TEST_F(HatchingFrames, BaseColourMultipliesTheHatching) {
  Material m;
  m.baseColor = {1.0f, 0.0f, 0.0f};
  load(hatchingPackage(squarePrimitive(), m), "colour");
  const Image image = frame({0.2f, 0.1f, 1.0f});
  const std::vector<bool> mask = squareMask();
  double red = 0, other = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if (mask[std::size_t(y * kSize + x)]) red += image.at(x, y, 0), other += image.at(x, y, 1) + image.at(x, y, 2);
  EXPECT_GT(red, 1000.0);
  EXPECT_EQ(other, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Goldens (BAKE_UPDATE_GOLDEN=1 rewrites them)

struct GoldenCase {
  std::string name;
  std::string shape;
  Material material;
};

class HatchingGolden : public HatchingFrames, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(HatchingGolden, MatchesTheGoldenImage) {
  const GoldenCase& c = GetParam();
  load(hatchingPackage(meshPrimitive(shape(c.shape, 48)), c.material), "golden_" + c.name);
  const Image image = frame(lightAt(40, 35));
  const std::string golden = "runtime/hatching-" + c.name + ".v1.png";
  EXPECT_TRUE(test::matchesGoldenImage(image, golden));
}

Material coloured() {
  Material m;
  m.rgba = true;
  m.orientation = fmt::kOrientationAcrossLight;
  m.rotation = 0.4f;
  m.translation = {0.25f, 0.5f};
  m.tilesPerUnit = 4;
  m.baseColor = {1.0f, 0.85f, 0.6f};
  return m;
}

INSTANTIATE_TEST_SUITE_P(Cases, HatchingGolden,
                         ::testing::Values(GoldenCase{"sphere", "sphere", Material{}},
                                           GoldenCase{"torus-colour-across", "torus", coloured()}),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name) ch = ch == '-' ? '_' : ch;
                           return name;
                         });

// ---------------------------------------------------------------------------------------------
// Validation

std::string messageOf(const Status& status) { return status.describe(); }

TEST(HatchingValidate, AcceptsTheTestPackage) {
  const glb::Package package = hatchingPackage(meshPrimitive(shape("sphere", 16)));
  const Status status = checkPackageStructure(package, "h.glb");
  EXPECT_TRUE(status.isOk()) << status.describe();
  Material m = coloured();
  EXPECT_TRUE(checkPackageStructure(hatchingPackage(squarePrimitive(), m), "h.glb").isOk());
}

TEST(HatchingValidate, RejectsALayerCountMismatch) {
  const ktx2::Texture three = stripeTam(64, false, 3);
  const Status status = checkPackageStructure(hatchingPackage(squarePrimitive(), {}, &three), "h.glb");
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(messageOf(status).find("layer count mismatch"), std::string::npos) << messageOf(status);
  EXPECT_NE(messageOf(status).find("material 0"), std::string::npos) << messageOf(status);
  EXPECT_NE(messageOf(status).find("h.glb"), std::string::npos) << messageOf(status);
}

TEST(HatchingValidate, RejectsTonesNotIncreasing) {
  glb::Package package = hatchingPackage(squarePrimitive());
  package.materials[0]["extensions"][fmt::kExtension]["tones"] = {0.125, 0.25, 0.2, 0.625};
  const Status status = checkPackageStructure(package, "h.glb");
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(messageOf(status).find("strictly increasing"), std::string::npos) << messageOf(status);
  EXPECT_NE(messageOf(status).find("tones[2]"), std::string::npos) << messageOf(status);
}

TEST(HatchingValidate, RejectsAMissingImage) {
  glb::Package package = hatchingPackage(squarePrimitive());
  package.materials[0]["extensions"][fmt::kExtension]["tam"] = 3;
  Status status = checkPackageStructure(package, "h.glb");
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(messageOf(status).find("BAKE_hatching.tam = 3 names no image"), std::string::npos) << messageOf(status);

  package.materials[0]["extensions"][fmt::kExtension].erase("tam");
  status = checkPackageStructure(package, "h.glb");
  EXPECT_NE(messageOf(status).find("lacks \"tam\""), std::string::npos) << messageOf(status);
}

TEST(HatchingValidate, RejectsBrokenTamsAndFields) {
  {  // not KTX2 bytes
    glb::Package package = hatchingPackage(squarePrimitive());
    package.blobs[0].bytes.assign(64, 7);
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("does not decode"), std::string::npos);
  }
  {  // a partial mip chain
    ktx2::Texture tam = stripeTam();
    tam.levels.resize(3);
    const Status status = checkPackageStructure(hatchingPackage(squarePrimitive(), {}, &tam), "h.glb");
    EXPECT_NE(messageOf(status).find("mip levels"), std::string::npos) << messageOf(status);
  }
  {  // a plain 2D texture
    ktx2::Texture tam = stripeTam(64, false, 1);
    tam.layers = 0;
    const Status status = checkPackageStructure(hatchingPackage(squarePrimitive(), {}, &tam), "h.glb");
    EXPECT_NE(messageOf(status).find("2D array"), std::string::npos) << messageOf(status);
  }
  {  // out-of-range fields
    glb::Package package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension]["tilesPerUnit"] = 0;
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("tilesPerUnit"), std::string::npos);
    package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension]["orientation"] = "sideways";
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("orientation"), std::string::npos);
    package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension]["tones"] = {0.125, 0.25, 0.4375, 1.5};
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("outside (0, 1)"), std::string::npos);
    package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension]["baseColor"] = {0.5, 1.5, 0.5};
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("baseColor[1]"), std::string::npos);
    package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension].erase("rotation");
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("lacks \"rotation\""), std::string::npos);
    package = hatchingPackage(squarePrimitive());
    package.materials[0]["extensions"][fmt::kExtension]["tilesPerMetre"] = 2;
    EXPECT_NE(messageOf(checkPackageStructure(package, "h.glb")).find("unknown field \"tilesPerMetre\""), std::string::npos);
  }
}

// `bakeplay render` draws a hatching package end to end (the file's PNG is written) and validate
// passes it, rendering its reference views.
TEST(HatchingRender, BakeplayRendersAndValidatesThePackage) {
  const fs::path file = writePackage(hatchingPackage(meshPrimitive(shape("torus", 24))), "bakeplay");
  RenderSettings settings;
  settings.view.scenes = {file.string()};
  settings.view.width = settings.view.height = 64;
  settings.output = (file.parent_path() / "torus.png").string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  ASSERT_TRUE(status.isOk()) << status.describe();
  EXPECT_TRUE(fs::exists(settings.output));

  ValidateSettings validate;
  validate.packages = {file.string()};
  validate.size = 64;
  std::FILE* sink = std::tmpfile();
  const Status verdict = runValidate(validate, diagnostics, sink);
  std::fclose(sink);
  EXPECT_TRUE(verdict.isOk()) << verdict.describe();
}

// --compare-standard times the scene twice, as drawn and with standard shading, into one report.
TEST(HatchingRender, CompareStandardTimesBothRenderers) {
  const fs::path file = writePackage(hatchingPackage(meshPrimitive(shape("sphere", 16))), "compare");
  RenderSettings settings;
  settings.view.scenes = {file.string()};
  settings.view.width = settings.view.height = 64;
  settings.frames = 3;
  settings.compareStandard = true;
  settings.output = (file.parent_path() / "sphere.png").string();
  settings.common.reportPath = (file.parent_path() / "report.json").string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  ASSERT_TRUE(status.isOk()) << status.describe();
  const std::vector<std::uint8_t> bytes = test::readAll(settings.common.reportPath);
  const nlohmann::json report = nlohmann::json::parse(bytes.begin(), bytes.end());
  const nlohmann::json& statistics = report["statistics"];
  EXPECT_EQ(statistics["techniques"], nlohmann::json({fmt::kExtension}));
  EXPECT_EQ(statistics["frameTimeCpu"]["frames"], 3);
  EXPECT_EQ(statistics["frameTimeStandardCpu"]["frames"], 3);
  EXPECT_GT(statistics["frameTimeStandardCpu"]["medianMs"].get<double>(), 0.0);
}

// ---------------------------------------------------------------------------------------------
// End to end: the example scene of pipelines/hatching, baked by tambake from its own style files

// Bakes one example style onto `mesh` and returns the package's path.
fs::path bakeExample(const std::string& style, const fs::path& mesh, const fs::path& dir, const std::string& position) {
  hatching::Settings settings;
  settings.style = (test::sourceDir() / "pipelines" / "hatching" / style).string();
  settings.output = (dir / (style + ".ktx2")).string();
  settings.material.mesh = mesh.string();
  settings.material.package = (dir / (style + ".glb")).string();
  std::sscanf(position.c_str(), "%lf,%lf,%lf", &settings.material.position[0], &settings.material.position[1],
              &settings.material.position[2]);
  settings.common.quiet = true;
  Diagnostics quiet("tambake", true);
  const Status status = hatching::run(settings, quiet);
  EXPECT_TRUE(status.isOk()) << style << ": " << status.describe();
  return settings.material.package;
}

// The two example objects render headless side by side, each with ink and paper visible, the same
// bytes twice, and the packages pass validation.
TEST(HatchingExample, PipelineStylesBakeValidateAndRenderHeadless) {
  const fs::path dir = test::freshTempDir("hatching_example");
  glb::Package meshOnly;
  glb::Mesh torus;
  torus.primitives.push_back(meshPrimitive(shape("torus", 40)));
  torus.primitives.back().material = -1;
  meshOnly.meshes.push_back(std::move(torus));
  glb::Node node;
  node.mesh = 0;
  meshOnly.nodes.push_back(node);
  const fs::path mesh = dir / "torus.glb";
  ASSERT_TRUE(glb::write(mesh, meshOnly).isOk());
  const fs::path left = bakeExample("hatching.json", mesh, dir, "-1.5,0,0");
  const fs::path right = bakeExample("stippling.json", mesh, dir, "1.5,0,0");
  ASSERT_FALSE(::testing::Test::HasFailure());

  Diagnostics diagnostics("bakeplay", true);
  ValidateSettings validate;
  validate.packages = {left.string(), right.string()};
  validate.size = 64;
  std::FILE* sink = std::tmpfile();
  const Status verdict = runValidate(validate, diagnostics, sink);
  std::fclose(sink);
  EXPECT_TRUE(verdict.isOk()) << verdict.describe();

  std::vector<std::vector<std::uint8_t>> frames;
  for (int run = 0; run < 2; ++run) {
    RenderSettings settings;
    settings.view.scenes = {left.string(), right.string()};
    settings.view.width = 512;
    settings.view.height = 256;
    // Close enough that strokes span pixels (from afar the TAM's mips turn them into grey tone).
    settings.view.camera = "0,1.2,3.6:0,0,0";
    settings.view.light = "-0.5,0.7,0.6";
    settings.output = (dir / ("scene" + std::to_string(run) + ".png")).string();
    const Status status = runRender(settings, diagnostics);
    ASSERT_TRUE(status.isOk()) << status.describe();
    frames.push_back(test::readAll(settings.output));
  }
  EXPECT_EQ(frames[0], frames[1]) << "the same scene rendered twice differs";

  auto image = readImage(dir / "scene0.png");
  ASSERT_TRUE(image.isOk()) << image.status().describe();
  // Each half holds one object: count its inked (dark) and paper (bright) pixels apart from the
  // background, which is the colour of the top-left corner.
  for (int half = 0; half < 2; ++half) {
    int dark = 0, bright = 0;
    for (int y = 0; y < image->height; ++y)
      for (int x = half * image->width / 2; x < (half + 1) * image->width / 2; ++x) {
        float difference = 0, luminance = 0;
        for (int c = 0; c < 3; ++c) {
          difference += std::abs(image->at(x, y, c) - image->at(0, 0, c));
          luminance += image->at(x, y, c) / 3;
        }
        if (difference < 0.02f) continue;
        dark += luminance < 0.3f ? 1 : 0;
        bright += luminance > 0.7f ? 1 : 0;
      }
    EXPECT_GT(dark, 1000) << "half " << half << ": no ink drawn";
    EXPECT_GT(bright, 1000) << "half " << half << ": no paper left between the strokes";
  }
}

// ---------------------------------------------------------------------------------------------
// Fine tone control (Webb et al. 2002) against the seed's two-layer blend. A square lit by a
// directional light has one Lambert term, so one darkness d over all of it. The reference is the
// darkness asked for: both modes must give it as the frame's mean (1 - mean displayed grey, the TAM's
// own measure of a tone), and the threshold must draw strokes whole where the blend fades them: half
// way between two tones, clearly more of its pixels are near paper or ink.

struct ToneFrame {
  double darkness = 0;  // 1 - mean grey over the square's centre
  double crisp = 0;     // share of those pixels near paper or ink: grey above 0.75 or below 0.25
};

ToneFrame measureTone(const Image& image) {
  ToneFrame out;
  int count = 0;
  for (int y = 24; y < kSize - 24; ++y)
    for (int x = 24; x < kSize - 24; ++x) {
      const float g = grey(image, x, y);
      out.darkness += 1.0 - g;
      out.crisp += g > 0.75f || g < 0.25f ? 1 : 0;
      ++count;
    }
  out.darkness /= count;
  out.crisp /= count;
  return out;
}

TEST(HatchingTone, ThresholdFollowsTheDarknessAndDrawsStrokesWhole) {
  const fs::path dir = test::freshTempDir("hatching_threshold_tone");
  {
    std::ofstream style(dir / "style.json");
    style << R"({"tones": [0.2, 0.4, 0.6, 0.8], "resolution": 128, "levels": 3, "candidates": 6, "seed": 5,
                 "stroke": {"kind": "hatching", "length": {"min": 0.3, "max": 0.6}, "width": {"min": 1.5, "max": 2.0},
                            "angle": 30}})";
  }
  glb::Package squareOnly;
  glb::Primitive square = squarePrimitive();
  square.material = -1;
  squareOnly.meshes.push_back({"square", {square}});
  glb::Node node;
  node.mesh = 0;
  squareOnly.nodes.push_back(node);
  ASSERT_TRUE(glb::write(dir / "square.glb", squareOnly).isOk());
  hatching::Settings bake;
  bake.style = (dir / "style.json").string();
  bake.output = (dir / "tam.ktx2").string();
  bake.threshold = (dir / "threshold.ktx2").string();
  bake.material.mesh = (dir / "square.glb").string();
  bake.material.package = (dir / "square-hatched.glb").string();
  bake.material.tilesPerUnit = 0.5;  // one tile over the square: strokes span several pixels
  bake.common.quiet = true;
  Diagnostics quiet("tambake", true);
  const Status baked = hatching::run(bake, quiet);
  ASSERT_TRUE(baked.isOk()) << baked.describe();

  const auto render = [&](const std::string& tone, double d) {
    RenderSettings settings;
    settings.view.scenes = {bake.material.package};
    settings.view.width = settings.view.height = kSize;
    settings.view.camera = "0,0,3.2:0,0,0";
    // Lambert 1 - d: the light tilted off the square's normal (+z) by acos(1 - d).
    const double tilt = std::acos(1 - d);
    settings.view.light = std::to_string(std::sin(tilt)) + ",0," + std::to_string(std::cos(tilt));
    settings.view.hatchingTone = tone;
    settings.output = (dir / (tone + std::to_string(int(d * 100)) + ".png")).string();
    Diagnostics diagnostics("bakeplay", true);
    const Status status = runRender(settings, diagnostics);
    EXPECT_TRUE(status.isOk()) << status.describe();
    auto image = readImage(settings.output);
    EXPECT_TRUE(image.isOk());
    return image.isOk() ? measureTone(*image) : ToneFrame{};
  };
  std::string figures;
  double worstBlend = 0, worstThreshold = 0;
  for (double d : {0.2, 0.3, 0.4, 0.5, 0.6, 0.7}) {
    const ToneFrame blend = render("blend", d), threshold = render("threshold", d);
    figures += "d " + std::to_string(d) + ": blend " + std::to_string(blend.darkness) + " (crisp " +
               std::to_string(blend.crisp) + "), threshold " + std::to_string(threshold.darkness) + " (crisp " +
               std::to_string(threshold.crisp) + "); ";
    worstBlend = std::max(worstBlend, std::abs(blend.darkness - d));
    worstThreshold = std::max(worstThreshold, std::abs(threshold.darkness - d));
    // Half way between two tones the blend shows the darker layer's new strokes at half strength
    // (measured: 11 to 20 points more crisp pixels with the threshold); at a tone both draw the layer.
    if (int(std::lround(d * 10)) % 2 == 1) EXPECT_GT(threshold.crisp, blend.crisp + 0.08) << figures;
    else EXPECT_GT(threshold.crisp, blend.crisp - 0.02) << figures;
  }
  RecordProperty("toneFigures", figures);
  // The threshold's picture half way between two tones, as a golden (BAKE_UPDATE_GOLDEN=1 rewrites it).
  Result<Image> between = readImage(dir / "threshold50.png");
  ASSERT_TRUE(between.isOk()) << between.status().describe();
  EXPECT_TRUE(test::matchesGoldenImage(*between, "runtime/hatching-threshold-tone.v1.png"));
  RecordProperty("worstBlendError", std::to_string(worstBlend));
  RecordProperty("worstThresholdError", std::to_string(worstThreshold));
  EXPECT_LT(worstBlend, 0.05) << figures;
  EXPECT_LT(worstThreshold, 0.06) << figures;
}

}  // namespace
}  // namespace bake::play
