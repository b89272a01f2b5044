// Revolution mapping (seed 001; formats/revolution.md) on llvmpipe. The packages are built here with
// libbake's GLB writer from analytic shape maps: the exact signed distance of the (r, h) half-plane to
// a circle of radius 0.5 centred at (0, 0.5) (a sphere) and to a circle of radius 0.15 centred at
// (0.35, 0.5) (a torus), the shape box as a mesh node whose material carries BAKE_revolution. They are
// drawn through `bakeplay render`'s own entry point and checked against independent CPU references:
// the silhouette against a ray cast of the exact surface (root bracketing of its implicit function
// along each pixel's ray), depth against the analytic sphere cut by a standard-mesh plane, the
// projections against each other, goldens per projection, and validation against damaged packages.
#include <gtest/gtest.h>

#include <bake_formats/revolution.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <optional>

#include "bake/core/vec.h"
#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "bake/revolution/bake.h"
#include "io/image_compare.h"
#include "play/render.h"
#include "play/validate.h"
#include "render/revolution.h"
#include "revolution/oracle/march.h"
#include "runtime/gl_test.h"
#include "runtime/golden_image.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

constexpr int kSize = 128;
constexpr float kFov = 0.7f;  // the camera's vertical field of view (Camera::yfov)

// ---------------------------------------------------------------------------------------------
// Analytic profiles in the (r, h) half-plane: a circle of `radius` around (centreR, centreH).

struct Circle {
  double centreR, centreH, radius;
  double distance(double r, double h) const { return std::hypot(r - centreR, h - centreH) - radius; }
  std::array<double, 2> gradient(double r, double h) const {
    const double l = std::hypot(r - centreR, h - centreH);
    return l > 0 ? std::array{(r - centreR) / l, (h - centreH) / l} : std::array{1.0, 0.0};
  }
  // The 3D solid's implicit function (negative inside) at an object-space point.
  double implicit(const Vec3& p) const {
    return distance(std::hypot(double(p[0]), double(p[2])), double(p[1]));
  }
};

const Circle kSphere{0.0, 0.5, 0.5};
const Circle kTorus{0.35, 0.5, 0.15};

// The grid both shape maps use: r in [0, 0.6], h in [-0.1, 1.1].
constexpr int kWidth = 96, kHeight = 192;
constexpr double kTexel = 0.6 / kWidth;
constexpr double kHMin = -0.1;
constexpr double kDistanceScale = 0.6;  // S: the largest distance the integer encodings keep

enum class Encoding { Float, Unorm16, Sqrt8 };
const char* encodingName(Encoding e) {
  return e == Encoding::Float ? "float" : e == Encoding::Unorm16 ? "unorm16" : "sqrt8";
}

std::uint16_t unorm16(double x) { return std::uint16_t(std::lround(std::clamp(x, 0.0, 1.0) * 65535.0)); }
std::uint8_t unorm8(double x) { return std::uint8_t(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

template <class T>
void append(std::vector<std::uint8_t>& bytes, T value) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

// Texel (i, j) holds the profile's distance and gradient at its centre, encoded as the spec says.
std::vector<std::uint8_t> shapeMapBytes(const Circle& circle, Encoding encoding) {
  std::vector<std::uint8_t> bytes;
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const double r = (i + 0.5) * kTexel, h = kHMin + (j + 0.5) * kTexel;
      const double d = circle.distance(r, h);
      const auto g = circle.gradient(r, h);
      const double coverage = d < 0 ? 1.0 : 0.0;
      if (encoding == Encoding::Float) {
        for (double v : {g[0], g[1], d, coverage}) append(bytes, float(v));
      } else if (encoding == Encoding::Unorm16) {
        for (double v : {0.5 + 0.5 * g[0], 0.5 + 0.5 * g[1], 0.5 + 0.5 * d / kDistanceScale, coverage})
          append(bytes, unorm16(v));
      } else {
        const double e = (d < 0 ? -1.0 : 1.0) * std::sqrt(std::fabs(d) / kDistanceScale);
        for (double v : {0.5 + 0.5 * g[0], 0.5 + 0.5 * g[1], 0.5 + 0.5 * e, coverage}) append(bytes, unorm8(v));
      }
    }
  }
  return bytes;
}

// Safety margin: bilinear overestimate of a circle's distance (convex: at most texel^2 / (4 radius)
// near its surface, doubled) plus the encoding's quantisation near the surface (|d| < 0.02).
double marginFor(const Circle& circle, Encoding encoding) {
  const double bilinear = 2 * kTexel * kTexel / (4 * circle.radius);
  const double quantisation = encoding == Encoding::Float     ? 0.0
                              : encoding == Encoding::Unorm16 ? 2 * kDistanceScale / 65535
                                                              : 2 * std::sqrt(0.02 / kDistanceScale) * kDistanceScale / 255;
  return bilinear + quantisation;
}

// ---------------------------------------------------------------------------------------------
// Packages

struct Options {
  Encoding encoding = Encoding::Unorm16;
  std::string projection = "cylindrical";
  int iterations = 64;
  bool bands = true;
  bool displacement = false;
  bool colourTexture = false;
  bool arcLengthMap = false;
  std::array<float, 4> baseColour{0.9f, 0.5f, 0.2f, 1.0f};
  nlohmann::json replicas;  // the extension's "replicas" (null: one object)
  bool selfShadow = false;
};

glb::Primitive boxMesh(float rMax, float hMin, float hMax) {
  std::vector<float> p;
  for (int i = 0; i < 8; ++i) {
    p.insert(p.end(), {i & 1 ? rMax : -rMax, i & 2 ? hMax : hMin, i & 4 ? rMax : -rMax});
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, p));
  primitive.indices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                       2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  primitive.material = 0;
  return primitive;
}

// Bumps H = a sin(8 pi u) sin(6 pi v): RG = dH/du, dH/dv over one repeat, rows from v = 0.
constexpr double kBumpHeight = 0.02;
std::vector<std::uint8_t> displacementBytes(int size, double& derivativeScale) {
  derivativeScale = kBumpHeight * 8 * kPi;
  std::vector<std::uint8_t> bytes;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double u = (i + 0.5) / size, v = (j + 0.5) / size;
      const double du = kBumpHeight * 8 * kPi * std::cos(8 * kPi * u) * std::sin(6 * kPi * v);
      const double dv = kBumpHeight * 6 * kPi * std::sin(8 * kPi * u) * std::cos(6 * kPi * v);
      append(bytes, unorm16(0.5 + 0.5 * du / derivativeScale));
      append(bytes, unorm16(0.5 + 0.5 * dv / derivativeScale));
    }
  }
  return bytes;
}

// A PNG checkerboard (8 x 8 squares, two colours) to embed as the base colour image.
std::vector<std::uint8_t> checkerPng() {
  Image image;
  image.width = image.height = 64;
  image.channels = 3;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool dark = ((x / 8) + (y / 8)) % 2 == 1;
      const bool top = y < 32;  // the top half is tinted, so upside-down images show
      image.pixels.insert(image.pixels.end(), {dark ? 0.15f : 1.0f, dark ? 0.15f : (top ? 0.6f : 1.0f), 1.0f});
    }
  }
  const fs::path path = test::freshTempDir("revolution_checker") / "checker.png";
  EXPECT_TRUE(writeImage(path, image, PixelType::U8).isOk());
  return test::readAll(path);
}

// The sphere's arc-length map: the normalised length along the profile (bottom pole to top pole) of
// the nearest profile point, i.e. the polar angle from the bottom over pi.
std::vector<std::uint8_t> sphereArcLengthBytes() {
  std::vector<std::uint8_t> bytes;
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const double r = (i + 0.5) * kTexel, h = kHMin + (j + 0.5) * kTexel;
      append(bytes, unorm16(std::atan2(r, -(h - 0.5)) / kPi));
    }
  }
  return bytes;
}

glb::Package revolutionPackage(const Circle& circle, const Options& o = {}) {
  glb::Package package;
  package.blobs.push_back({shapeMapBytes(circle, o.encoding), 16});
  const float rMax = float(kWidth * kTexel), hMin = float(kHMin), hMax = float(kHMin + kHeight * kTexel);
  nlohmann::json shapeMap = {{"bufferView", 0},         {"width", kWidth}, {"height", kHeight},
                             {"texelSize", kTexel},     {"hMin", kHMin},   {"encoding", encodingName(o.encoding)},
                             {"distanceScale", kDistanceScale}};
  nlohmann::json extension = {
      {"version", format::revolution::kVersion},
      {"shapeMap", shapeMap},
      {"safetyMargin", marginFor(circle, o.encoding)},
      {"march", {{"iterations", o.iterations}, {"overRelaxation", 1.6}, {"hitEpsilon", 0.05 * kTexel}}},
      {"projection", {{"type", o.projection}, {"repeat", {2, 1}}, {"sphereCentreH", 0.5}}}};
  if (o.bands) {
    // Two bands around the solid's h range, one texel wider than it.
    const double lo = circle.centreH - circle.radius - kTexel, hi = circle.centreH + circle.radius + kTexel;
    const double rOut = circle.centreR + circle.radius + kTexel;
    extension["proxyBands"] = {{lo, circle.centreH, rOut}, {circle.centreH, hi, rOut}};
  }
  if (o.displacement) {
    double scale = 0;
    package.blobs.push_back({displacementBytes(64, scale), 16});
    extension["displacementMap"] = {{"bufferView", int(package.blobs.size()) - 1},
                                    {"width", 64},
                                    {"height", 64},
                                    {"derivativeScale", scale},
                                    {"heightScale", kBumpHeight}};
  }
  if (o.arcLengthMap) {
    package.blobs.push_back({sphereArcLengthBytes(), 16});
    extension["arcLengthMap"] = {{"bufferView", int(package.blobs.size()) - 1}};
  }
  if (!o.replicas.is_null()) extension["replicas"] = o.replicas;
  if (o.selfShadow) extension["selfShadow"] = true;
  nlohmann::json material = {{"pbrMetallicRoughness", {{"baseColorFactor", o.baseColour}}},
                             {"extensions", {{format::revolution::kExtension, extension}}}};
  if (o.colourTexture) {
    package.blobs.push_back({checkerPng(), 16});
    package.images = {{{"bufferView", int(package.blobs.size()) - 1}, {"mimeType", "image/png"}}};
    package.textures = {{{"source", 0}}};
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  }
  package.materials = nlohmann::json::array({material});
  package.meshes.push_back({"shape box", {boxMesh(rMax, hMin, hMax)}});
  glb::Node node;
  node.mesh = 0;
  package.nodes.push_back(node);
  package.extensionsUsed = {format::revolution::kExtension};
  return package;
}

// A standard (untechniqued) square at y = `height`, x and z in [-1, 1], in one colour.
glb::Package planePackage(float height, std::array<float, 4> colour) {
  glb::Primitive primitive;
  const std::vector<float> p = {-1, height, -1, 1, height, -1, 1, height, 1, -1, height, 1};
  const std::vector<float> n = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, p));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, n));
  primitive.indices = {0, 2, 1, 0, 3, 2};
  primitive.material = 0;
  glb::Package package;
  package.materials = nlohmann::json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", colour}}}}});
  package.meshes.push_back({"plane", {primitive}});
  glb::Node node;
  node.mesh = 0;
  package.nodes.push_back(node);
  return package;
}

fs::path writePackage(const glb::Package& package, const std::string& name) {
  const fs::path path = test::freshTempDir("revolution_" + name) / (name + ".glb");
  const Status status = glb::write(path, package);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return path;
}

// ---------------------------------------------------------------------------------------------
// Rendering and the CPU references

struct View {
  Vec3 eye, target;
};

std::string cameraText(const View& view) {
  auto v = [](const Vec3& p) {
    return std::to_string(p[0]) + "," + std::to_string(p[1]) + "," + std::to_string(p[2]);
  };
  return v(view.eye) + ":" + v(view.target);
}

// Renders through `bakeplay render`'s own entry point; the PNG read back (sRGB, top row first).
Image render(const std::vector<glb::Package>& packages, const std::string& name, const View& view,
             const std::string& light = "0.3,0.6,1") {
  RenderSettings settings;
  for (std::size_t i = 0; i < packages.size(); ++i)
    settings.view.scenes.push_back(writePackage(packages[i], name + std::to_string(i)).string());
  settings.view.width = settings.view.height = kSize;
  settings.view.camera = cameraText(view);
  settings.view.light = light;
  settings.output = (fs::path(settings.view.scenes[0]).parent_path() / (name + ".png")).string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  auto image = readImage(settings.output);
  EXPECT_TRUE(image.isOk());
  return image.isOk() ? *image : Image{};
}

struct Ray {
  Vec3 origin, direction;
};

// The ray through the centre of pixel (x, y) (top row first), built from the camera as lookAt and
// perspective define it.
Ray pixelRay(const View& view, int x, int y) {
  const Vec3 f = normalize(view.target - view.eye);
  const Vec3 s = normalize(cross(f, Vec3{0, 1, 0}));
  const Vec3 u = cross(s, f);
  const float t = std::tan(kFov / 2);
  const float nx = ((float(x) + 0.5f) / kSize * 2 - 1) * t, ny = (1 - (float(y) + 0.5f) / kSize * 2) * t;
  return {view.eye, normalize(s * nx + u * ny + f)};
}

// First crossing of the exact solid along the ray: its implicit function sampled every 1e-3 object
// units (well below the smallest feature, the torus tube's 0.3), the crossing refined by bisection.
// `implicit` is a lower bound of the distance to the solid outside it (an exact distance, or the
// least of several).
std::optional<double> exactHit(const std::function<double(const Vec3&)>& implicit, const Ray& ray, double tMax = 8.0) {
  auto at = [&](double t) { return implicit(ray.origin + ray.direction * float(t)); };
  const double step = 1e-3;
  double previous = at(0);
  if (previous < 0) return 0.0;
  for (double t = step; t < tMax; t += step) {
    const double value = at(t);
    if (value < 0) {
      double lo = t - step, hi = t;
      for (int i = 0; i < 40; ++i) ((at(0.5 * (lo + hi)) < 0) ? hi : lo) = 0.5 * (lo + hi);
      return hi;
    }
    // Far from the solid, skip ahead by the distance (the implicit function is an exact distance).
    if (value > 4 * step) t += value - 4 * step;
    previous = value;
  }
  return std::nullopt;
}

std::optional<double> exactHit(const Circle& circle, const Ray& ray, double tMax = 8.0) {
  return exactHit([&](const Vec3& p) { return circle.implicit(p); }, ray, tMax);
}

// Covered pixels differ from the background colour (the frame's clear colour, in a corner).
bool covered(const Image& image, int x, int y) {
  for (int c = 0; c < 3; ++c) {
    if (std::fabs(image.at(x, y, c) - image.at(0, 0, c)) > 0.02f) return true;
  }
  return false;
}

struct Mismatch {
  int reference = 0;  // covered pixels of the reference
  int differing = 0;  // pixels whose coverage differs
  int extra = 0;      // of those, covered in the frame but not in the reference
  double fraction() const { return reference ? double(differing) / reference : 1.0; }
  std::string describe() const {
    return std::to_string(differing) + " of " + std::to_string(reference) + " pixels differ (" +
           std::to_string(extra) + " covered only in the frame)";
  }
};

Mismatch silhouetteMismatch(const Image& image, const Circle& circle, const View& view) {
  Mismatch m;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool expected = exactHit(circle, pixelRay(view, x, y)).has_value();
      m.reference += expected ? 1 : 0;
      const bool drawn = covered(image, x, y);
      m.differing += expected != drawn ? 1 : 0;
      m.extra += drawn && !expected ? 1 : 0;
    }
  }
  return m;
}

// Keeps the measured figure in the test's XML record (--gtest_output=xml).
void record(const Mismatch& m) {
  ::testing::Test::RecordProperty("silhouetteMismatch", std::to_string(m.fraction()));
  ::testing::Test::RecordProperty("differingPixels", m.differing);
  ::testing::Test::RecordProperty("referencePixels", m.reference);
}

const View kFront{{0.0f, 1.3f, 2.6f}, {0.0f, 0.5f, 0.0f}};

// ---------------------------------------------------------------------------------------------
// (a) Silhouettes against the exact surfaces

class RevolutionSilhouette : public ::testing::TestWithParam<Encoding> {};

// Allowed mismatch. sqrt8 is filtered on its square-root code (as the GPU does), which underestimates
// distances within about a texel of the surface by up to a third of a texel: its silhouettes grow by
// a fraction of a pixel here (measured 1.4 % sphere, 1.8 % torus, every differing pixel an extra one).
double allowedMismatch(Encoding encoding) { return encoding == Encoding::Sqrt8 ? 0.03 : 0.01; }

TEST_P(RevolutionSilhouette, SphereMatchesTheAnalyticRayCast) {
  Options o;
  o.encoding = GetParam();
  const Image image = render({revolutionPackage(kSphere, o)}, "sphere", kFront);
  const Mismatch m = silhouetteMismatch(image, kSphere, kFront);
  record(m);
  EXPECT_GT(m.reference, 2000);
  EXPECT_LT(m.fraction(), allowedMismatch(o.encoding)) << m.describe();
}

TEST_P(RevolutionSilhouette, TorusMatchesTheAnalyticRayCast) {
  Options o;
  o.encoding = GetParam();
  const Image image = render({revolutionPackage(kTorus, o)}, "torus", kFront);
  const Mismatch m = silhouetteMismatch(image, kTorus, kFront);
  record(m);
  EXPECT_GT(m.reference, 1000);
  EXPECT_LT(m.fraction(), allowedMismatch(o.encoding)) << m.describe();
}

INSTANTIATE_TEST_SUITE_P(Encodings, RevolutionSilhouette,
                         ::testing::Values(Encoding::Float, Encoding::Unorm16, Encoding::Sqrt8),
                         [](const ::testing::TestParamInfo<Encoding>& info) { return encodingName(info.param); });

// Proxy bands only move where the march starts: with and without them the silhouette is the same.
TEST(RevolutionRender, ProxyBandsKeepTheSilhouette) {
  Options without;
  without.bands = false;
  without.iterations = 128;
  const Image image = render({revolutionPackage(kTorus, without)}, "torus_nobands", kFront);
  const Mismatch m = silhouetteMismatch(image, kTorus, kFront);
  record(m);
  EXPECT_LT(m.fraction(), 0.01) << m.describe();
}

// The march runs in object space: a node that moves, scales and mirrors the torus (which the mirror
// maps onto itself) shows the transformed exact torus. Mirroring also flips the box's winding.
TEST(RevolutionRender, NodeTransformsMoveScaleAndMirror) {
  glb::Package package = revolutionPackage(kTorus);
  const Vec3 offset{0.2f, -0.1f, 0.0f};
  const float scale = 1.3f;
  package.nodes[0].translation = {offset[0], offset[1], offset[2]};
  package.nodes[0].scale = {-scale, scale, scale};
  const Image image = render({package}, "torus_moved", kFront);
  Mismatch m;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      Ray ray = pixelRay(kFront, x, y);
      ray.origin = (ray.origin - offset) * (1.0f / scale);
      ray.origin[0] = -ray.origin[0];
      ray.direction[0] = -ray.direction[0];
      const bool expected = exactHit(kTorus, ray).has_value();
      const bool drawn = covered(image, x, y);
      m.reference += expected ? 1 : 0;
      m.differing += expected != drawn ? 1 : 0;
      m.extra += drawn && !expected ? 1 : 0;
    }
  }
  record(m);
  EXPECT_GT(m.reference, 2000);
  EXPECT_LT(m.fraction(), 0.01) << m.describe();
}

// A camera inside the shape box (in the torus' hole) starts its rays on the near plane.
TEST(RevolutionRender, CameraInsideTheShapeBox) {
  const View inside{{0.0f, 0.55f, 0.0f}, {1.0f, 0.75f, 0.3f}};
  const Image image = render({revolutionPackage(kTorus)}, "torus_inside", inside);
  const Mismatch m = silhouetteMismatch(image, kTorus, inside);
  record(m);
  EXPECT_GT(m.reference, 2000);
  EXPECT_LT(m.reference, kSize * kSize - 2000) << "the view shows the torus and the background above it";
  EXPECT_LT(m.fraction(), 0.01) << m.describe();
}

// Too few iterations leave grazing rays unconverged: the budget matters, and more is not worse.
TEST(RevolutionRender, TooFewIterationsLoseTheSilhouette) {
  Options few;
  few.iterations = 3;
  const Image image = render({revolutionPackage(kTorus, few)}, "torus_few", kFront);
  EXPECT_GT(silhouetteMismatch(image, kTorus, kFront).fraction(), 0.05);
}

// ---------------------------------------------------------------------------------------------
// (b) Depth: the revolved sphere and a standard-mesh plane through its centre cut each other where
// the exact sphere and plane do.

std::optional<double> sphereHit(const Ray& ray) {
  const Vec3 oc = ray.origin - Vec3{0, 0.5f, 0};
  const double b = dot(oc, ray.direction), c = dot(oc, oc) - 0.25;
  const double disc = b * b - c;
  if (disc < 0) return std::nullopt;
  const double t = -b - std::sqrt(disc);
  return t > 0 ? std::optional<double>(t) : std::nullopt;
}

TEST(RevolutionRender, DepthCutsAStandardMeshWhereTheSphereDoes) {
  Options o;
  o.baseColour = {0.1f, 0.2f, 0.9f, 1.0f};  // blue sphere
  const View view{{0.3f, 1.4f, 2.4f}, {0.0f, 0.5f, 0.0f}};
  const Image image =
      render({revolutionPackage(kSphere, o), planePackage(0.5f, {0.9f, 0.1f, 0.1f, 1.0f})}, "cut", view);
  int sphereFront = 0, planeFront = 0, wrong = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Ray ray = pixelRay(view, x, y);
      const std::optional<double> sphere = sphereHit(ray);
      std::optional<double> plane;
      if (std::fabs(ray.direction[1]) > 1e-6f) {
        const double t = (0.5 - ray.origin[1]) / ray.direction[1];
        const Vec3 p = ray.origin + ray.direction * float(t);
        if (t > 0 && std::fabs(p[0]) < 0.98f && std::fabs(p[2]) < 0.98f) plane = t;
      }
      if (!sphere || !plane) continue;
      // Leave out pixels near the cut line or the silhouette, where a pixel's footprint sees both.
      const Vec3 oc = ray.origin - Vec3{0, 0.5f, 0};
      const double miss = std::sqrt(std::max(0.0, double(dot(oc, oc)) - std::pow(dot(oc, ray.direction), 2)));
      if (std::fabs(*sphere - *plane) < 0.04 || miss > 0.48) continue;
      const bool sphereVisible = *sphere < *plane;
      const bool looksBlue = image.at(x, y, 2) > image.at(x, y, 0);
      (sphereVisible ? sphereFront : planeFront) += 1;
      wrong += looksBlue != sphereVisible ? 1 : 0;
    }
  }
  RecordProperty("wrongSurfacePixels", wrong);
  RecordProperty("comparedPixels", sphereFront + planeFront);
  EXPECT_GT(sphereFront, 300) << "the upper half stands in front of the plane";
  EXPECT_GT(planeFront, 300) << "the plane hides the lower half";
  EXPECT_LE(wrong, (sphereFront + planeFront) / 200) << wrong << " pixels show the wrong surface";
}

// ---------------------------------------------------------------------------------------------
// Texturing and bumps

// Bump mapping changes the shading, never the silhouette.
TEST(RevolutionRender, BumpsShadeButKeepTheSilhouette) {
  Options flat;
  Options bumped;
  bumped.displacement = true;
  const Image a = render({revolutionPackage(kTorus, flat)}, "flat", kFront);
  const Image b = render({revolutionPackage(kTorus, bumped)}, "bumped", kFront);
  int coverageDiffers = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) coverageDiffers += covered(a, x, y) != covered(b, x, y) ? 1 : 0;
  EXPECT_EQ(coverageDiffers, 0);
  auto difference = compareImages(a, b, 0.05);
  ASSERT_TRUE(difference.isOk());
  EXPECT_GT(difference->percentOver, 2.0) << describe(*difference);
}

// On the sphere, the arc-length map built here equals the spherical projection's v about the centre,
// so both projections give the same picture.
TEST(RevolutionRender, ArcLengthMatchesSphericalOnTheSphere) {
  Options spherical;
  spherical.projection = "spherical";
  spherical.colourTexture = true;
  Options arc = spherical;
  arc.projection = "arc-length";
  arc.arcLengthMap = true;
  const Image a = render({revolutionPackage(kSphere, spherical)}, "spherical", kFront);
  const Image b = render({revolutionPackage(kSphere, arc)}, "arclength", kFront);
  auto difference = compareImages(a, b, 0.1);
  ASSERT_TRUE(difference.isOk());
  EXPECT_LT(difference->percentOver, 1.0) << describe(*difference);
  // And the texture is really applied: the textured sphere differs from a plain one.
  Options plain = spherical;
  plain.colourTexture = false;
  auto untextured = compareImages(a, render({revolutionPackage(kSphere, plain)}, "plain", kFront), 0.1);
  ASSERT_TRUE(untextured.isOk());
  EXPECT_GT(untextured->percentOver, 10.0);
}

// The base colour image's top row is at the top of the object: the checker's top half is pink
// (green 0.6), its bottom half white; light pixels above the sphere's equator must be pink, below white.
TEST(RevolutionRender, ImageTopIsAtTheTop) {
  Options o;
  o.projection = "spherical";
  o.colourTexture = true;
  o.baseColour = {1, 1, 1, 1};
  const Image image = render({revolutionPackage(kSphere, o)}, "orientation", kFront);
  int upper = 0, upperPink = 0, lower = 0, lowerWhite = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Ray ray = pixelRay(kFront, x, y);
      const auto t = sphereHit(ray);
      if (!t) continue;
      const Vec3 p = ray.origin + ray.direction * float(*t);
      const double v = 1 - std::acos(std::clamp((p[1] - 0.5) / 0.5, -1.0, 1.0)) / kPi;
      const float r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
      if (r < 0.7f * b || std::fabs(v - 0.5) < 0.08) continue;  // dark squares, the equator
      const bool pink = g < 0.9f * r;
      if (v > 0.5) {
        ++upper;
        upperPink += pink ? 1 : 0;
      } else {
        ++lower;
        lowerWhite += pink ? 0 : 1;
      }
    }
  }
  ASSERT_GT(upper, 200);
  ASSERT_GT(lower, 100);
  EXPECT_GT(double(upperPink) / upper, 0.85) << upperPink << " of " << upper;
  EXPECT_GT(double(lowerWhite) / lower, 0.85) << lowerWhite << " of " << lower;
}

// (c) Goldens per projection (BAKE_UPDATE_GOLDEN=1 rewrites them): checker texture and bumps.
class RevolutionGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(RevolutionGolden, MatchesTheGoldenImage) {
  const std::string projection = GetParam();
  Options o;
  o.projection = projection;
  o.colourTexture = true;
  o.displacement = true;
  o.baseColour = {1, 1, 1, 1};
  const Circle& shape = projection == "spherical" ? kSphere : kTorus;
  const Image image = render({revolutionPackage(shape, o)}, "golden_" + projection, kFront);
  const std::string golden = "runtime/revolution-" + projection + ".v1.png";
  EXPECT_TRUE(test::matchesGoldenImage(image, golden));
}

INSTANTIATE_TEST_SUITE_P(Projections, RevolutionGolden, ::testing::Values("cylindrical", "spherical"));

// Only the maps a material reads reach the GPU: an arc-length map under a cylindrical projection
// stays behind, a displacement map is uploaded, and two instances of one package share their maps.
class RevolutionUpload : public test::GlTest {
 protected:
  std::size_t gpuBytes(const glb::Package& package, const std::string& name) {
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({writePackage(package, name)}, diagnostics, [](const std::string&) { return true; });
    EXPECT_TRUE(scene.isOk()) << scene.status().describe();
    gl::ShaderLibrary shaders;
    auto renderer = SceneRenderer::create(*scene, RendererRegistry::builtIn(), shaders);
    EXPECT_TRUE(renderer.isOk()) << renderer.status().describe();
    EXPECT_EQ(renderer->techniques(), std::vector<std::string>{format::revolution::kExtension});
    return renderer->gpuBytes();
  }
};

TEST_F(RevolutionUpload, OnlyTheMapsTheMaterialReads) {
  constexpr std::size_t kBoxBytes = 8 * 3 * 4 + 36 * 4;  // positions and indices of the drawn box
  Options o;
  o.arcLengthMap = true;  // present but not read: the projection is cylindrical
  const glb::Package unread = revolutionPackage(kSphere, o);
  EXPECT_EQ(gpuBytes(unread, "unread"), unread.blobs[0].bytes.size() + kBoxBytes);
  o.arcLengthMap = false;
  o.displacement = true;
  const glb::Package bumped = revolutionPackage(kSphere, o);
  EXPECT_EQ(gpuBytes(bumped, "bumped"), bumped.blobs[0].bytes.size() + bumped.blobs[1].bytes.size() + kBoxBytes);
  glb::Package twice = revolutionPackage(kSphere);
  glb::Node second = twice.nodes[0];
  second.translation = {1.5, 0, 0};
  twice.nodes.push_back(second);
  EXPECT_EQ(gpuBytes(twice, "twice"), twice.blobs[0].bytes.size() + 2 * kBoxBytes);
}

// Every variant compiles and links, including combinations no test package uses.
TEST_F(RevolutionUpload, EveryVariantCompiles) {
  gl::ShaderLibrary shaders;
  for (const char* encoding : {"ENCODING_FLOAT", "ENCODING_UNORM16", "ENCODING_SQRT8"}) {
    for (const char* projection : {"PROJECTION_CYLINDRICAL", "PROJECTION_SPHERICAL", "PROJECTION_ARC_LENGTH"}) {
      for (int features = 0; features < 4; ++features) {
        gl::Variant variant{{"revolution/revolution.vert", "revolution/revolution.frag", "", "", ""},
                            {encoding, projection, "MAX_PROXY_BANDS 64"}};
        if (features & 1) variant.defines.push_back("HAS_DISPLACEMENT");
        if (features & 2) variant.defines.push_back("HAS_BASE_COLOR_TEXTURE");
        const auto program = shaders.program(variant);
        EXPECT_TRUE(program.isOk()) << variant.key() << ": " << program.status().describe();
      }
    }
  }
  for (const char* replicas : {"", "REPLICAS_GRID", "REPLICAS_RING"}) {
    for (bool shadow : {false, true}) {
      gl::Variant variant{{"revolution/revolution.vert", "revolution/revolution.frag", "", "", ""},
                          {"ENCODING_UNORM16", "PROJECTION_SPHERICAL", "MAX_PROXY_BANDS 64", "HAS_DISPLACEMENT"}};
      if (*replicas) variant.defines.push_back(replicas);
      if (shadow) variant.defines.push_back("SELF_SHADOW");
      const auto program = shaders.program(variant);
      EXPECT_TRUE(program.isOk()) << variant.key() << ": " << program.status().describe();
    }
  }
}

// ---------------------------------------------------------------------------------------------
// (c) Replicas and self-shadowing (seed 001 Eq. 9 and Fig. 13; formats/revolution.md, "Replicas").
// The references place the copies by the format's words, written here apart from the runtime's cell
// walk: grid copy (i, j, k) is the object moved by (i, j, k) times the spacing, an odd copy of a
// mirrored axis reflected about its box's centre on that axis; ring copy k is the object moved out
// along +x and turned 2 pi k / n about +y. Each function maps a point to the one object's frame.

constexpr double kBoxExtent = 2 * kWidth * kTexel;  // 1.2 across, and kHeight * kTexel = 1.2 high
constexpr double kBoxCentreH = kHMin + 0.5 * kHeight * kTexel;

Vec3 gridCopyLocal(const Vec3& p, int i, int j, bool mirrorY) {
  Vec3 q{float(p[0] - i * kBoxExtent), float(p[1] - j * kBoxExtent), p[2]};
  if (mirrorY && j % 2 == 1) q[1] = float(2 * kBoxCentreH - q[1]);
  return q;
}

Vec3 ringCopyLocal(const Vec3& p, int k, int count, double radius) {
  const double back = -2 * kPi * k / count;
  const double x = p[0] * std::cos(back) - p[2] * std::sin(back), z = p[0] * std::sin(back) + p[2] * std::cos(back);
  return {float(x - radius), p[1], float(z)};
}

Mismatch coverageMismatch(const Image& image, const View& view, const std::function<double(const Vec3&)>& implicit) {
  Mismatch m;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool expected = exactHit(implicit, pixelRay(view, x, y), 14.0).has_value();
      const bool drawn = covered(image, x, y);
      m.reference += expected ? 1 : 0;
      m.differing += expected != drawn ? 1 : 0;
      m.extra += drawn && !expected ? 1 : 0;
    }
  }
  return m;
}

TEST(RevolutionReplicas, GridRowIsTheUnionOfMovedCopies) {
  Options o;
  o.replicas = {{"layout", "grid"}, {"count", {3, 1, 1}}};
  const View view{{1.2f, 2.2f, 5.0f}, {1.2f, 0.5f, 0.0f}};
  const Image image = render({revolutionPackage(kSphere, o)}, "grid_row", view);
  const Mismatch m = coverageMismatch(image, view, [](const Vec3& p) {
    double d = 1e30;
    for (int i = 0; i < 3; ++i) d = std::min(d, kSphere.implicit(gridCopyLocal(p, i, 0, false)));
    return d;
  });
  record(m);
  EXPECT_GT(m.reference, 2000);
  EXPECT_LT(m.fraction(), 0.01) << m.describe();
  // The reference can tell: the first copy alone is far from the frame.
  const Mismatch one = coverageMismatch(image, view, [](const Vec3& p) { return kSphere.implicit(p); });
  EXPECT_GT(one.differing, m.reference / 2) << one.describe();
}

// Fig. 13's mirror and repetition: a torus near the bottom of its box, three copies up the axis, the
// middle one reflected (its torus near the top of its cell).
TEST(RevolutionReplicas, MirroredStackReflectsOddCopies) {
  const Circle lowTorus{0.3, 0.15, 0.12};
  Options o;
  o.replicas = {{"layout", "grid"}, {"count", {1, 3, 1}}, {"mirror", {false, true, false}}};
  const View view{{0.0f, 3.4f, 4.2f}, {0.0f, 1.3f, 0.0f}};
  const Image image = render({revolutionPackage(lowTorus, o)}, "mirrored_stack", view);
  const auto stack = [&](bool mirror) {
    return [&lowTorus, mirror](const Vec3& p) {
      double d = 1e30;
      for (int j = 0; j < 3; ++j) d = std::min(d, lowTorus.implicit(gridCopyLocal(p, 0, j, mirror)));
      return d;
    };
  };
  const Mismatch m = coverageMismatch(image, view, stack(true));
  record(m);
  EXPECT_GT(m.reference, 600);
  EXPECT_LT(m.fraction(), 0.02) << m.describe();
  const Mismatch unmirrored = coverageMismatch(image, view, stack(false));
  EXPECT_GT(unmirrored.fraction(), 0.3) << "an unmirrored stack would look otherwise: " << unmirrored.describe();
}

TEST(RevolutionReplicas, RingTurnsCopiesAboutTheAxis) {
  Options o;
  o.replicas = {{"layout", "ring"}, {"count", 6}, {"radius", 1.3}};
  const View view{{0.3f, 4.0f, 4.6f}, {0.0f, 0.5f, 0.0f}};
  const Image image = render({revolutionPackage(kTorus, o)}, "ring", view);
  const Mismatch m = coverageMismatch(image, view, [](const Vec3& p) {
    double d = 1e30;
    for (int k = 0; k < 6; ++k) d = std::min(d, kTorus.implicit(ringCopyLocal(p, k, 6, 1.3)));
    return d;
  });
  record(m);
  EXPECT_GT(m.reference, 1500);
  EXPECT_LT(m.fraction(), 0.015) << m.describe();
}

// Self-shadowing: a row of three spheres lit low from +x; the +x side of each of the first two lies
// partly in the shadow of its neighbour. The reference casts the shadow rays
// analytically (ray against sphere); a pixel counts as lit by its red channel.
struct SphereHit {
  double t;
  Vec3 point, normal;
};
std::optional<SphereHit> nearestSphere(const Vec3& origin, const Vec3& direction, int count) {
  std::optional<SphereHit> best;
  for (int i = 0; i < count; ++i) {
    const Vec3 centre{float(i * kBoxExtent), 0.5f, 0.0f};
    const Vec3 oc = origin - centre;
    const double b = dot(oc, direction), c = dot(oc, oc) - 0.25, disc = b * b - c;
    if (disc < 0) continue;
    const double t = -b - std::sqrt(disc);
    if (t <= 1e-5 || (best && best->t <= t)) continue;
    const Vec3 p = origin + direction * float(t);
    best = SphereHit{t, p, normalize(p - centre)};
  }
  return best;
}

TEST(RevolutionReplicas, SelfShadowMatchesAnalyticShadowRays) {
  const Vec3 light = normalize(Vec3{1.0f, 0.3f, 0.15f});
  const std::string lightText = "1,0.3,0.15";
  const View view{{1.2f, 1.2f, 4.6f}, {1.2f, 0.5f, 0.0f}};
  Options o;
  o.replicas = {{"layout", "grid"}, {"count", {3, 1, 1}}};
  o.selfShadow = true;
  const Image shadowed = render({revolutionPackage(kSphere, o)}, "shadowed_row", view, lightText);
  o.selfShadow = false;
  const Image unshadowed = render({revolutionPackage(kSphere, o)}, "unshadowed_row", view, lightText);
  // Lit with n.l >= 0.25: red >= 0.9 * (0.08 + 0.25) linear, 0.58 in sRGB; in shadow: ambient only,
  // 0.9 * 0.08 linear, 0.30 in sRGB.
  constexpr float kLitRed = 0.44f;
  int inShadow = 0, lit = 0, wrong = 0, shadowsDrawnWithout = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Ray ray = pixelRay(view, x, y);
      const auto hit = nearestSphere(ray.origin, ray.direction, 3);
      if (!hit || dot(hit->normal, light) < 0.25f) continue;
      // Leave out the outline, where a pixel's footprint spans two surfaces.
      if (-dot(hit->normal, ray.direction) < 0.2f) continue;
      const bool expectShadow = nearestSphere(hit->point + hit->normal * 1e-4f, light, 3).has_value();
      (expectShadow ? inShadow : lit) += 1;
      wrong += (shadowed.at(x, y, 0) >= kLitRed) == expectShadow ? 1 : 0;
      if (expectShadow && unshadowed.at(x, y, 0) < kLitRed) ++shadowsDrawnWithout;
    }
  }
  RecordProperty("shadowedPixels", inShadow);
  RecordProperty("litPixels", lit);
  RecordProperty("wrongPixels", wrong);
  EXPECT_GT(inShadow, 150);
  EXPECT_GT(lit, 500);
  EXPECT_LE(wrong, (inShadow + lit) * 3 / 100) << wrong << " of " << inShadow + lit << " pixels lit wrongly";
  EXPECT_LE(shadowsDrawnWithout, inShadow / 20) << "without selfShadow those pixels are lit";
}

// ---------------------------------------------------------------------------------------------
// (d) Validation names the fault

TEST(RevolutionValidate, AcceptsWellFormedPackages) {
  for (Encoding e : {Encoding::Float, Encoding::Unorm16, Encoding::Sqrt8}) {
    Options o;
    o.encoding = e;
    o.displacement = o.colourTexture = o.arcLengthMap = true;
    const Status status = checkPackageStructure(revolutionPackage(kSphere, o), "ok.glb");
    EXPECT_TRUE(status.isOk()) << status.describe();
  }
}

nlohmann::json& extensionOf(glb::Package& package) {
  return package.materials[0]["extensions"][format::revolution::kExtension];
}

struct Damage {
  std::string name;
  std::function<void(glb::Package&)> apply;
  std::string expected;  // text the message must contain
};

TEST(RevolutionValidate, RejectsDamagedPackagesNamingTheFault) {
  const std::vector<Damage> damages = {
      {"version", [](glb::Package& p) { extensionOf(p)["version"] = 2; }, "version 2"},
      {"bufferView index", [](glb::Package& p) { extensionOf(p)["shapeMap"]["bufferView"] = 7; },
       "shapeMap.bufferView is 7"},
      {"byte size", [](glb::Package& p) { p.blobs[0].bytes.resize(p.blobs[0].bytes.size() - 8); },
       "shapeMap.bufferView (bufferView 0) holds"},
      {"size fields", [](glb::Package& p) { extensionOf(p)["shapeMap"]["width"] = kWidth + 1; },
       "shapeMap.bufferView"},
      {"encoding", [](glb::Package& p) { extensionOf(p)["shapeMap"]["encoding"] = "half"; },
       "shapeMap.encoding is \"half\""},
      {"texel size", [](glb::Package& p) { extensionOf(p)["shapeMap"]["texelSize"] = 0.0; },
       "shapeMap.texelSize must be positive"},
      {"margin", [](glb::Package& p) { extensionOf(p)["safetyMargin"] = "tiny"; },
       "safetyMargin must be a finite number"},
      {"negative margin", [](glb::Package& p) { extensionOf(p)["safetyMargin"] = -0.1; }, "safetyMargin is -0.1"},
      {"iterations", [](glb::Package& p) { extensionOf(p)["march"]["iterations"] = 0; }, "march.iterations"},
      {"band order", [](glb::Package& p) { extensionOf(p)["proxyBands"][1] = {0.9, 0.2, 0.3}; },
       "proxyBands[1] has hMin >= hMax"},
      {"band shape", [](glb::Package& p) { extensionOf(p)["proxyBands"][0] = {0.1, 0.2}; },
       "proxyBands[0] must be [hMin, hMax, rMax]"},
      {"too many bands",
       [](glb::Package& p) {
         nlohmann::json bands = nlohmann::json::array();
         for (int i = 0; i <= format::revolution::kMaxProxyBands; ++i) bands.push_back({i, i + 1, 0.5});
         extensionOf(p)["proxyBands"] = bands;
       },
       "at most 64"},
      {"projection", [](glb::Package& p) { extensionOf(p)["projection"]["type"] = "conical"; },
       "projection.type is \"conical\""},
      {"arc length map", [](glb::Package& p) { extensionOf(p)["projection"]["type"] = "arc-length"; },
       "arcLengthMap is missing"},
      {"repeat", [](glb::Package& p) { extensionOf(p)["projection"]["repeat"] = {0, 1}; }, "projection.repeat"},
      {"distance scale", [](glb::Package& p) { extensionOf(p)["shapeMap"].erase("distanceScale"); },
       "shapeMap.distanceScale is missing"},
      {"displacement size", [](glb::Package& p) { extensionOf(p)["displacementMap"]["height"] = 32; },
       "displacementMap.bufferView"},
      {"texture", [](glb::Package& p) { p.images[0].erase("bufferView"); }, "not embedded"},
      {"replica layout", [](glb::Package& p) { extensionOf(p)["replicas"] = {{"layout", "spiral"}, {"count", 3}}; },
       "replicas.layout is \"spiral\""},
      {"overlapping copies",
       [](glb::Package& p) {
         extensionOf(p)["replicas"] = {{"layout", "grid"}, {"count", {2, 1, 1}}, {"spacing", {1.0, 1.2, 1.2}}};
       },
       "replicas.spacing is [1.0,1.2,1.2]"},
      {"too many copies",
       [](glb::Package& p) { extensionOf(p)["replicas"] = {{"layout", "grid"}, {"count", {100, 100, 1}}}; },
       "replicas.count asks for more than 4096"},
      {"crowded ring",
       [](glb::Package& p) { extensionOf(p)["replicas"] = {{"layout", "ring"}, {"count", 6}, {"radius", 1.0}}; },
       "replicas.radius is 1; 6 copies"},
      {"self shadow", [](glb::Package& p) { extensionOf(p)["selfShadow"] = "yes"; }, "selfShadow must be true or false"},
  };
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.name);
    Options o;
    o.displacement = o.colourTexture = true;
    glb::Package package = revolutionPackage(kSphere, o);
    damage.apply(package);
    const Status status = checkPackageStructure(package, "damaged.glb");
    ASSERT_FALSE(status.isOk());
    EXPECT_NE(status.describe().find("damaged.glb"), std::string::npos) << status.describe();
    EXPECT_NE(status.describe().find("material 0"), std::string::npos) << status.describe();
    EXPECT_NE(status.describe().find(damage.expected), std::string::npos) << status.describe();
  }
}

// A damaged package is refused by the renderer too (no upload of a short buffer).
TEST(RevolutionValidate, RenderRefusesADamagedPackage) {
  glb::Package package = revolutionPackage(kSphere);
  package.blobs[0].bytes.resize(100);
  RenderSettings settings;
  settings.view.scenes = {writePackage(package, "short").string()};
  settings.view.width = settings.view.height = 16;
  settings.output = (fs::path(settings.view.scenes[0]).parent_path() / "short.png").string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(status.describe().find("shapeMap.bufferView"), std::string::npos) << status.describe();
}

// ---------------------------------------------------------------------------------------------
// End to end: revolbake's package of the example vase against the vase's own profile

// revolbake's settings for an example profile of pipelines/revolution, baked into `dir` at 512 texels.
revolution::Settings exampleBake(const std::string& profile, const fs::path& dir) {
  revolution::Settings settings;
  settings.input = (test::sourceDir() / "pipelines" / "revolution" / (profile + ".json")).string();
  settings.output = (dir / (profile + ".glb")).string();
  settings.resolution = 512;
  settings.common.quiet = true;
  return settings;
}

Status runBake(const revolution::Settings& settings) {
  Diagnostics quiet("revolbake", true);
  return revolution::run(settings, quiet);
}

TEST(RevolutionBaked, VaseSilhouetteMatchesItsProfileWithinTheReportedError) {
  const fs::path dir = test::freshTempDir("baked_vase");
  const revolution::Settings settings = exampleBake("vase", dir);
  const Status baked = runBake(settings);
  ASSERT_TRUE(baked.isOk()) << baked.describe();
  auto package = glb::read(settings.output);
  ASSERT_TRUE(package.isOk()) << package.status().describe();
  const double reported =
      package->materials[0]["extensions"][format::revolution::kExtension]["march"]["silhouetteMismatch"].get<double>();
  // Saturated red: even the unlit side of the outline differs from the grey background.
  package->materials[0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 0.0, 0.0, 1.0};

  auto profile = revolution::readProfileJson(settings.input);
  ASSERT_TRUE(profile.isOk());
  std::vector<std::string> repairs;
  ASSERT_TRUE(revolution::validateProfile(*profile, repairs).isOk());
  const View view{{0.0f, 1.2f, 2.2f}, {0.0f, 0.45f, 0.0f}};
  const Image image = render({*package}, "baked_vase", view);
  ASSERT_EQ(image.width, kSize);
  Mismatch m;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Ray ray = pixelRay(view, x, y);
      revolution::Ray exactRay{{ray.origin[0], ray.origin[1], ray.origin[2]},
                               {ray.direction[0], ray.direction[1], ray.direction[2]}};
      const bool expected = revolution::intersectExact(exactRay, *profile).has_value();
      const bool drawn = covered(image, x, y);
      m.reference += expected ? 1 : 0;
      m.differing += expected != drawn ? 1 : 0;
      m.extra += drawn && !expected ? 1 : 0;
    }
  }
  record(m);
  ::testing::Test::RecordProperty("reportedMismatch", std::to_string(reported));
  ASSERT_GT(m.reference, 1000);
  // The bake's figure is over rays from six views of a finer grid; one 128^2 view adds the pixels the
  // rasteriser decides differently right at the outline, a few per hundred outline pixels.
  EXPECT_LE(m.fraction(), reported + 0.005) << m.describe() << "; the bake reported " << reported;
}

// `bakeplay validate --golden` on the example's row of balusters as revolbake writes it (five copies
// of one profile in one box, self-shadowing on): the package passes, and its first reference view is
// the golden image (tests/golden/runtime/revolution-balusters.v1.png).
TEST(RevolutionBaked, BalusterRowValidatesAgainstItsGoldenImage) {
  const fs::path dir = test::freshTempDir("baked_balusters");
  revolution::Settings settings = exampleBake("baluster", dir);
  settings.grid = {5, 1, 1};
  settings.gridSpacing = {0.55, 0, 0};
  const Status baked = runBake(settings);
  ASSERT_TRUE(baked.isOk()) << baked.describe();
  auto package = glb::read(settings.output);
  ASSERT_TRUE(package.isOk()) << package.status().describe();
  const nlohmann::json& extension = package->materials[0]["extensions"][format::revolution::kExtension];
  EXPECT_EQ(extension["replicas"]["count"], nlohmann::json({5, 1, 1}));
  EXPECT_EQ(extension["selfShadow"], true);

  test::expectValidatesAgainstGolden(settings.output, "runtime/revolution-balusters.v1.png", dir / "views");
}

}  // namespace
}  // namespace bake::play
