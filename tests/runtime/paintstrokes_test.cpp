// Paintstrokes (seed 002) in the runtime: view-dependent tessellation on the GPU against fixed tubes
// tessellated on the CPU. A small package is built here with libbake's writer (straight, curved and
// tapered strokes), drawn headless at each quality level and as fine tubes (64 around, 32 along each
// segment: the reference, whose own facets deviate from the true cylinder by r (1 - cos(pi/64)), about
// 0.1% of the radius). Checked: the frames are not empty and finite, the strokes cover the same pixels
// as the reference, the finest quality is close to it in RMSE, the polygon counts follow the quality
// level and the tolerance, the triangles the GPU reports (GL_PRIMITIVES_GENERATED) are the ones the
// control stage predicts from its levels, a stroke outside the view generates nothing, and head-on
// views stay finite. Also: registration and the loader checks for `bakeplay validate`.
#include <gtest/gtest.h>

#include <GL/glcorearb.h>
#include <bake_formats/paintstrokes.h>

#include <cmath>
#include <cstring>
#include <tuple>
#include <vector>

#include "bake/io/glb.h"
#include "paintstrokes/package/package.h"
#include "play/validate.h"
#include "render/paintstrokes.h"
#include "render/target.h"
#include "runtime/gl_test.h"
#include "scene/scene.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;
namespace fmt = format::paintstrokes;

constexpr int kSize = 160;

paintstrokes::StrokePoint point(double x, double y, double z, double radius, Vec3d colour) {
  paintstrokes::StrokePoint p;
  p.position = {x, y, z};
  p.radius = radius;
  p.colour = colour;
  return p;
}

// Three strokes in the z = 0 plane around the origin: a straight one, a half circle, and a tapered
// S curve; one style, opaque at the centre and a little translucent at the edges, with a highlight.
paintstrokes::StrokeSet sampleStrokes() {
  paintstrokes::StrokeSet set;
  paintstrokes::StrokeStyle style;
  style.edgeOpacity = 0.8;
  style.volumeAcross = 0.9;
  style.specular = {0.3, 0.3, 0.3};
  style.shininess = 24;
  set.styles.push_back(style);
  paintstrokes::Stroke straight;
  for (int i = 0; i < 3; ++i) straight.points.push_back(point(-0.8 + 0.8 * i, 0.6, 0, 0.06, {0.8, 0.3, 0.2}));
  paintstrokes::Stroke arc;
  for (int i = 0; i <= 6; ++i) {
    const double a = M_PI * i / 6;
    arc.points.push_back(point(-0.35 + 0.4 * std::cos(a), -0.1 - 0.4 * std::sin(a), 0, 0.05, {0.2, 0.6, 0.3}));
  }
  paintstrokes::Stroke curl;
  for (int i = 0; i <= 5; ++i) {
    const double t = i / 5.0;
    curl.points.push_back(point(0.3 + 0.5 * t, -0.5 + 0.25 * std::sin(2 * M_PI * t), 0.1 * t, 0.07 * (1 - 0.7 * t),
                                {0.25, 0.35, 0.85}));
  }
  set.strokes = {straight, arc, curl};
  return set;
}

fs::path writePackage(const paintstrokes::StrokeSet& set, const std::string& name) {
  auto package = paintstrokes::buildPaintstrokePackage(set, {}, {}, nullptr);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  if (!package.isOk()) return {};
  const fs::path file = test::freshTempDir("paintstrokes_" + name) / (name + ".glb");
  const Status written = glb::write(file, *package);
  EXPECT_TRUE(written.isOk()) << written.describe();
  return file;
}

struct Frame {
  Image image;
  PaintstrokeCounts counts;
  std::uint64_t coverage = 0;  // pixels the strokes changed (background black)
  bool finite = true;
};

class Paintstrokes : public test::GlTest {
 protected:
  void SetUp() override {
    test::GlTest::SetUp();
    file_ = writePackage(sampleStrokes(), "sample");
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({file_}, diagnostics, [](const std::string&) { return true; });
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    scene_ = std::move(scene).value();
    ASSERT_EQ(scene_.instances.size(), 1u);
    ASSERT_EQ(scene_.technique(scene_.instances[0]), fmt::kExtension);
  }

  Frame render(const PaintstrokeOptions& options, const Camera& camera) { return render(scene_, options, camera); }

  Frame render(const Scene& scene, const PaintstrokeOptions& options, const Camera& camera) {
    Frame out;
    gl::ShaderLibrary shaders;
    PaintstrokesRenderer renderer(options);
    const Status prepared = renderer.prepare(scene, {0}, shaders);
    EXPECT_TRUE(prepared.isOk()) << prepared.describe();
    if (!prepared.isOk()) return out;
    auto target = OffscreenTarget::create(kSize, kSize);
    EXPECT_TRUE(target.isOk());
    if (!target.isOk()) return out;
    const Light light{normalize(Vec3{0.3f, 0.6f, 0.8f}), {1, 1, 1}};
    const FrameContext frame{scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), kSize, kSize};
    target->bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    renderer.draw(frame);
    out.counts = renderer.lastFrameCounts();
    out.image = target->readLinearRgba();
    for (std::size_t p = 0; p < std::size_t(kSize) * kSize; ++p) {
      const float* c = &out.image.pixels[p * 4];
      out.finite = out.finite && std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]);
      if (c[0] > 0.02f || c[1] > 0.02f || c[2] > 0.02f) ++out.coverage;
    }
    return out;
  }

  static Camera front() { return Camera{{0.1f, -0.2f, 3.0f}, {0, -0.05f, 0}, {0, 1, 0}, 0.7f, 0.1f, 20.0f}; }

  static PaintstrokeOptions quality(int level, float tolerance = 0.5f) {
    PaintstrokeOptions o;
    o.quality = level;
    o.tolerance = tolerance;
    return o;
  }
  static PaintstrokeOptions tubes(int sides, int steps) {
    PaintstrokeOptions o;
    o.tubeSides = sides;
    o.tubeSteps = steps;
    return o;
  }

  fs::path file_;
  Scene scene_;
};

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.pixels[i]) - double(b.pixels[i]);
    sum += d * d;
    ++n;
  }
  return std::sqrt(sum / double(std::max<std::size_t>(n, 1)));
}

TEST_F(Paintstrokes, RegisteredAndChecked) {
  EXPECT_TRUE(RendererRegistry::builtIn().has(fmt::kExtension));
  auto package = glb::read(file_);
  ASSERT_TRUE(package.isOk());
  const Status ok = checkPackageStructure(*package, file_.string());
  EXPECT_TRUE(ok.isOk()) << ok.describe();
}

TEST_F(Paintstrokes, QualityLevelsMatchFineTubes) {
  const Frame reference = render(tubes(64, 32), front());
  ASSERT_TRUE(reference.finite);
  // Not empty: the three strokes cover a few percent of the frame.
  EXPECT_GT(reference.coverage, std::uint64_t(kSize * kSize / 50));
  Frame levels[3];
  for (int q = 0; q < 3; ++q) {
    levels[q] = render(quality(q), front());
    ASSERT_TRUE(levels[q].finite) << "quality " << q;
    const double covered = double(levels[q].coverage), expected = double(reference.coverage);
    // Silhouettes agree to within the tolerance and a pixel of antialiasing on each side of a
    // stroke: at most 4% of the covered pixels differ in count.
    EXPECT_NEAR(covered, expected, 0.04 * expected) << "quality " << q;
    const double error = rmse(levels[q].image, reference.image);
    RecordProperty("rmse_quality" + std::to_string(q), std::to_string(error));
    RecordProperty("polygons_quality" + std::to_string(q), std::to_string(levels[q].counts.polygons));
  }
  RecordProperty("polygons_tubes_64x32", std::to_string(reference.counts.polygons));
  // Quality 2 shades from the same normal formula as the tubes; what differs is the silhouette
  // (half a pixel of tessellation tolerance, different rasterisation of the edge ramp) and the
  // facets of the reference. Linear RMSE over the frame below 0.02 (the strokes cover about a tenth
  // of it; an edge pixel off by its whole colour counts about 0.5).
  EXPECT_LT(rmse(levels[2].image, reference.image), 0.02);
  // Fewer polygons across, fewer triangles; far fewer than the reference tubes.
  EXPECT_LT(levels[0].counts.polygons, levels[1].counts.polygons);
  EXPECT_LT(levels[1].counts.polygons, levels[2].counts.polygons);
  EXPECT_LT(levels[2].counts.polygons * 10, reference.counts.polygons);
  EXPECT_GT(levels[0].counts.polygons, 0u);
}

// Thousands of segments in one draw (a driver splits such draws into batches): every stroke is drawn,
// covering what the tubes cover (strokes about 2 pixels wide, so the comparison is not dominated by
// how each rasterises sub-pixel widths).
TEST_F(Paintstrokes, ManyStrokesAreAllDrawn) {
  paintstrokes::StrokeSet set = sampleStrokes();
  set.strokes.clear();
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 20; ++column) {
      paintstrokes::Stroke stroke;
      for (int i = 0; i < 4; ++i)
        stroke.points.push_back(point(-1 + 0.1 * column + 0.02 * i, -1 + 0.05 * row + 0.005 * (i % 2), 0, 0.016,
                                      {0.9, 0.8, 0.3}));
      set.strokes.push_back(stroke);
    }
  }
  const fs::path file = writePackage(set, "many");
  Diagnostics diagnostics("bakeplay", true);
  auto scene = loadScene({file}, diagnostics, [](const std::string&) { return true; });
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  const Camera camera{{0, 0, 3.2f}, {0, 0, 0}, {0, 1, 0}, 0.7f, 0.1f, 20.0f};
  const Frame strokes = render(*scene, quality(1), camera);
  const Frame tubes = render(*scene, this->tubes(16, 4), camera);
  EXPECT_EQ(strokes.counts.segments, 800u * 3u);
  EXPECT_GT(tubes.coverage, std::uint64_t(kSize * kSize / 20));
  EXPECT_NEAR(double(strokes.coverage), double(tubes.coverage), 0.04 * double(tubes.coverage));
}

TEST_F(Paintstrokes, GeneratedTrianglesAreThePredictedOnes) {
  for (int q = 0; q < 3; ++q) {
    const Frame f = render(quality(q), front());
    // The control stage's prediction of the tessellator's output (a regular grid, or the fan of one
    // polygon across) against the GPU's own count.
    EXPECT_EQ(f.counts.polygons, f.counts.predictedPolygons) << "quality " << q;
    EXPECT_GT(f.counts.vertices, f.counts.segments) << "quality " << q;
  }
  const Frame t = render(tubes(8, 4), front());
  // Tubes: every triangle of the mesh is generated (culling comes later): 2 x 8 x 4 per segment.
  EXPECT_EQ(t.counts.polygons, 2u * 8u * 4u * t.counts.segments);
  EXPECT_EQ(t.counts.vertices, 8u * 5u * t.counts.segments);
}

TEST_F(Paintstrokes, PolygonsGrowAsTheToleranceShrinks) {
  const Frame coarse = render(quality(1, 4.0f), front());
  const Frame medium = render(quality(1, 0.5f), front());
  const Frame fine = render(quality(1, 0.05f), front());
  EXPECT_LT(coarse.counts.polygons, medium.counts.polygons);
  EXPECT_LT(medium.counts.polygons, fine.counts.polygons);
  RecordProperty("polygons_4px", std::to_string(coarse.counts.polygons));
  RecordProperty("polygons_0.5px", std::to_string(medium.counts.polygons));
  RecordProperty("polygons_0.05px", std::to_string(fine.counts.polygons));
}

TEST_F(Paintstrokes, StrokesOutsideTheViewGenerateNothing) {
  // Looking away from the strokes (they are behind the camera).
  const Camera away{{0, 0, 3}, {0, 0, 6}, {0, 1, 0}, 0.7f, 0.1f, 20.0f};
  for (int q = 0; q < 3; ++q) {
    const Frame f = render(quality(q), away);
    EXPECT_EQ(f.counts.polygons, 0u) << "quality " << q;
    EXPECT_EQ(f.counts.vertices, 0u) << "quality " << q;
    EXPECT_EQ(f.coverage, 0u);
  }
  // Beside the view: the frustum's side planes cull too.
  const Camera aside{{5, 0, 3}, {5, 0, 0}, {0, 1, 0}, 0.3f, 0.1f, 20.0f};
  EXPECT_EQ(render(quality(2), aside).counts.polygons, 0u);
}

TEST_F(Paintstrokes, HeadOnViewsStayFinite) {
  // Straight down the straight stroke's axis (it runs along x at y = 0.6, z = 0), from both ends,
  // and from very close.
  const Camera views[] = {{{3, 0.6f, 0}, {0, 0.6f, 0}, {0, 1, 0}, 0.7f, 0.1f, 20.0f},
                          {{-3, 0.6f, 0}, {0, 0.6f, 0}, {0, 1, 0}, 0.7f, 0.1f, 20.0f},
                          {{0.85f, 0.6f, 0}, {0, 0.6f, 0}, {0, 1, 0}, 0.7f, 0.01f, 20.0f}};
  for (const Camera& camera : views) {
    for (int q = 0; q < 3; ++q) {
      const Frame f = render(quality(q), camera);
      EXPECT_TRUE(f.finite) << "quality " << q << " eye x " << camera.eye[0];
    }
    EXPECT_TRUE(render(tubes(16, 8), camera).finite);
  }
}

TEST(PaintstrokeOptions, BadValuesAreUsageErrors) {
  EXPECT_TRUE(makePaintstrokeOptions(1, 0.5, "").isOk());
  auto tubes = makePaintstrokeOptions(1, 0.5, "12x3");
  ASSERT_TRUE(tubes.isOk());
  EXPECT_EQ(tubes->tubeSides, 12);
  EXPECT_EQ(tubes->tubeSteps, 3);
  EXPECT_EQ(makePaintstrokeOptions(1, 0.5, "16")->tubeSteps, 8);
  for (const auto& [quality, tolerance, text] : std::vector<std::tuple<int, double, std::string>>{
           {3, 0.5, ""}, {-1, 0.5, ""}, {1, 0.0, ""}, {1, NAN, ""}, {1, 0.5, "2x4"}, {1, 0.5, "8x0"}, {1, 0.5, "8x"},
           {1, 0.5, "x8"}, {1, 0.5, "8x4x2"}, {1, 0.5, "-8x4"}, {1, 0.5, "eight"}}) {
    const auto options = makePaintstrokeOptions(quality, tolerance, text);
    EXPECT_FALSE(options.isOk()) << quality << " " << tolerance << " " << text;
    if (!options.isOk()) EXPECT_EQ(options.status().code(), ExitCode::Usage);
  }
}

// The loader checks refuse tampered packages, naming the element.
TEST(PaintstrokeValidate, RefusesTamperedPackages) {
  auto built = paintstrokes::buildPaintstrokePackage(sampleStrokes(), {}, {}, nullptr);
  ASSERT_TRUE(built.isOk()) << built.status().describe();
  ASSERT_TRUE(checkPaintstrokePackage(*built, "sample.glb").isOk());
  int material = -1;
  for (std::size_t m = 0; m < built->materials.size(); ++m)
    if (built->materials[m]["extensions"].contains(fmt::kExtension)) material = int(m);
  ASSERT_GE(material, 0);
  const nlohmann::json& extension = built->materials[std::size_t(material)]["extensions"][fmt::kExtension];

  {  // A style's centre opacity of 2.
    glb::Package tampered = *built;
    auto& bytes = tampered.blobs[extension["bufferViews"]["styles"].get<std::size_t>()].bytes;
    const float two = 2.0f;
    std::memcpy(bytes.data(), &two, 4);
    const Status s = checkPaintstrokePackage(tampered, "sample.glb");
    EXPECT_FALSE(s.isOk());
    EXPECT_NE(s.describe().find("styles/0"), std::string::npos) << s.describe();
  }
  {  // A stroke whose points run past the array.
    glb::Package tampered = *built;
    auto& bytes = tampered.blobs[extension["bufferViews"]["strokes"].get<std::size_t>()].bytes;
    const std::uint32_t many = 1000;
    std::memcpy(bytes.data() + 4, &many, 4);
    const Status s = checkPackageStructure(tampered, "sample.glb");
    EXPECT_FALSE(s.isOk());
    EXPECT_NE(s.describe().find("strokes/0"), std::string::npos) << s.describe();
  }
  {  // The centrelines drawn as triangles.
    glb::Package tampered = *built;
    for (auto& mesh : tampered.meshes)
      for (auto& primitive : mesh.primitives)
        if (primitive.material == material) primitive.mode = 4;
    const Status s = checkPaintstrokePackage(tampered, "sample.glb");
    EXPECT_FALSE(s.isOk());
    EXPECT_NE(s.describe().find("LINES"), std::string::npos) << s.describe();
  }
}

}  // namespace
}  // namespace bake::play
