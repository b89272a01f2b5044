// Grooved surfaces (seed 000 §4-§7) in the runtime, checked against libbake's CPU method, the oracle
// (libbake/grooves/oracle/shade.h SeedShader::shade). Each scene is baked here (parseGrooveScene ->
// buildGrooveGrid -> buildGroovePackage), drawn headless by the grooves renderer into 32-bit float
// attachments with the shader's SHADING_INPUTS variant, which also writes every pixel's shading inputs
// (footprint centre F, edges A1 and A2, E and L in the tangent frame). The CPU method shades each
// pixel from exactly those inputs; after 8-bit quantisation (round(255 clamp(x)), the rendering
// model's output) no channel may differ by more than 2 levels. The RMSE and the largest difference
// are recorded as test properties. Also: the bakeplay registration and package checks.
#include <gtest/gtest.h>

#include <GL/glcorearb.h>
#include <bake_formats/grooves.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "bake/io/glb.h"
#include "bake/mesh/shapes.h"
#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/shade.h"
#include "grooves/package/package.h"
#include "grooves/package/surface.h"
#include "mesh/tangent_frames.h"
#include "grooves/reference/reference.h"
#include "play/validate.h"
#include "render/grooves.h"
#include "render/target.h"
#include "runtime/gl_test.h"
#include "runtime/golden_image.h"
#include "scene/scene.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

constexpr int kSize = 96;
constexpr int kAttachments = 4;  // radiance, then the three shading-input outputs

struct Baked {
  grooves::GrooveScene scene;
  grooves::GrooveGrid grid;
  fs::path file;
};

// `node`: place the preview plane with this node (a rotation, to test the tangent frame); default:
// the writer's node with no transform.
// `uvScale`: the preview plane's TEXCOORD_0 multiplied by it (a repeating pattern tiled that many
// times across the plane).
// `surface`: the preview plane replaced by this mesh (groovebake --apply-to).
// `specialCases`: false leaves out the special-case records (groovebake --no-special-cases).
Baked bake(const std::string& json, const std::string& name, std::optional<glb::Node> node = std::nullopt,
           float uvScale = 1, const grooves::GrooveSurface* surface = nullptr, bool specialCases = true) {
  Baked out;
  auto scene = grooves::parseGrooveScene(json, name + ".json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  if (!scene.isOk()) return out;
  out.scene = std::move(scene).value();
  auto grid = grooves::buildGrooveGrid(out.scene, {});
  EXPECT_TRUE(grid.isOk()) << grid.status().describe();
  if (!grid.isOk()) return out;
  out.grid = std::move(grid).value();
  if (!specialCases) grooves::dropSpecialCases(out.grid);
  auto package = grooves::buildGroovePackage(out.scene, out.grid);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  if (!package.isOk()) return out;
  if (surface) grooves::applySurface(*package, *surface);
  if (node) package->nodes.push_back(*node);
  if (uvScale != 1) {
    for (glb::Attribute& attribute : package->meshes[0].primitives[0].attributes) {
      if (attribute.name != "TEXCOORD_0") continue;
      std::vector<float> uv = attribute.toFloats();
      for (float& x : uv) x *= uvScale;
      attribute = glb::Attribute::fromFloats("TEXCOORD_0", 2, uv);
    }
  }
  out.file = test::freshTempDir("grooves_" + name) / (name + ".glb");
  const Status written = glb::write(out.file, *package);
  EXPECT_TRUE(written.isOk()) << written.describe();
  return out;
}

// bakeshape's column (64 segments) with the tangent frames groovebake --apply-to computes.
grooves::GrooveSurface columnSurface() {
  grooves::GrooveSurface surface;
  surface.name = "column";
  Result<TriangleMesh> column = makeShape({"column", 64});
  EXPECT_TRUE(column.isOk()) << column.status().describe();
  if (!column.isOk()) return surface;
  surface.mesh = std::move(column).value();
  Result<TangentFrames> frames = computeTangentFrames(surface.mesh);
  EXPECT_TRUE(frames.isOk()) << frames.status().describe();
  if (frames.isOk()) surface.tangents = frames->tangents;
  return surface;
}

// Straight lines across the domain and beyond it (so no open end lies near the viewed region).
std::string linesAlongU(const std::vector<double>& vs, double length, const std::string& profile) {
  std::ostringstream s;
  for (std::size_t i = 0; i < vs.size(); ++i)
    s << (i ? ", " : "") << R"({"profile": ")" << profile << R"(", "path": {"line": [[-0.5, )" << vs[i] << "], ["
      << length + 0.5 << ", " << vs[i] << "]]}}";
  return s.str();
}

std::string sceneJson(double domain, const std::string& profiles, const std::string& materials, const std::string& base,
                      const std::string& grooves) {
  return R"({"version": 1, "domain": {"size": [)" + std::to_string(domain) + ", " + std::to_string(domain) +
         R"(]}, "profiles": {)" + profiles + R"(}, "materials": {)" + materials + R"(}, "base": ")" + base +
         R"(", "grooves": [)" + grooves + "]}";
}

// An offscreen framebuffer with four RGBA32F colour attachments.
class FloatTarget {
 public:
  FloatTarget() {
    glCreateFramebuffers(1, &framebuffer_);
    glCreateTextures(GL_TEXTURE_2D, kAttachments, textures_);
    GLenum buffers[kAttachments];
    for (int k = 0; k < kAttachments; ++k) {
      glTextureStorage2D(textures_[k], 1, GL_RGBA32F, kSize, kSize);
      glNamedFramebufferTexture(framebuffer_, GLenum(GL_COLOR_ATTACHMENT0 + k), textures_[k], 0);
      buffers[k] = GLenum(GL_COLOR_ATTACHMENT0 + k);
    }
    glNamedFramebufferDrawBuffers(framebuffer_, kAttachments, buffers);
  }
  ~FloatTarget() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(kAttachments, textures_);
  }
  void bindAndClear() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, kSize, kSize);
    const float zero[4] = {0, 0, 0, 0};
    for (int k = 0; k < kAttachments; ++k) glClearNamedFramebufferfv(framebuffer_, GL_COLOR, k, zero);
  }
  std::vector<float> read(int attachment) const {
    std::vector<float> pixels(std::size_t(kSize) * kSize * 4);
    glGetTextureImage(textures_[attachment], 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    return pixels;
  }

 private:
  GLuint framebuffer_ = 0;
  GLuint textures_[kAttachments] = {};
};

struct OracleFigures {
  std::size_t pixels = 0, special = 0;
  std::size_t dispatchDisagreements = 0;  // pixels the shader and the CPU flag differently (§4.2)
  int maxLevels = 0;   // largest 8-bit difference
  double rmse = 0;     // linear, over channels
  double maxLinear = 0;
  double meanRadiance = 0;
  std::string worst;   // the worst pixel's inputs and values, for the failure message
  std::vector<float> radiance;  // the shader's image, RGBA
  std::vector<float> inputs[3];  // the shader's shading inputs (F, A1; A2, E.uv; E.w, L), RGBA each
  // Pixels the CPU method sends to area sampling (§6): compared apart (the shader samples them by
  // area too, in fp32), and left out of the figures above. Pixels the shader line sampled instead
  // are counted apart and left out of the special figures: noSlot (no arena slot was free) and cut
  // (llvmpipe's cap of 65,535 loop iterations per SIMD group cut the area sample short).
  std::size_t noSlot = 0, cut = 0;
  std::size_t shaderSpecial = 0;  // pixels the shader flags as special (alpha 2, 3 or 4)
  nlohmann::json statistics;      // the renderer's counts of the frame
  double specialRmse = 0;
  int specialMaxLevels = 0;
  int cutMaxLevels = 0;  // how far the cut pixels' stand-in line samples are from the CPU's area samples
  // The special-case pixels against the CPU method with area-sampled reflections untraced (a mirror
  // piece there adds mirror x environment): how much the traced beams change them.
  int untracedSpecialMaxLevels = 0;
  // Line-sampled pixels whose CPU value moves by more than 2/255 when arcs are left straight (the
  // pixels that test the shader's curved sections).
  std::size_t curvedShows = 0;
  std::size_t nearArcCentre = 0;  // line-sampled pixels near a watched arc centre (arcCentres_)
  std::size_t far = 0;            // pixels the CPU shaded from the far level (over kMaxFoundPerFootprint)
  // Those pixels against the seed's method with every primitive found (no cap): what the far level
  // stands in for.
  int farToExactMaxLevels = 0;
  double farToExactRmse = 0;
};

int quantised(double x) { return int(std::lround(255.0 * std::clamp(x, 0.0, 1.0))); }

class GroovesOracle : public test::GlTest {
 protected:
  // Area sampling compiled in (a minute or two per variant on llvmpipe): only the views that show
  // special cases turn it on; the others check that none is in view.
  bool areaSampling_ = false;
  int forceRetries_ = 0;  // GroovesOptions::forceRetries
  // GroovesOptions::retryDraws: no limit, so that every pixel a view lists is retried to the end.
  std::uint32_t retryDraws_ = std::numeric_limits<std::uint32_t>::max();
  bool areaReflections_ = true;  // GroovesOptions::areaReflections, and the CPU method's
  Vec3 environment_{0, 0, 0};  // what mirror bounces that leave the surface see (seed §7)
  // Arc centres to watch: line-sampled pixels whose footprint centre lies within 1.5 half-extents of
  // one are counted (libbake/grooves/oracle/shade.cpp nearArcCentre splits those footprints in 3 x 3).
  std::vector<std::array<float, 2>> arcCentres_;

  // Renders the baked scene from `eye` (looking at `target`) lit from `light`, shades every covered
  // pixel on the CPU from the shader's own inputs, and returns the comparison.
  OracleFigures compare(const Baked& baked, const Vec3& eye, const Vec3& target, const Vec3& light, int maxBounces,
                        const Vec3& up = {0, 0, 1}) {
    OracleFigures figures;
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({baked.file}, diagnostics, [](const std::string&) { return true; });
    EXPECT_TRUE(scene.isOk()) << scene.status().describe();
    if (!scene.isOk()) return figures;
    gl::ShaderLibrary shaders;
    GroovesOptions options;
    options.maxBounces = maxBounces;
    options.shadingInputs = true;
    options.areaSampling = areaSampling_;
    options.areaReflections = areaReflections_;
    options.forceRetries = forceRetries_;
    options.retryDraws = retryDraws_;
    GroovesRenderer renderer(options);
    const Status prepared = renderer.prepare(*scene, {0}, shaders);
    EXPECT_TRUE(prepared.isOk()) << prepared.describe();
    if (!prepared.isOk()) return figures;
    EXPECT_GT(renderer.gpuBytes(), 0u);

    const Camera camera{eye, target, up, 0.7f, 0.01f, 100.0f};
    Light lighting;
    lighting.direction = normalize(light);
    lighting.environment = environment_;
    const FrameContext frame{*scene, camera, lighting, lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), kSize, kSize};
    FloatTarget targetBuffers;
    targetBuffers.bindAndClear();
    glDisable(GL_DEPTH_TEST);
    renderer.draw(frame);
    glFinish();
    const std::vector<float> radiance = targetBuffers.read(0), in0 = targetBuffers.read(1), in1 = targetBuffers.read(2),
                             in2 = targetBuffers.read(3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    figures.radiance = radiance;
    figures.inputs[0] = in0;
    figures.inputs[1] = in1;
    figures.inputs[2] = in2;
    figures.statistics = renderer.statistics();

    // The CPU holds what the shader holds: a footprint over more primitives goes to the far level.
    grooves::SeedSettings asRuntime;
    asRuntime.foundCap = format::grooves::kMaxFoundPerFootprint;
    asRuntime.areaReflections = areaReflections_;
    const grooves::SeedShader oracle(baked.scene, baked.grid, asRuntime);
    grooves::SeedSettings untracedSettings = asRuntime;
    untracedSettings.areaReflections = false;
    const grooves::SeedShader untraced(baked.scene, baked.grid, untracedSettings);
    grooves::SeedSettings straightArcs = asRuntime;
    straightArcs.curvedSections = false;
    const grooves::SeedShader straight(baked.scene, baked.grid, straightArcs);
    const grooves::SeedShader uncapped(baked.scene, baked.grid);
    double farSquared = 0;
    double squared = 0, sum = 0, specialSquared = 0;
    for (std::size_t p = 0; p < std::size_t(kSize) * kSize; ++p) {
      const float* a = &in0[p * 4];
      const float* b = &in1[p * 4];
      const float* c = &in2[p * 4];
      if (!(c[0] > 0)) continue;  // not covered by the plane
      grooves::Footprint footprint{{a[0], a[1]}, {a[2], a[3]}, {b[0], b[1]}};
      const grooves::Vec3 toViewer{b[2], b[3], c[0]};
      grooves::Lighting light3;
      light3.toLight = {c[1], c[2], c[3]};
      light3.maxBounces = maxBounces;
      light3.environment = {environment_[0], environment_[1], environment_[2]};
      grooves::ShadeStats stats;
      const grooves::Rgb expected = oracle.shade(footprint, toViewer, light3, &stats);
      figures.far += stats.far ? 1 : 0;
      if (stats.far) {
        const grooves::Rgb exact = uncapped.shade(footprint, toViewer, light3);
        for (int k = 0; k < 3; ++k) {
          const double got = radiance[p * 4 + std::size_t(k)], want = exact[std::size_t(k)];
          farSquared += (got - want) * (got - want);
          figures.farToExactMaxLevels = std::max(figures.farToExactMaxLevels, std::abs(quantised(got) - quantised(want)));
        }
      }
      const bool shaderSpecial = radiance[p * 4 + 3] > 1.5f;
      figures.shaderSpecial += shaderSpecial ? 1 : 0;
      const float flag = radiance[p * 4 + 3];
      figures.noSlot += flag > 2.5f && flag < 3.5f ? 1 : 0;
      const bool cut = flag > 3.5f;
      figures.cut += cut ? 1 : 0;
      figures.dispatchDisagreements += shaderSpecial != stats.special ? 1 : 0;
      if (stats.special) {
        ++figures.special;
        if (cut) {
          for (int k = 0; k < 3; ++k)
            figures.cutMaxLevels = std::max(figures.cutMaxLevels, std::abs(quantised(radiance[p * 4 + std::size_t(k)]) -
                                                                           quantised(expected[std::size_t(k)])));
          continue;
        }
        const grooves::Rgb withoutBeams = untraced.shade(footprint, toViewer, light3);
        for (int k = 0; k < 3; ++k) {
          const double got = radiance[p * 4 + std::size_t(k)], want = expected[std::size_t(k)];
          specialSquared += (got - want) * (got - want);
          figures.specialMaxLevels = std::max(figures.specialMaxLevels, std::abs(quantised(got) - quantised(want)));
          figures.untracedSpecialMaxLevels =
              std::max(figures.untracedSpecialMaxLevels, std::abs(quantised(got) - quantised(withoutBeams[std::size_t(k)])));
        }
        continue;
      }
      ++figures.pixels;
      const double extent = 0.5 * (std::hypot(a[2], a[3]) + std::hypot(b[0], b[1]));
      for (const auto& c : arcCentres_)
        if (std::hypot(a[0] - c[0], a[1] - c[1]) < 1.5 * extent) {
          ++figures.nearArcCentre;
          break;
        }
      const grooves::Rgb withoutCurves = straight.shade(footprint, toViewer, light3);
      bool curvedShows = false;
      for (int k = 0; k < 3; ++k)
        curvedShows = curvedShows || std::abs(quantised(withoutCurves[std::size_t(k)]) - quantised(expected[std::size_t(k)])) > 2;
      figures.curvedShows += curvedShows ? 1 : 0;
      for (int k = 0; k < 3; ++k) {
        const double got = radiance[p * 4 + std::size_t(k)];
        const double d = got - expected[std::size_t(k)];
        squared += d * d;
        sum += expected[std::size_t(k)];
        figures.maxLinear = std::max(figures.maxLinear, std::abs(d));
        const int levels = std::abs(quantised(got) - quantised(expected[std::size_t(k)]));
        if (levels > figures.maxLevels) {
          std::ostringstream s;
          s << "F (" << a[0] << ", " << a[1] << ") A1 (" << a[2] << ", " << a[3] << ") A2 (" << b[0] << ", " << b[1]
            << ") E (" << b[2] << ", " << b[3] << ", " << c[0] << ") L (" << c[1] << ", " << c[2] << ", " << c[3]
            << "): shader " << got << " [" << radiance[p * 4 + 1] << " " << radiance[p * 4 + 2] << " " << radiance[p * 4 + 3] << "], CPU " << expected[std::size_t(k)] << " (channel " << k << ", "
            << stats.primitives << " primitives)";
          figures.worst = s.str();
        }
        figures.maxLevels = std::max(figures.maxLevels, levels);
      }
    }
    if (figures.pixels > 0) {
      figures.rmse = std::sqrt(squared / (3.0 * double(figures.pixels)));
      figures.meanRadiance = sum / (3.0 * double(figures.pixels));
    }
    if (figures.far > 0) figures.farToExactRmse = std::sqrt(farSquared / (3.0 * double(figures.far)));
    if (figures.special > 0) figures.specialRmse = std::sqrt(specialSquared / (3.0 * double(figures.special)));
    return figures;
  }

  // `special`: special-case pixels are in view; the shader's area sampling is held to the same 2/255,
  // and every one of them must have been sampled by area to the end.
  void expectWithinTwoLevels(const OracleFigures& f, const std::string& name, bool special = false) {
    RecordProperty(name + "_rmse", std::to_string(f.rmse));
    RecordProperty(name + "_max_levels", f.maxLevels);
    std::printf("[ grooves ] %s: %zu pixels (%zu special, %zu flagged differently), RMSE %.3g, max |diff| %.3g linear = "
                "%d/255, mean %.3f\n",
                name.c_str(), f.pixels, f.special, f.dispatchDisagreements, f.rmse, f.maxLinear, f.maxLevels, f.meanRadiance);
    EXPECT_GT(f.pixels, std::size_t(kSize * kSize / 8)) << "the plane covers too little of the image";
    if (special) {
      RecordProperty(name + "_special_rmse", std::to_string(f.specialRmse));
      RecordProperty(name + "_special_max_levels", f.specialMaxLevels);
      RecordProperty(name + "_special_cut", int(f.cut));
      RecordProperty(name + "_special_cut_max_levels", f.cutMaxLevels);
      std::printf("[ grooves ] %s: special-case pixels (area sampled): RMSE %.3g, max %d/255 (%d/255 from the CPU "
                  "method without area-sampled reflections); %zu cut short by the driver's loop cap (line sampled "
                  "instead, up to %d/255 off) and %zu without an arena slot (line sampled, not counted)\n",
                  name.c_str(), f.specialRmse, f.specialMaxLevels, f.untracedSpecialMaxLevels, f.cut, f.cutMaxLevels,
                  f.noSlot);
      EXPECT_GT(f.special, 0u) << "the view should show the special case";
      // Sampled by area to the end, on llvmpipe too: what its loop cap cuts short in a group of pixels
      // is shaded again alone, or by quarters (the retry passes).
      EXPECT_EQ(f.cut, 0u) << "special-case pixels cut short by the driver's loop cap";
      EXPECT_EQ(f.noSlot, 0u) << "every area-sampled pixel should find a slot of the arena";
      // The renderer's counts (what `bakeplay render` reports) are the flags' counts.
      ASSERT_TRUE(f.statistics.is_object()) << "area sampling draws report their counts";
      EXPECT_EQ(f.statistics["grooveAreaFragments"], f.shaderSpecial);
      EXPECT_EQ(f.statistics["grooveAreaLineSampledNoSlot"], f.noSlot);
      EXPECT_EQ(f.statistics["grooveAreaLineSampledLoopCap"], f.cut);
      EXPECT_LE(f.specialMaxLevels, 2);
    } else {
      EXPECT_EQ(f.special, 0u) << "no special case was meant to be in view";
    }
    EXPECT_LE(f.maxLevels, 2) << "worst pixel: " << f.worst;
    // The shader finds the same special cases (§4.2), up to boxes that touch within rounding.
    EXPECT_LE(f.dispatchDisagreements, (f.pixels + f.special) / 200);
    EXPECT_GT(f.meanRadiance, 0.01) << "an all-black image proves nothing";
  }
};

const std::string kGrey = R"("grey": {"albedo": [0.6, 0.6, 0.6], "specular": [0.3, 0.3, 0.3], "shininess": 20})";

TEST_F(GroovesOracle, SingleVeeGrooveSeenObliquely) {
  const Baked baked = bake(sceneJson(1, R"("vee": {"points": [[-0.06, 0], [0, -0.05], [0.06, 0]]})", kGrey, "grey",
                                     linesAlongU({0.5}, 1, "vee")),
                           "single_vee");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.55f, -0.35f, 0.75f}, {0.5f, 0.5f, 0.0f}, {0.2f, 0.6f, 0.7f}, 0);
  expectWithinTwoLevels(f, "single_vee");
}

TEST_F(GroovesOracle, ParallelSetFarAway) {
  std::vector<double> vs;
  for (int k = 0; k < 200; ++k) vs.push_back(0.01 + 0.02 * k);
  const Baked baked = bake(sceneJson(4, R"("fine": {"points": [[-0.006, 0], [0, -0.008], [0.006, 0]]})", kGrey, "grey",
                                     linesAlongU(vs, 4, "fine")),
                           "parallel_far");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {2.0f, -2.0f, 3.0f}, {2.0f, 2.0f, 0.0f}, {0.1f, 0.5f, 0.8f}, 0);
  expectWithinTwoLevels(f, "parallel_far");
}

// Very far away (footprints of tens of groove widths): more grooves under a footprint than the
// shader's fixed arrays hold (MAX_FOUND) are shaded from the package's far level, on the GPU as on
// the CPU, and every such fragment is counted in the frame's statistics.
// 2,000 fine grooves 0.002 apart over a 4 x 4 plate: seen from where ParallelSetFarAway looks, a
// pixel covers up to 70 of them.
std::string veryFarScene() {
  std::vector<double> vs;
  for (int k = 0; k < 2000; ++k) vs.push_back(0.001 + 0.002 * k);
  return sceneJson(4, R"("fine": {"points": [[-0.0006, 0], [0, -0.0008], [0.0006, 0]]})", kGrey, "grey",
                   linesAlongU(vs, 4, "fine"));
}

TEST_F(GroovesOracle, ParallelSetVeryFarUsesTheFarLevel) {
  const Baked baked = bake(veryFarScene(), "parallel_very_far");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {2.0f, -2.0f, 3.0f}, {2.0f, 2.0f, 0.0f}, {0.1f, 0.5f, 0.8f}, 0);
  std::printf("[ grooves ] parallel_very_far: %zu of %zu pixels from the far level; against every groove shaded "
              "(no cap): RMSE %.3g, max %d/255\n", f.far, f.pixels, f.farToExactRmse, f.farToExactMaxLevels);
  RecordProperty("parallel_very_far_to_exact_rmse", std::to_string(f.farToExactRmse));
  RecordProperty("parallel_very_far_to_exact_max_levels", f.farToExactMaxLevels);
  expectWithinTwoLevels(f, "parallel_very_far");
  EXPECT_GT(f.far, f.pixels / 4) << "the view should put many footprints over the cap";
  // What the far level stands in for: every groove shaded (the seed's method without the cap). Its
  // error is the coverage of a footprint's bounding box read from a table of about eight grooves per cell.
  EXPECT_LE(f.farToExactRmse, 1.0 / 255);
  EXPECT_LE(f.farToExactMaxLevels, 4);
  ASSERT_TRUE(f.statistics.is_object());
  // Up to footprints whose count of primitives sits on the cap within rounding of their boxes.
  const auto shaderFar = f.statistics["grooveFarFragments"].get<std::size_t>();
  EXPECT_LE(std::max(shaderFar, f.far) - std::min(shaderFar, f.far), f.pixels / 100 + 1) << "shader " << shaderFar << ", CPU " << f.far << ": " << f.statistics.dump();
  EXPECT_EQ(f.statistics["grooveTruncatedFragments"], 0);
}

// A repeating tile of 20 grooves, tiled 200 times across the plate by its texture coordinates: far
// pixels cover many periods with fewer primitives than the cap under them, and the far level counts
// every copy (the seed's method, straightening each groove at one copy, would count each once).
TEST_F(GroovesOracle, RepeatingTileFarAwayUsesTheFarLevel) {
  std::string grooves;
  for (int k = 0; k < 20; ++k)
    grooves += std::string(k ? ", " : "") + R"({"profile": "vee", "path": {"line": [[)" + std::to_string(0.025 + 0.05 * k) +
               ", 0], [" + std::to_string(0.025 + 0.05 * k) + ", 1]]}}";
  const std::string json = R"({"version": 1, "domain": {"size": [1, 1]}, "wrap": "repeat",
      "profiles": {"vee": {"points": [[-0.02, 0], [0, -0.02], [0.02, 0]]}}, "materials": {)" + kGrey +
                           R"(}, "base": "grey", "grooves": [)" + grooves + "]}";
  const Baked baked = bake(json, "repeating_tile", std::nullopt, 200);
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, -0.8f, 1.2f}, {0.5f, 0.5f, 0.0f}, {0.1f, 0.5f, 0.8f}, 0);
  std::printf("[ grooves ] repeating_tile: %zu of %zu pixels from the far level\n", f.far, f.pixels);
  expectWithinTwoLevels(f, "repeating_tile");
  EXPECT_GT(f.far, f.pixels / 2);
  ASSERT_TRUE(f.statistics.is_object());
  const auto shaderFar = f.statistics["grooveFarFragments"].get<std::size_t>();
  EXPECT_LE(std::max(shaderFar, f.far) - std::min(shaderFar, f.far), f.pixels / 100 + 1)
      << "shader " << shaderFar << ", CPU " << f.far;
}

// A version 1 package has no far level: the footprints over the shader's cap keep MAX_FOUND
// primitives and drop the rest, and the frame's statistics count every one of them.
TEST_F(GroovesOracle, VersionOnePackageCountsTruncatedFootprints) {
  Baked baked = bake(veryFarScene(), "parallel_version_one");
  ASSERT_FALSE(baked.file.empty());
  Result<glb::Package> package = glb::read(baked.file);
  ASSERT_TRUE(package.isOk());
  nlohmann::json& extension = package->materials[0]["extensions"][format::grooves::kExtension];
  extension["version"] = 1;
  extension.erase(format::grooves::kFar);
  for (const char* key : {format::grooves::kFarClasses, format::grooves::kFarTable}) {
    extension[format::grooves::kBufferViews].erase(key);
    extension[format::grooves::kCounts].erase(key);
    extension["strides"].erase(key);
  }
  baked.file = baked.file.parent_path() / "version_one.glb";
  ASSERT_TRUE(glb::write(baked.file, *package).isOk());
  const OracleFigures f = compare(baked, {2.0f, -2.0f, 3.0f}, {2.0f, 2.0f, 0.0f}, {0.1f, 0.5f, 0.8f}, 0);
  ASSERT_TRUE(f.statistics.is_object());
  EXPECT_EQ(f.statistics["grooveFarFragments"], 0);
  const auto truncated = f.statistics["grooveTruncatedFragments"].get<std::size_t>();
  EXPECT_LE(std::max(truncated, f.far) - std::min(truncated, f.far), f.pixels / 100 + 1)
      << "shader " << truncated << ", CPU over the cap " << f.far;
  EXPECT_GT(truncated, f.pixels / 4);
}

// bench/groove's dense-parallel views (bench/groove/cases.json: 1,001 V-grooves, footprint / width
// from 0.1 to 1000), drawn by the runtime's renderer through an oblique orthographic projection whose
// pixels are exactly the bench's footprints (render.h windowView), against the ray-traced reference
// (grooves/reference/reference.h): within 3x the reference's own noise floor (two renders with other seeds) at
// every footprint (half an 8-bit level where the reference has no noise). Past MAX_FOUND primitives
// under a footprint the far level shades it.
TEST_F(GroovesOracle, DenseParallelViewsWithinTheReferenceNoise) {
  const fs::path source = fs::path(BAKE_SOURCE_DIR) / "bench" / "groove";
  auto scene = grooves::readGrooveScene((source / "scenes" / "parallel-1000.json").string());
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  auto grid = grooves::buildGrooveGrid(*scene, {});
  ASSERT_TRUE(grid.isOk()) << grid.status().describe();
  auto package = grooves::buildGroovePackage(*scene, *grid);
  ASSERT_TRUE(package.isOk()) << package.status().describe();
  const fs::path file = test::freshTempDir("grooves_dense_parallel") / "dense.glb";
  ASSERT_TRUE(glb::write(file, *package).isOk());
  Diagnostics diagnostics("bakeplay", true);
  auto loaded = loadScene({file}, diagnostics, [](const std::string&) { return true; });
  ASSERT_TRUE(loaded.isOk()) << loaded.status().describe();
  gl::ShaderLibrary shaders;
  GroovesOptions options;
  options.maxBounces = 0;
  options.areaSampling = false;
  GroovesRenderer renderer(options);
  ASSERT_TRUE(renderer.prepare(*loaded, {0}, shaders).isOk());

  std::ifstream casesFile(source / "cases.json");
  const nlohmann::json cases = nlohmann::json::parse(casesFile);
  int views = 0;
  std::size_t farFragments = 0;
  double worstRatio = 0;
  for (const nlohmann::json& c : cases["cases"]) {
    if (c["name"] != "dense-parallel") continue;
    const grooves::Vec2 lower{c["window"][0][0].get<double>(), c["window"][0][1].get<double>()};
    const grooves::Vec2 upper{c["window"][1][0].get<double>(), c["window"][1][1].get<double>()};
    for (const nlohmann::json& theta : c["view"]["theta"]) {
      const double radians = 3.14159265358979323846 / 180;
      const grooves::View view = grooves::windowView(lower, upper, c["width"].get<int>(), theta.get<double>() * radians,
                                                   c["view"]["phi"].get<double>() * radians);
      grooves::Lighting lighting;
      lighting.toLight = grooves::directionFromAngles(c["light"]["theta"].get<double>() * radians,
                                                     c["light"]["phi"].get<double>() * radians);
      ASSERT_LE(view.width, kSize);
      ASSERT_LE(view.height, kSize);
      // x = u, y = v of the plane onto the view's pixels (GL row r is the view's row height - 1 - r).
      const double pixel = view.axisX.u, w = pixel * view.width, h = pixel * view.height, bottom = upper.v - h;
      Mat4 projection{};
      projection[0] = float(2 / w);
      projection[5] = float(2 / h);
      projection[12] = float(-1 - 2 * lower.u / w);
      projection[13] = float(-1 - 2 * bottom / h);
      projection[15] = 1;
      const Vec3 centre{float(lower.u + 0.5 * w), float(bottom + 0.5 * h), 0};
      const double far = 1e7;  // the camera along E, so far that every pixel sees the plane along E
      const Camera camera{{float(centre[0] + far * view.toViewer.u), float(centre[1] + far * view.toViewer.v),
                           float(far * view.toViewer.w)},
                          centre, {0, 1, 0}, 0.7f, 0.01f, 100.0f};
      const Light light{{float(lighting.toLight.u), float(lighting.toLight.v), float(lighting.toLight.w)}, {1, 1, 1}};
      const FrameContext frame{*loaded, camera, light, identity(), projection, view.width, view.height};
      FloatTarget target;
      target.bindAndClear();
      glViewport(0, 0, view.width, view.height);
      glDisable(GL_DEPTH_TEST);
      renderer.draw(frame);
      glFinish();
      const std::vector<float> rendered = target.read(0);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      farFragments += renderer.statistics()["grooveFarFragments"].get<std::size_t>();

      grooves::ReferenceSettings reference;
      reference.samplesPerPixel = 256;
      const Image truth = grooves::renderReference(*scene, view, lighting, reference);
      reference.seed = 2;
      const Image second = grooves::renderReference(*scene, view, lighting, reference);
      double squared = 0, floorSquared = 0;
      for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x)
          for (int k = 0; k < 3; ++k) {
            const double got = rendered[(std::size_t(view.height - 1 - y) * kSize + std::size_t(x)) * 4 + std::size_t(k)];
            squared += (got - truth.at(x, y, k)) * (got - truth.at(x, y, k));
            floorSquared += (second.at(x, y, k) - truth.at(x, y, k)) * (second.at(x, y, k) - truth.at(x, y, k));
          }
      const double values = 3.0 * view.width * view.height;
      const double rmse = std::sqrt(squared / values), floor = std::sqrt(floorSquared / values);
      // A footprint inside one facet gives every reference sample the same value: no noise floor;
      // there the bound is half an 8-bit level of the output.
      const double ratio = floor > 0 ? rmse / floor : 0;
      worstRatio = std::max(worstRatio, ratio);
      const double footprintOverWidth = pixel / (2 * scene->wmax);
      std::printf("[ grooves ] dense-parallel footprint/width %7.1f, theta %2.0f: %2dx%d px, RMSE %.3g, noise floor %.3g, "
                  "ratio %.2f\n",
                  footprintOverWidth, theta.get<double>(), view.width, view.height, rmse, floor, ratio);
      RecordProperty("dense_parallel_" + std::to_string(int(std::lround(footprintOverWidth))) + "_" +
                         std::to_string(theta.get<int>()) + "_ratio",
                     std::to_string(ratio));
      EXPECT_LE(rmse, floor > 0 ? 3 * floor : 0.5 / 255) << "footprint/width " << footprintOverWidth << ", theta " << theta;
      ++views;
    }
  }
  std::printf("[ grooves ] dense-parallel: %d views, worst RMSE / noise floor %.2f, %zu fragments from the far level\n",
              views, worstRatio, farFragments);
  EXPECT_EQ(views, 10);
  EXPECT_GT(farFragments, 0u) << "the widest footprints should be over the shader's cap";
}

TEST_F(GroovesOracle, RidgesCastShadows) {
  const Baked baked = bake(sceneJson(1, R"("ridge": {"points": [[-0.03, 0], [0, 0.05], [0.03, 0]]})", kGrey, "grey",
                                     linesAlongU({0.3, 0.5, 0.7}, 1, "ridge")),
                           "ridges");
  ASSERT_FALSE(baked.file.empty());
  // A low light across the ridges: each throws a long shadow on the base beside it.
  const OracleFigures f = compare(baked, {0.45f, -0.3f, 0.9f}, {0.5f, 0.5f, 0.0f}, {0.05f, 0.95f, 0.3f}, 0);
  expectWithinTwoLevels(f, "ridges");
}

TEST_F(GroovesOracle, MirrorGrooveWithBounces) {
  const std::string materials =
      kGrey + R"(, "mirror": {"albedo": [0.1, 0.1, 0.1], "specular": [0, 0, 0], "shininess": 1, "mirror": [0.9, 0.8, 0.7]})";
  const Baked baked = bake(sceneJson(1, R"("deep": {"points": [[-0.05, 0], [0, -0.09], [0.05, 0]]})", materials, "grey",
                                     R"({"profile": "deep", "material": "mirror", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}})"),
                           "mirror");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, -0.2f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.1f, -0.4f, 0.9f}, 3);
  expectWithinTwoLevels(f, "mirror");
  // Under a constant environment (seed §7's light from outside the grooves): the shader adds it where
  // the CPU method does, and it shows.
  environment_ = {0.25f, 0.45f, 0.65f};
  const OracleFigures lit = compare(baked, {0.5f, -0.2f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.1f, -0.4f, 0.9f}, 3);
  expectWithinTwoLevels(lit, "mirror_environment");
  EXPECT_GT(lit.meanRadiance, f.meanRadiance + 0.01) << "the environment does not show";
}

// The tangent frame: the plane turned upright by its node (90 degrees about x), seen by a camera and
// lit by a light turned with it, must give the same image and still match the CPU method.
TEST_F(GroovesOracle, TangentFrameFollowsTheMesh) {
  const std::string json = sceneJson(1, R"("vee": {"points": [[-0.06, 0], [0, -0.05], [0.06, 0]]})", kGrey, "grey",
                                     linesAlongU({0.5}, 1, "vee"));
  glb::Node upright;
  upright.mesh = 0;
  upright.rotation = {std::sqrt(0.5), 0, 0, std::sqrt(0.5)};  // (x, y, z) -> (x, -z, y)
  const Baked flat = bake(json, "frame_flat"), turned = bake(json, "frame_turned", upright);
  ASSERT_FALSE(flat.file.empty());
  ASSERT_FALSE(turned.file.empty());
  auto turn = [](const Vec3& p) { return Vec3{p[0], -p[2], p[1]}; };
  const Vec3 eye{0.55f, -0.35f, 0.75f}, target{0.5f, 0.5f, 0.0f}, light{0.2f, 0.6f, 0.7f};
  const OracleFigures a = compare(flat, eye, target, light, 0);
  const OracleFigures b = compare(turned, turn(eye), turn(target), turn(light), 0, turn({0, 0, 1}));
  expectWithinTwoLevels(b, "frame_turned");
  ASSERT_EQ(a.radiance.size(), b.radiance.size());
  int worst = 0;
  for (std::size_t i = 0; i < a.radiance.size(); ++i)
    worst = std::max(worst, std::abs(quantised(a.radiance[i]) - quantised(b.radiance[i])));
  EXPECT_LE(worst, 2) << "the turned plane looks different";
}

// Arcs (a closed circle, four G1 arcs) with a scale perturbation, in a repeating domain where the
// circle crosses the edge: the shader's arc foot points, perturbation (its value and its rate along
// the path at the foot point) and nearest-copy choice.
TEST_F(GroovesOracle, PerturbedCircleAcrossARepeatingEdge) {
  const std::string json = R"({"version": 1, "domain": {"size": [1, 1]}, "wrap": "repeat",
    "profiles": {"vee": {"points": [[-0.04, 0], [0, -0.03], [0.04, 0]]}},
    "materials": {)" + kGrey + R"(}, "base": "grey",
    "grooves": [{"profile": "vee", "perturbation": {"kind": "scale", "amplitude": 0.4, "wavelength": 0.25},
                 "path": {"arc": {"centre": [0.85, 0.5], "radius": 0.3, "start": 0, "end": 360}}}]})";
  const Baked baked = bake(json, "circle_wrap");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, -0.4f, 0.9f}, {0.5f, 0.5f, 0.0f}, {-0.3f, 0.4f, 0.8f}, 0);
  expectWithinTwoLevels(f, "circle_wrap");
}

// Two rings seen at about 45 degrees: one whose radius equals its half-width (the inner rim closes at
// the centre) and one of 2.5 half-widths. Their curvature shows over the view's travel below the
// surface, so both the CPU and the shader shade them on curved sections (subdivided facets, points
// moved along their circles, turned normals); the count of pixels that straight arcs would change
// says the view tests that path.
TEST_F(GroovesOracle, TightRingsOnCurvedSections) {
  const std::string json = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"vee": {"points": [[-0.08, 0], [0, -0.05], [0.08, 0]]}},
    "materials": {)" + kGrey + R"(}, "base": "grey",
    "grooves": [{"profile": "vee", "path": {"arc": {"centre": [0.3, 0.5], "radius": 0.08, "start": 0, "end": 360}}},
                {"profile": "vee", "path": {"arc": {"centre": [0.7, 0.5], "radius": 0.2, "start": 0, "end": 360}}}]})";
  areaSampling_ = true;  // the small ring's band overlaps itself at its centre: a special case
  const Baked baked = bake(json, "tight_rings");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, -0.3f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.6f, 0.3f, 0.7f}, 0);
  std::printf("[ grooves ] tight_rings: %zu pixels change by more than 2/255 with straight arcs\n", f.curvedShows);
  RecordProperty("tight_rings_curved_pixels", int(f.curvedShows));
  EXPECT_GT(f.curvedShows, std::size_t(50)) << "the view should show the rings' curvature";
  expectWithinTwoLevels(f, "tight_rings", true);
}

// A ring whose radius equals its half-width (no special case: its band only touches itself at the
// centre), seen at about 45 degrees: the footprints around the centre are split in 3 x 3 (shade.cpp
// nearArcCentre) and the others' span edges turn and bend with the circle, in the shader as on the CPU.
TEST_F(GroovesOracle, RingCentreOnSubFootprints) {
  const std::string json = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"vee": {"points": [[-0.1, 0], [0, -0.06], [0.1, 0]]}},
    "materials": {)" + kGrey + R"(}, "base": "grey",
    "grooves": [{"profile": "vee", "path": {"arc": {"centre": [0.5, 0.5], "radius": 0.1, "start": 0, "end": 360}}}]})";
  const Baked baked = bake(json, "ring_centre");
  ASSERT_FALSE(baked.file.empty());
  arcCentres_ = {{0.5f, 0.5f}};
  const OracleFigures f = compare(baked, {0.5f, -0.3f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.6f, 0.3f, 0.7f}, 0);
  std::printf("[ grooves ] ring_centre: %zu pixels near the centre (split), %zu change by more than 2/255 with "
              "straight arcs\n",
              f.nearArcCentre, f.curvedShows);
  RecordProperty("ring_centre_split_pixels", int(f.nearArcCentre));
  EXPECT_GT(f.nearArcCentre, std::size_t(2)) << "the view should hold footprints around the ring's centre";
  EXPECT_GT(f.curvedShows, std::size_t(50)) << "the view should show the ring's curvature";
  expectWithinTwoLevels(f, "ring_centre");
}

// A box groove whose offset wanders (curvature radius about 0.08, near its own width), lit across it:
// the shadows its walls cast on the floor follow the bend of the path to second order on both sides
// (gSectionAccelB and the light's travel base in the shader).
TEST_F(GroovesOracle, WanderingBoxGrooveShadows) {
  const std::string json = R"({"version": 1, "domain": {"size": [1, 1]},
    "profiles": {"box": {"points": [[-0.04, 0], [-0.04, -0.03], [0.04, -0.03], [0.04, 0]]}},
    "materials": {)" + kGrey + R"(}, "base": "grey",
    "grooves": [{"profile": "box", "perturbation": {"kind": "offset", "amplitude": 0.02, "wavelength": 0.25},
                 "path": {"line": [[0.1, 0.5], [0.9, 0.5]]}}]})";
  areaSampling_ = true;  // its open ends are in view too
  const Baked baked = bake(json, "wandering_box");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, 0.3f, 0.9f}, {0.5f, 0.5f, 0.0f}, {-0.35f, 0.5f, 0.8f}, 0);
  expectWithinTwoLevels(f, "wandering_box", true);
}

// Stiff inputs: a view about 75 degrees from the normal and a light about 85 degrees from it (long
// shadows, the query box stretched along the light), over ridges and cuts side by side. (A light
// below the horizon leaves the seed's method all black: the endless base hides everything.)
TEST_F(GroovesOracle, GrazingViewAndLight) {
  const std::string profiles = R"("cut": {"points": [[-0.05, 0], [-0.02, -0.06], [0.02, -0.06], [0.05, 0]]},
                                  "ridge": {"points": [[-0.03, 0], [0, 0.04], [0.03, 0]]})";
  const Baked baked = bake(sceneJson(1, profiles, kGrey, "grey", linesAlongU({0.35, 0.65}, 1, "cut") + ", " +
                                                                     linesAlongU({0.5}, 1, "ridge")),
                           "grazing");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.5f, -0.9f, 0.25f}, {0.5f, 0.55f, 0.0f}, {0.0f, -1.0f, 0.08f}, 0);
  expectWithinTwoLevels(f, "grazing");
}

// A crossing (§4.2, a special case): away from the record's box the shader must match the CPU method
// as elsewhere, and inside it both sample the footprint by area (§6).
TEST_F(GroovesOracle, CrossingSampledByAreaAsOnTheCpu) {
  areaSampling_ = true;
  const std::string vee = R"("vee": {"points": [[-0.05, 0], [0, -0.04], [0.05, 0]]})";
  const Baked baked = bake(sceneJson(1, vee, kGrey, "grey",
                                     R"({"profile": "vee", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}}, )"
                                     R"({"profile": "vee", "path": {"line": [[0.5, -0.5], [0.5, 1.5]]}})"),
                           "crossing");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.6f, -0.3f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.8f}, 0);
  expectWithinTwoLevels(f, "crossing", true);
}

// A mirror base under an environment (seed §7's light from outside) over a crossing: the shader adds
// the base's reflection of the environment in plain footprints, in the sections' flat parts and in
// the area-sampled pieces as the CPU method does.
TEST_F(GroovesOracle, MirrorBaseReflectsTheEnvironmentAsOnTheCpu) {
  areaSampling_ = true;
  environment_ = {0.4f, 0.5f, 0.6f};
  const std::string materials =
      R"("polished": {"albedo": [0.3, 0.3, 0.3], "specular": [0.2, 0.2, 0.2], "shininess": 20, "mirror": [0.6, 0.5, 0.4]}, )" + kGrey;
  const std::string vee = R"("vee": {"points": [[-0.05, 0], [0, -0.04], [0.05, 0]]})";
  const Baked baked = bake(sceneJson(1, vee, materials, "polished",
                                     R"({"profile": "vee", "material": "grey", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}}, )"
                                     R"({"profile": "vee", "material": "grey", "path": {"line": [[0.5, -0.5], [0.5, 1.5]]}})"),
                           "mirror_base_environment");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.6f, -0.3f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(f, "mirror_base_environment", true);
}

// Mirror grooves crossing (seed 000 §7 in §6's special cases), three bounces under an environment:
// the shader traces the beams of the mirror pieces it samples by area as the CPU method does, and
// they show (the CPU method without them is far off).
TEST_F(GroovesOracle, MirrorCrossingTracesBouncesAsOnTheCpu) {
  areaSampling_ = true;
  environment_ = {0.4f, 0.5f, 0.6f};
  const std::string materials =
      R"("polished": {"albedo": [0.1, 0.1, 0.1], "specular": [0.2, 0.2, 0.2], "shininess": 20, "mirror": [0.9, 0.8, 0.7]}, )" + kGrey;
  const std::string deep = R"("deep": {"points": [[-0.05, 0], [0, -0.07], [0.05, 0]]})";
  const Baked baked = bake(sceneJson(1, deep, materials, "grey",
                                     R"({"profile": "deep", "material": "polished", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}}, )"
                                     R"({"profile": "deep", "material": "polished", "path": {"line": [[0.5, -0.5], [0.5, 1.5]]}})"),
                           "mirror_crossing_bounces");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.62f, 0.25f, 0.45f}, {0.5f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.8f}, 3);
  expectWithinTwoLevels(f, "mirror_crossing_bounces", true);
  EXPECT_GE(f.untracedSpecialMaxLevels, 8) << "the view should show inter-reflections in the special cases";
  // The renderer's cheaper model (bakeplay --groove-reflections environment) is the CPU method's
  // without area-sampled reflections.
  areaReflections_ = false;
  const OracleFigures untraced = compare(baked, {0.62f, 0.25f, 0.45f}, {0.5f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.8f}, 3);
  expectWithinTwoLevels(untraced, "mirror_crossing_environment_only", true);
}

// The example scenes of pipelines/grooves, as the examples bake them: the record (no special case
// but its two ends) and the tiles (the joints between the T-junctions and ends). The tiles'
// T-junctions are the costliest area samples of the examples: every one must stay inside llvmpipe's
// loop cap.
std::string exampleScene(const std::string& name) {
  std::ifstream in(std::string(BAKE_SOURCE_DIR) + "/pipelines/grooves/" + name);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}

TEST_F(GroovesOracle, ExampleRecord) {
  areaSampling_ = true;
  const Baked baked = bake(exampleScene("record.json"), "example_record");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.2f, -0.05f, 0.3f}, {0.15f, 0.15f, 0.0f}, {-0.3f, 0.6f, 0.7f}, 0);
  expectWithinTwoLevels(f, "example_record", true);  // the spiral's outer end is in view
}

TEST_F(GroovesOracle, ExampleTiles) {
  areaSampling_ = true;
  const Baked baked = bake(exampleScene("tiles.json"), "example_tiles");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.7f, -0.2f, 0.6f}, {0.6f, 0.4f, 0.0f}, {0.3f, 0.5f, 0.8f}, 0);
  expectWithinTwoLevels(f, "example_tiles", true);
}

// The engraved plate: a corner of the border with the start of a diagonal V-cut (corner, crossing
// and end records), brass and its cut mirroring one bounce, traced in the special cases too.
TEST_F(GroovesOracle, ExamplePlate) {
  areaSampling_ = true;
  const Baked baked = bake(exampleScene("plate.json"), "example_plate");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(f, "example_plate", true);
  EXPECT_GE(f.untracedSpecialMaxLevels, 6) << "the brass's reflections in the special cases should show";
}

// The plate where the straight scratch (a V with pile-up ridges) crosses the ring: special cases with
// both layers, which the shader overlays in one pass and the CPU builds apart and intersects. Up to
// 18 primitives meet some of these footprints. On llvmpipe, 23 of the 1,084 special-case pixels
// overrun its loop cap in the first pass, and one of them again when shaded alone: the retry passes
// (shaders/grooves/area_retry.glsl) shade them alone, then that one by quarters, and every one is
// sampled by area to the end.
TEST_F(GroovesOracle, ExamplePlateScratchOverRing) {
  areaSampling_ = true;
  const Baked baked = bake(exampleScene("plate.json"), "example_plate_scratch");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.19f, 0.12f, 0.1f}, {0.138f, 0.182f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(f, "example_plate_scratch", true);
  std::printf("[ grooves ] example_plate_scratch: %s fragments shaded again in %s retry passes\n",
              f.statistics["grooveAreaRetried"].dump().c_str(), f.statistics["grooveAreaRetryPasses"].dump().c_str());
}

// The retry passes on any driver: every area sample of the plate's view is taken as cut short in the
// first pass, again when shaded alone and again when shaded beam by beam, so each special-case pixel
// ends up sampled beam by beam by quarters of its footprint, the shares summed across passes. The
// image must still match the CPU. Then the same without traced beams.
TEST_F(GroovesOracle, RetryPassesBeamByBeamByQuartersMatchTheCpu) {
  areaSampling_ = true;
  forceRetries_ = 3;
  const Baked baked = bake(exampleScene("plate.json"), "example_plate_retries");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(f, "example_plate_retries", true);
  ASSERT_TRUE(f.statistics.is_object());
  const auto fragments = f.statistics["grooveAreaFragments"].get<std::uint32_t>();
  EXPECT_GT(fragments, 16u);
  // Deferred three times each: from the first pass, from its whole-footprint retry, and from its
  // beam-by-beam retry.
  EXPECT_EQ(f.statistics["grooveAreaRetried"].get<std::uint32_t>(), 3 * fragments);
  // One retry pass per pixel for the whole footprint, then one per beam (6), then one per beam for
  // each quarter (24), then the pass that sums them.
  EXPECT_EQ(f.statistics["grooveAreaRetryPasses"].get<std::uint32_t>(), 32 * fragments);
  // Without traced beams (the renderer's default), the second retry takes the footprint's quarters
  // whole: cut short in the first pass and when shaded alone, each pixel is shaded by quarters, then
  // summed.
  areaReflections_ = false;
  forceRetries_ = 2;
  const OracleFigures quarters = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(quarters, "example_plate_retries_environment", true);
  ASSERT_TRUE(quarters.statistics.is_object());
  EXPECT_EQ(quarters.statistics["grooveAreaRetried"].get<std::uint32_t>(), 2 * fragments);
  EXPECT_EQ(quarters.statistics["grooveAreaRetryPasses"].get<std::uint32_t>(), 6 * fragments);
}

// Shaded again by parts, only the children of a node cut short are drawn: with node 0 of every level
// but the deepest taken as cut short, each special-case pixel sums three quarters, three sixteenths
// and four sixty-fourths, and must still match the CPU, with and without traced beams.
TEST_F(GroovesOracle, RetryPassesByPartsRefineOnlyNodesCutShort) {
  areaSampling_ = true;
  forceRetries_ = 4;
  const Baked baked = bake(exampleScene("plate.json"), "example_plate_retries");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(f, "example_plate_retries_nodes", true);
  ASSERT_TRUE(f.statistics.is_object());
  const auto fragments = f.statistics["grooveAreaFragments"].get<std::uint32_t>();
  EXPECT_GT(fragments, 16u);
  EXPECT_EQ(f.statistics["grooveAreaLineSampledLoopCap"].get<std::uint32_t>(), 0u);
  // Deferred from the first pass, the whole retry, and levels 0, 1 and 2 by parts.
  EXPECT_EQ(f.statistics["grooveAreaRetried"].get<std::uint32_t>(), 5 * fragments);
  // The whole retry; by parts, 6 beams of the footprint, then of 4 quarters, of the 4 children of
  // quarter 0, of the 4 children of that sixteenth; the sum.
  EXPECT_EQ(f.statistics["grooveAreaRetryPasses"].get<std::uint32_t>(), (1 + 6 * (1 + 4 + 4 + 4) + 1) * fragments);
  areaReflections_ = false;
  const OracleFigures whole = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  expectWithinTwoLevels(whole, "example_plate_retries_nodes_environment", true);
  ASSERT_TRUE(whole.statistics.is_object());
  EXPECT_EQ(whole.statistics["grooveAreaLineSampledLoopCap"].get<std::uint32_t>(), 0u);
  // From quarters: deferred from the first pass, the whole retry, levels 1 and 2.
  EXPECT_EQ(whole.statistics["grooveAreaRetried"].get<std::uint32_t>(), 4 * fragments);
  EXPECT_EQ(whole.statistics["grooveAreaRetryPasses"].get<std::uint32_t>(), (1 + 4 + 4 + 4 + 1) * fragments);
}

// The frame's retry draws are bounded (GroovesOptions::retryDraws): with every first-pass area sample
// taken as cut short and 20 retry draws, the first 20 listed pixels are shaded again alone and sampled
// by area to the end; the rest keep their line samples, counted as cut short and unfinished.
TEST_F(GroovesOracle, RetryDrawsStopAtTheBudget) {
  areaSampling_ = true;
  forceRetries_ = 1;
  retryDraws_ = 20;
  const Baked baked = bake(exampleScene("plate.json"), "example_plate_retries");
  ASSERT_FALSE(baked.file.empty());
  const OracleFigures f = compare(baked, {0.11f, -0.02f, 0.1f}, {0.05f, 0.05f, 0.0f}, {0.3f, 0.5f, 0.8f}, 1);
  ASSERT_TRUE(f.statistics.is_object());
  const auto fragments = f.statistics["grooveAreaFragments"].get<std::uint32_t>();
  ASSERT_GT(fragments, 20u);
  EXPECT_EQ(f.statistics["grooveAreaRetryPasses"].get<std::uint32_t>(), 20u);
  EXPECT_EQ(f.statistics["grooveAreaRetriesUnfinished"].get<std::uint32_t>(), fragments - 20);
  EXPECT_EQ(f.statistics["grooveAreaLineSampledLoopCap"].get<std::uint32_t>(), fragments - 20);
  EXPECT_EQ(f.cut, std::size_t(fragments - 20)) << "the pixels flagged as line sampled";
  EXPECT_EQ(f.specialMaxLevels, 0) << "the 20 retried pixels, sampled by area, against the CPU";
}

// The per-frame counts (far level, truncated, classes dropped) are the first pass's: a star of six
// V-cuts crossing at one point, whose special-case footprints meet grooves in more directions than
// the shader keeps, counts the same whether every special-case pixel is shaded again or not.
TEST_F(GroovesOracle, RetryPassesDoNotCountFragmentsAgain) {
  areaSampling_ = true;
  std::string grooves;
  for (int k = 0; k < 6; ++k) {
    const double angle = k * std::acos(-1.0) / 6, c = 0.4 * std::cos(angle), s = 0.4 * std::sin(angle);
    grooves += std::string(k > 0 ? ", " : "") + R"({"profile": "vee", "path": {"line": [[)" + std::to_string(0.5 - c) +
               ", " + std::to_string(0.5 - s) + "], [" + std::to_string(0.5 + c) + ", " + std::to_string(0.5 + s) + "]]}}";
  }
  const std::string vee = R"("vee": {"points": [[-0.02, 0], [0, -0.015], [0.02, 0]]})";
  const Baked baked = bake(sceneJson(1, vee, kGrey, "grey", grooves), "star_counts");
  ASSERT_FALSE(baked.file.empty());
  const auto counts = [&](int force) {
    forceRetries_ = force;
    return compare(baked, {0.5f, 0.2f, 0.5f}, {0.5f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.8f}, 0).statistics;
  };
  const nlohmann::json plain = counts(0), retried = counts(1);
  ASSERT_TRUE(plain.is_object() && retried.is_object());
  EXPECT_GT(retried["grooveAreaRetried"].get<std::uint32_t>(), 0u) << retried.dump();
  for (const char* count : {"grooveFarFragments", "grooveTruncatedFragments", "grooveClassesDroppedFragments"})
    EXPECT_EQ(retried[count], plain[count]) << count;
  EXPECT_GT(plain["grooveClassesDroppedFragments"].get<std::uint32_t>(), 0u) << plain.dump();
}

// ---------------------------------------------------------------------------------------------
// The whole bakeplay path: the registry picks the grooves renderer, the frame goes through the
// runtime's offscreen target and PNG encoding (sRGB, as `bakeplay render` writes it), and must match
// its golden picture.

TEST_F(GroovesOracle, BakeplayFrameMatchesTheGoldenImage) {
  const std::string materials =
      kGrey + R"(, "mirror": {"albedo": [0.1, 0.1, 0.1], "specular": [0, 0, 0], "shininess": 1, "mirror": [0.9, 0.8, 0.7]})";
  const std::string profiles = R"("vee": {"points": [[-0.06, 0], [0, -0.05], [0.06, 0]]},
                                  "ridge": {"points": [[-0.03, 0], [0, 0.05], [0.03, 0]]})";
  const std::string grooves = linesAlongU({0.25}, 1, "vee") + ", " + linesAlongU({0.5}, 1, "ridge") +
                              R"(, {"profile": "vee", "material": "mirror", "path": {"line": [[-0.5, 0.75], [1.5, 0.75]]}})";
  const Baked baked = bake(sceneJson(1, profiles, materials, "grey", grooves), "golden");
  ASSERT_FALSE(baked.file.empty());
  Diagnostics diagnostics("bakeplay", true);
  auto scene = loadScene({baked.file}, diagnostics, [](const std::string&) { return true; });
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  gl::ShaderLibrary shaders;
  auto renderer = SceneRenderer::create(*scene, RendererRegistry::builtIn(), shaders);
  ASSERT_TRUE(renderer.isOk()) << renderer.status().describe();
  ASSERT_EQ(renderer->techniques(), std::vector<std::string>{format::grooves::kExtension});
  auto target = OffscreenTarget::create(kSize, kSize);
  ASSERT_TRUE(target.isOk()) << target.status().describe();
  const Camera camera{{0.5f, -0.4f, 0.9f}, {0.5f, 0.5f, 0.0f}, {0, 0, 1}, 0.7f, 0.01f, 100.0f};
  Light light;
  light.direction = normalize(Vec3{0.1f, 0.6f, 0.6f});
  const FrameContext frame{*scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                           perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), kSize, kSize};
  target->bind();
  renderer->drawFrame(frame);
  const Image image = encodeSrgb(target->readLinearRgba());
  EXPECT_TRUE(test::matchesGoldenImage(image, "runtime/grooves-vee-ridge-mirror.v1.png"));
}

// Two packages whose special cases need scratch slots of different sizes (a 3-point and a 4-point
// profile) in one frame: each slot layout gets an arena of its own. Cut from one arena, slots of two
// sizes overlap, and two rasteriser threads shading the two packages at once wrote into each other's
// slots (the grooves scene's traced render differed from run to run). Two packages of one layout
// share an arena.
TEST_F(GroovesOracle, EverySlotLayoutHasAnArenaOfItsOwn) {
  const auto crossing = [](const std::string& profile, const std::string& name) {
    return bake(sceneJson(1, profile, kGrey, "grey",
                          R"({"profile": "p", "path": {"line": [[-0.5, 0.5], [1.5, 0.5]]}}, )"
                          R"({"profile": "p", "path": {"line": [[0.5, -0.5], [0.5, 1.5]]}})"),
                name);
  };
  const Baked vee = crossing(R"("p": {"points": [[-0.05, 0], [0, -0.04], [0.05, 0]]})", "layout_vee");
  const Baked vee2 = crossing(R"("p": {"points": [[-0.04, 0], [0, -0.03], [0.04, 0]]})", "layout_vee2");
  const Baked box = crossing(R"("p": {"points": [[-0.05, 0], [-0.05, -0.03], [0.05, -0.03], [0.05, 0]]})", "layout_box");
  ASSERT_FALSE(vee.file.empty() || vee2.file.empty() || box.file.empty());
  const auto arenas = [](const Baked& a, const Baked& b) -> nlohmann::json {
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({a.file, b.file}, diagnostics, [](const std::string&) { return true; });
    EXPECT_TRUE(scene.isOk()) << scene.status().describe();
    if (!scene.isOk() || scene->instances.size() != 2) return {};
    gl::ShaderLibrary shaders;
    GroovesRenderer renderer;  // area sampling on, as by default
    const Status prepared = renderer.prepare(*scene, {0, 1}, shaders);
    EXPECT_TRUE(prepared.isOk()) << prepared.describe();
    const Camera camera{{0.6f, -0.3f, 0.8f}, {0.5f, 0.5f, 0.0f}, {0, 0, 1}, 0.7f, 0.01f, 100.0f};
    Light light;
    light.direction = normalize(Vec3{0.3f, 0.5f, 0.8f});
    const FrameContext frame{*scene, camera, light, lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, 1.0f, camera.znear, camera.zfar), kSize, kSize};
    FloatTarget target;
    target.bindAndClear();
    renderer.draw(frame);
    glFinish();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return renderer.statistics();
  };
  const nlohmann::json two = arenas(vee, box), one = arenas(vee, vee2);
  ASSERT_TRUE(two.is_object() && one.is_object());
  EXPECT_EQ(two["grooveAreaArenas"], 2) << two.dump();
  EXPECT_EQ(one["grooveAreaArenas"], 1) << one.dump();
  EXPECT_GT(two["grooveAreaFragments"].get<std::uint32_t>(), 0u) << two.dump();
  EXPECT_EQ(two["grooveAreaLineSampledNoSlot"], 0) << two.dump();
}

// ---------------------------------------------------------------------------------------------
// Registration and package checks

// Grooves on a curved mesh (groovebake --apply-to; seed 000 Figs. 1, 11, 13): the fluted column of
// pipelines/grooves on bakeshape's column, its tangent frames computed by the library. Two checks:
// the shader against the CPU method from the shader's own inputs (within 2/255, as on the plane), and
// the shader's inputs against the CPU's own path through the same mesh: a ray from the camera through
// each pixel centre hits the triangles (double precision, nothing shared with the renderer), the hit's
// barycentrics give F, the normal and the TANGENT frame, E and L; the footprint edges are the change
// of F over one pixel on the hit triangle's plane. The CPU method shaded from those inputs must match
// the shader's image too.
struct RayHit {
  double t = 0;
  std::size_t triangle = 0;
  double b[3] = {0, 0, 0};  // barycentrics
};

std::optional<RayHit> castRay(const TriangleMesh& mesh, const Vec3d& origin, const Vec3d& direction) {
  std::optional<RayHit> best;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& tri = mesh.triangles[i];
    auto at = [&](int k) { const Vec3f& p = mesh.positions[tri[std::size_t(k)]]; return Vec3d{p[0], p[1], p[2]}; };
    const Vec3d a = at(0), e1 = vec::sub(at(1), a), e2 = vec::sub(at(2), a);
    const Vec3d p = vec::cross(direction, e2);
    const double det = vec::dot(e1, p);
    if (std::abs(det) < 1e-18) continue;
    const Vec3d s = vec::sub(origin, a);
    const double u = vec::dot(s, p) / det;
    if (u < 0 || u > 1) continue;
    const Vec3d q = vec::cross(s, e1);
    const double v = vec::dot(direction, q) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = vec::dot(e2, q) / det;
    if (t <= 1e-9 || (best && t >= best->t)) continue;
    best = RayHit{t, i, {1 - u - v, u, v}};
  }
  return best;
}

// Barycentrics of `point` in the plane of triangle i (outside the triangle too).
std::array<double, 3> planeBarycentrics(const TriangleMesh& mesh, std::size_t i, const Vec3d& point) {
  const Triangle& tri = mesh.triangles[i];
  auto at = [&](int k) { const Vec3f& p = mesh.positions[tri[std::size_t(k)]]; return Vec3d{p[0], p[1], p[2]}; };
  const Vec3d a = at(0), e1 = vec::sub(at(1), a), e2 = vec::sub(at(2), a), d = vec::sub(point, a);
  const double d11 = vec::dot(e1, e1), d12 = vec::dot(e1, e2), d22 = vec::dot(e2, e2);
  const double d1 = vec::dot(d, e1), d2 = vec::dot(d, e2), den = d11 * d22 - d12 * d12;
  const double u = (d22 * d1 - d12 * d2) / den, v = (d11 * d2 - d12 * d1) / den;
  return {1 - u - v, u, v};
}

struct CameraRays {
  Vec3d eye, forward, right, up;
  double halfHeight;  // tan(yfov / 2)
  Vec3d through(double x, double y) const {  // window coordinates, y up, pixel centres at +0.5
    const double nx = 2 * x / kSize - 1, ny = 2 * y / kSize - 1;
    return vec::unit(vec::add(forward, vec::add(vec::scale(right, nx * halfHeight), vec::scale(up, ny * halfHeight))), forward);
  }
};

TEST_F(GroovesOracle, FlutedColumnMatchesTheCpuThroughTheSameMesh) {
  const grooves::GrooveSurface surface = columnSurface();
  ASSERT_FALSE(surface.tangents.empty());
  const Baked baked = bake(exampleScene("flutes.json"), "column", std::nullopt, 1, &surface);
  ASSERT_FALSE(baked.file.empty());
  const Vec3 eye{0.32f, 0.05f, 0.78f}, target{0.13f, 0, 0.32f}, light{0.5f, 0.6f, 0.8f};
  const OracleFigures f = compare(baked, eye, target, light, 0, {0, 1, 0});
  expectWithinTwoLevels(f, "column");

  // The CPU's own path through the mesh.
  const TriangleMesh& mesh = surface.mesh;
  CameraRays rays;
  rays.eye = {eye[0], eye[1], eye[2]};
  rays.forward = vec::unit(vec::sub({target[0], target[1], target[2]}, rays.eye), {0, 0, -1});
  rays.right = vec::unit(vec::cross(rays.forward, {0, 1, 0}), {1, 0, 0});
  rays.up = vec::cross(rays.right, rays.forward);
  rays.halfHeight = std::tan(0.35);
  const Vec3d toLight = vec::unit({light[0], light[1], light[2]}, {0, 0, 1});
  const double domain[2] = {baked.scene.domain[0], baked.scene.domain[1]};
  auto textureAt = [&](std::size_t i, const std::array<double, 3>& b) {
    std::array<double, 2> uv{0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) uv[std::size_t(c)] += b[std::size_t(k)] * mesh.texcoords[mesh.triangles[i][std::size_t(k)]][std::size_t(c)];
    return std::array<double, 2>{uv[0] * domain[0], uv[1] * domain[1]};
  };
  // F where the ray through window point (x, y) meets triangle i's plane.
  auto textureOnPlane = [&](std::size_t i, double x, double y) {
    const Triangle& tri = mesh.triangles[i];
    const Vec3f& a = mesh.positions[tri[0]];
    const Vec3d d = rays.through(x, y), n = vec::cross(vec::sub({mesh.positions[tri[1]][0], mesh.positions[tri[1]][1], mesh.positions[tri[1]][2]}, {a[0], a[1], a[2]}),
                                                     vec::sub({mesh.positions[tri[2]][0], mesh.positions[tri[2]][1], mesh.positions[tri[2]][2]}, {a[0], a[1], a[2]}));
    const double t = vec::dot(n, vec::sub({a[0], a[1], a[2]}, rays.eye)) / vec::dot(n, d);
    return textureAt(i, planeBarycentrics(mesh, i, vec::add(rays.eye, vec::scale(d, t))));
  };
  grooves::SeedSettings asRuntime;
  asRuntime.foundCap = format::grooves::kMaxFoundPerFootprint;
  const grooves::SeedShader oracle(baked.scene, baked.grid, asRuntime);
  std::size_t compared = 0, over = 0;
  double maxCentre = 0, maxAxis = 0, maxDirection = 0;
  int maxLevels = 0;
  std::vector<double> axisErrors;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t p = std::size_t(y) * kSize + std::size_t(x);
      const float* a = &f.inputs[0][p * 4];
      const float* b = &f.inputs[1][p * 4];
      const float* c = &f.inputs[2][p * 4];
      if (!(c[0] > 0.1f)) continue;  // not covered, or within ~6 degrees of the silhouette
      const std::optional<RayHit> hit = castRay(mesh, rays.eye, rays.through(x + 0.5, y + 0.5));
      if (!hit) continue;
      const std::size_t i = hit->triangle;
      const std::array<double, 3> bary{hit->b[0], hit->b[1], hit->b[2]};
      const std::array<double, 2> centre = textureAt(i, bary);
      const auto right = textureOnPlane(i, x + 1.0, y + 0.5), left = textureOnPlane(i, x + 0.0, y + 0.5);
      const auto top = textureOnPlane(i, x + 0.5, y + 1.0), bottom = textureOnPlane(i, x + 0.5, y + 0.0);
      const grooves::Vec2 axis1{right[0] - left[0], right[1] - left[1]}, axis2{top[0] - bottom[0], top[1] - bottom[1]};
      Vec3d normal{0, 0, 0}, tangent{0, 0, 0};
      double handedness = 0;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.triangles[i][std::size_t(k)];
        for (int j = 0; j < 3; ++j) {
          normal[std::size_t(j)] += bary[std::size_t(k)] * mesh.normals[v][std::size_t(j)];
          tangent[std::size_t(j)] += bary[std::size_t(k)] * surface.tangents[v][std::size_t(j)];
        }
        handedness += surface.tangents[v][3];
      }
      normal = vec::unit(normal, {0, 0, 1});
      const Vec3d u = vec::unit(vec::sub(tangent, vec::scale(normal, vec::dot(normal, tangent))), {1, 0, 0});
      const Vec3d w = vec::scale(vec::cross(normal, u), handedness < 0 ? -1 : 1);
      const Vec3d point = vec::add(rays.eye, vec::scale(rays.through(x + 0.5, y + 0.5), hit->t));
      const Vec3d view = vec::unit(vec::sub(rays.eye, point), {0, 0, 1});
      const grooves::Vec3 toViewer{vec::dot(view, u), vec::dot(view, w), vec::dot(view, normal)};
      grooves::Lighting lighting;
      lighting.toLight = {vec::dot(toLight, u), vec::dot(toLight, w), vec::dot(toLight, normal)};
      lighting.maxBounces = 0;

      const double extent = std::max(std::hypot(axis1.u, axis1.v), std::hypot(axis2.u, axis2.v));
      maxCentre = std::max(maxCentre, std::hypot(a[0] - centre[0], a[1] - centre[1]) / extent);
      const double axisError = std::max(std::hypot(a[2] - axis1.u, a[3] - axis1.v), std::hypot(b[0] - axis2.u, b[1] - axis2.v)) / extent;
      axisErrors.push_back(axisError);
      maxAxis = std::max(maxAxis, axisError);
      maxDirection = std::max({maxDirection, std::abs(b[2] - toViewer.u), std::abs(b[3] - toViewer.v), std::abs(c[0] - toViewer.w),
                               std::abs(c[1] - lighting.toLight.u), std::abs(c[2] - lighting.toLight.v), std::abs(c[3] - lighting.toLight.w)});
      const grooves::Rgb expected = oracle.shade({{centre[0], centre[1]}, axis1, axis2}, toViewer, lighting);
      int levels = 0;
      for (int k = 0; k < 3; ++k)
        levels = std::max(levels, std::abs(quantised(f.radiance[p * 4 + std::size_t(k)]) - quantised(expected[std::size_t(k)])));
      maxLevels = std::max(maxLevels, levels);
      over += levels > 2 ? 1 : 0;
      ++compared;
    }
  std::sort(axisErrors.begin(), axisErrors.end());
  const double axis99 = axisErrors.empty() ? 0 : axisErrors[axisErrors.size() * 99 / 100];
  std::printf("[ grooves ] column through the mesh: %zu pixels; F within %.3g footprints, footprint edges within %.3g "
              "(99th percentile %.3g), E and L within %.3g; CPU-own inputs: max %d/255, %zu pixels over 2/255\n",
              compared, maxCentre, maxAxis, axis99, maxDirection, maxLevels, over);
  RecordProperty("column_mesh_pixels", int(compared));
  RecordProperty("column_mesh_max_levels", maxLevels);
  EXPECT_GT(compared, std::size_t(kSize * kSize / 4)) << "the column covers too little of the image";
  EXPECT_LE(maxCentre, 0.01) << "the shader's footprint centre is off the CPU's ray hit";
  EXPECT_LE(maxDirection, 2e-3) << "the shader's tangent frame differs from the mesh's TANGENT frame";
  EXPECT_LE(axis99, 0.05) << "the shader's footprint edges differ from one pixel's change of F";
  EXPECT_EQ(over, 0u) << "pixels where the CPU method through the mesh differs by more than 2/255";
}

// `bakeplay validate --golden` on the fluted column as `groovebake --apply-to` writes it (here without
// special-case records, so the check compiles no area-sampling variant): the package passes, and its
// first reference view is the golden image (tests/golden/runtime/grooves-column.v1.png).
TEST_F(GroovesOracle, ColumnPackageValidatesAgainstItsGoldenImage) {
  const grooves::GrooveSurface surface = columnSurface();
  ASSERT_FALSE(surface.tangents.empty());
  const Baked baked = bake(exampleScene("flutes.json"), "column_validate", std::nullopt, 1, &surface, false);
  ASSERT_FALSE(baked.file.empty());
  test::expectValidatesAgainstGolden(baked.file, "runtime/grooves-column.v1.png", baked.file.parent_path() / "views");
}

TEST(GroovesPackage, RegisteredForTheExtension) {
  EXPECT_TRUE(RendererRegistry::builtIn().has(format::grooves::kExtension));
}

TEST(GroovesPackage, ValidateAcceptsAGoodPackageAndRejectsDamage) {
  auto scene = grooves::parseGrooveScene(
      sceneJson(1, R"("vee": {"points": [[-0.06, 0], [0, -0.05], [0.06, 0]]})", kGrey, "grey", linesAlongU({0.5}, 1, "vee")),
      "check.json");
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  auto grid = grooves::buildGrooveGrid(*scene, {});
  ASSERT_TRUE(grid.isOk());
  auto package = grooves::buildGroovePackage(*scene, *grid);
  ASSERT_TRUE(package.isOk());
  EXPECT_TRUE(checkPackageStructure(*package, "good.glb").isOk());

  glb::Package wrongVersion = *package;
  wrongVersion.materials[0]["extensions"][format::grooves::kExtension]["version"] = format::grooves::kVersion + 1;
  const Status version = checkPackageStructure(wrongVersion, "version.glb");
  ASSERT_FALSE(version.isOk());
  EXPECT_NE(version.describe().find("version " + std::to_string(format::grooves::kVersion + 1)), std::string::npos)
      << version.describe();

  glb::Package badIndex = *package;
  const std::size_t refs = (*package).materials[0]["extensions"][format::grooves::kExtension]["bufferViews"]
                                                 [format::grooves::kPrimitiveRefs].get<std::size_t>();
  ASSERT_GE(badIndex.blobs[refs].bytes.size(), 4u);
  const std::uint32_t outOfRange = 1000;
  std::memcpy(badIndex.blobs[refs].bytes.data(), &outOfRange, 4);
  const Status index = checkPackageStructure(badIndex, "index.glb");
  ASSERT_FALSE(index.isOk());
  EXPECT_NE(index.describe().find(format::grooves::kExtension), std::string::npos) << index.describe();
}

}  // namespace
}  // namespace bake::play
