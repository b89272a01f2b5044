// GeoTextures (seed 003 5.2-5.3, Appendix C) on llvmpipe. The package is built here with libbake's
// GLB writer: a unit sphere whose field 0 is the exact geodesic distance from the +Z pole (the polar
// angle, normalised by pi) and field 1 the distance from the point (0.6, 0, 0.8), plus a small second
// sphere that no source reaches (unreachable flag). The camera looks down -Z from (0, 0, 3.5), so
// the tests ray-cast each pixel against the exact sphere and know its distances analytically: pixels
// well inside a front must show the near material, pixels well beyond it the far one.
#include <GL/glcorearb.h>
#include <gtest/gtest.h>

#include <bake_formats/geodesic.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>

#include "bake/io/glb.h"
#include "bake/io/image.h"
#include "io/image_compare.h"
#include "play/render.h"
#include "play/validate.h"
#include "render/geodesic.h"
#include "render/target.h"
#include "runtime/gl_test.h"
#include "runtime/golden_image.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

constexpr int kSize = 128;
constexpr float kEye = 3.5f;
constexpr float kFov = 0.7f;  // the default camera's vertical field of view
const Vec3 kSecondSource = {0.6f, 0.0f, 0.8f};
const Vec3 kLoneCentre = {0.96f, 0.96f, 0.0f};  // the unreachable sphere, radius 0.25
constexpr float kLoneRadius = 0.25f;

float polarDistance(const Vec3& p, const Vec3& source) {
  return std::acos(std::clamp(dot(normalize(p), source), -1.0f, 1.0f)) / std::numbers::pi_v<float>;
}

// A UV sphere, appended to the arrays; `field` gives the two field values of a unit-sphere point.
void addSphere(Vec3 centre, float radius, const std::function<std::array<float, 2>(const Vec3&)>& field,
               std::vector<float>& positions, std::vector<float>& normals, std::vector<float>& f0,
               std::vector<float>& f1, std::vector<std::uint32_t>& indices) {
  const int stacks = 40, slices = 80;
  const auto first = std::uint32_t(positions.size() / 3);
  for (int i = 0; i <= stacks; ++i) {
    const float theta = std::numbers::pi_v<float> * float(i) / float(stacks);
    for (int j = 0; j <= slices; ++j) {
      const float phi = 2 * std::numbers::pi_v<float> * float(j) / float(slices);
      const Vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      const Vec3 p = centre + n * radius;
      positions.insert(positions.end(), p.begin(), p.end());
      normals.insert(normals.end(), n.begin(), n.end());
      const auto values = field(n);
      f0.push_back(values[0]);
      f1.push_back(values[1]);
    }
  }
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const std::uint32_t a = first + std::uint32_t(i * (slices + 1) + j), b = a + std::uint32_t(slices + 1);
      indices.insert(indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
}

enum class Encoding { Float, Unorm16 };

glb::Package spherePackage(const nlohmann::json& material, Encoding encoding = Encoding::Float, bool loneSphere = true) {
  std::vector<float> positions, normals, f0, f1;
  std::vector<std::uint32_t> indices;
  addSphere(
      {0, 0, 0}, 1.0f,
      [](const Vec3& n) {
        return std::array{polarDistance(n, {0, 0, 1}), polarDistance(n, kSecondSource)};
      },
      positions, normals, f0, f1, indices);
  const float flag = encoding == Encoding::Float ? format::geodesic::kUnreachableFloat : 1.0f;
  if (loneSphere) addSphere(
      kLoneCentre, kLoneRadius,
      [&](const Vec3&) {
        return std::array{flag, flag};
      },
      positions, normals, f0, f1, indices);
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  const bool unorm = encoding == Encoding::Unorm16;
  if (unorm) {
    // Reachable values stop at 65534/65535; 1.0 (65535) is the flag.
    for (auto* f : {&f0, &f1}) {
      for (float& v : *f) v = v == 1.0f ? 1.0f : std::min(v, 65534.0f / 65535.0f);
    }
  }
  for (int k = 0; k < 2; ++k) {
    const std::string name = "_GEODESIC_" + std::to_string(k);
    const std::vector<float>& values = k == 0 ? f0 : f1;
    primitive.attributes.push_back(unorm ? glb::Attribute::fromUnorm16(name, 1, values)
                                         : glb::Attribute::fromFloats(name, 1, values));
  }
  primitive.indices = indices;
  glb::Package package;
  if (!material.is_null()) {
    primitive.material = 0;
    package.materials = nlohmann::json::array({{{"extensions", {{"BAKE_geodesic", material}}}}});
  }
  package.meshes.push_back({"spheres", {primitive}});
  glb::Node node;
  node.mesh = 0;
  package.nodes.push_back(node);
  package.extensions["BAKE_geodesic"] = {
      {"version", 1},
      {"encoding", unorm ? "unorm16" : "float"},
      {"unreachableValue", unorm ? 65535.0 : -1.0},
      {"fields",
       {{{"attribute", "_GEODESIC_0"}, {"maxDistance", std::numbers::pi}},
        {{"attribute", "_GEODESIC_1"}, {"maxDistance", std::numbers::pi}}}}};
  return package;
}

nlohmann::json geoMaterial(const std::string& preset, nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json m = {{"version", 1}, {"texture", preset}};
  for (const auto& [key, value] : extra.items()) m[key] = value;
  return m;
}

fs::path writePackage(const glb::Package& package, const std::string& name) {
  const fs::path path = test::freshTempDir("geodesic_" + name) / (name + ".glb");
  const Status status = glb::write(path, package);
  EXPECT_TRUE(status.isOk()) << status.describe();
  return path;
}

struct RenderOptions {
  std::string geotexture;
  float time = 0;
};

// Renders through `bakeplay render`'s own entry point; the PNG read back (sRGB values, top row first).
Image renderPackage(const glb::Package& package, const std::string& name, const RenderOptions& options = {}) {
  const fs::path file = writePackage(package, name);
  RenderSettings settings;
  settings.view.scenes = {file.string()};
  settings.view.width = settings.view.height = kSize;
  settings.view.camera = "0,0," + std::to_string(kEye) + ":0,0,0";
  settings.view.light = "0.3,0.4,1";
  settings.view.geotexture = options.geotexture;
  settings.view.time = options.time;
  settings.output = (file.parent_path() / (name + ".png")).string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  auto image = readImage(settings.output);
  EXPECT_TRUE(image.isOk());
  return image.isOk() ? *image : Image{};
}

// What a pixel sees: the exact sphere point, if the ray hits the unit sphere well inside its
// silhouette (grazing pixels are left out: there the triangulated sphere differs from the exact one).
std::optional<Vec3> unitSphereHit(int x, int y) {
  const float t = std::tan(kFov / 2);
  const Vec3 direction =
      normalize({((float(x) + 0.5f) / kSize * 2 - 1) * t, (1 - (float(y) + 0.5f) / kSize * 2) * t, -1});
  const Vec3 origin{0, 0, kEye};
  const float b = dot(origin, direction), c = dot(origin, origin) - 1;
  const float disc = b * b - c;
  if (disc <= 0) return std::nullopt;
  const Vec3 hit = origin + direction * (-b - std::sqrt(disc));
  if (dot(hit, normalize(origin - hit)) < 0.12f) return std::nullopt;  // up to d = 0.36
  return hit;
}

using Rgb8 = std::array<float, 3>;
Rgb8 pixel(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

// Share of the pixels whose exact distances satisfy `where` that also satisfy `looks`; the count is
// returned so tests can insist the class is not empty.
struct Share {
  double fraction = 0;
  int count = 0;
};
Share share(const Image& image, const std::function<bool(float d0, float d1)>& where,
            const std::function<bool(const Rgb8&)>& looks) {
  Share s;
  int good = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto hit = unitSphereHit(x, y);
      if (!hit || !where(polarDistance(*hit, {0, 0, 1}), polarDistance(*hit, kSecondSource))) continue;
      ++s.count;
      good += looks(pixel(image, x, y)) ? 1 : 0;
    }
  }
  s.fraction = s.count ? double(good) / s.count : 0;
  return s;
}

bool reddish(const Rgb8& c) { return c[0] > c[2] + 0.15f && c[0] > c[1] + 0.1f; }
bool greenish(const Rgb8& c) { return c[1] > c[0] + 0.1f && c[1] > c[2] + 0.1f; }
bool bluish(const Rgb8& c) { return c[2] > c[0] + 0.15f && c[2] > c[1] + 0.05f; }
float luminance(const Rgb8& c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }

const nlohmann::json kRed = {0.9, 0.05, 0.05}, kGreen = {0.05, 0.8, 0.05}, kBlue = {0.05, 0.1, 0.9};

// The centre pixel of the unreachable sphere.
Rgb8 lonePixel(const Image& image) {
  const float t = std::tan(kFov / 2);
  const int x = int((kLoneCentre[0] / (kEye - kLoneCentre[2]) / t + 1) * 0.5f * kSize);
  const int y = int((1 - kLoneCentre[1] / (kEye - kLoneCentre[2]) / t) * 0.5f * kSize);
  return pixel(image, x, y);
}

// ---------------------------------------------------------------------------------------------
// Parameters and validation (no GL)

TEST(GeoTextureParams, PresetsHaveNamesAndDefaults) {
  EXPECT_EQ(geoPresetNames().size(), 7u);
  for (const std::string& name : geoPresetNames()) {
    auto params = parseGeoTexture({{"version", 1}, {"texture", name}}, {});
    ASSERT_TRUE(params.isOk()) << params.status().describe();
    EXPECT_EQ(geoPresetName(params->preset), name);
  }
  auto water = parseGeoTexture({{"version", 1}, {"texture", "water-lava"}}, {});
  EXPECT_EQ(water->fields, (std::vector<int>{0, 1}));
  auto set = parseGeoTexture(
      geoMaterial("sand-water", {{"thresholds", {0.4}}, {"speed", 0.1}, {"colors", {kRed}}}), {});
  ASSERT_TRUE(set.isOk());
  EXPECT_FLOAT_EQ(set->thresholds[3], 0.4f) << "a short list repeats its last value";
  EXPECT_FLOAT_EQ(set->speed, 0.1f);
  EXPECT_FLOAT_EQ(set->colours[0][0], 0.9f);
}

TEST(GeoTextureParams, BadParametersAreNamed) {
  const Location where{"p.glb", "material 0"};
  auto unknown = parseGeoTexture(geoMaterial("plaid"), where);
  EXPECT_EQ(unknown.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(unknown.status().message().find("unknown texture \"plaid\""), std::string::npos);
  EXPECT_EQ(unknown.status().where().element, "material 0");
  EXPECT_FALSE(parseGeoTexture(geoMaterial("isolines", {{"thresholds", "0.3"}}), where).isOk());
  EXPECT_FALSE(parseGeoTexture(geoMaterial("isolines", {{"colors", {{2, 0, 0}}}}), where).isOk());
  EXPECT_FALSE(parseGeoTexture(geoMaterial("isolines", {{"fields", {0, 1, 2}}}), where).isOk())
      << "three separate fields";
  EXPECT_TRUE(
      parseGeoTexture(geoMaterial("isolines", {{"fields", {0, 1, 2}}, {"combine", "min"}}), where).isOk());
  EXPECT_FALSE(
      parseGeoTexture(geoMaterial("wave-displacement", {{"wave", {{"displace", 1}}}}), where).isOk());
}

TEST(GeoTextureValidate, ChecksFieldsAndMaterials) {
  EXPECT_TRUE(checkGeodesicPackage(spherePackage(geoMaterial("isolines")), "s.glb").isOk());
  EXPECT_TRUE(
      checkGeodesicPackage(spherePackage(geoMaterial("isolines"), Encoding::Unorm16), "s.glb").isOk());

  glb::Package outOfRange = spherePackage(geoMaterial("isolines"));
  glb::Attribute& field = outOfRange.meshes[0].primitives[0].attributes[2];
  std::vector<float> values = field.toFloats();
  values[7] = 1.5f;
  field = glb::Attribute::fromFloats("_GEODESIC_0", 1, values);
  const Status range = checkGeodesicPackage(outOfRange, "s.glb");
  EXPECT_NE(range.message().find("_GEODESIC_0 vertex 7 holds 1.5"), std::string::npos) << range.describe();
  EXPECT_EQ(checkPackageStructure(outOfRange, "s.glb").code(), ExitCode::InvalidInput)
      << "validate runs the check";

  glb::Package vector = spherePackage(geoMaterial("isolines"));
  vector.meshes[0].primitives[0].attributes[3] =
      glb::Attribute::fromFloats("_GEODESIC_1", 2, std::vector<float>(values.size() * 2, 0.5f));
  EXPECT_NE(checkGeodesicPackage(vector, "s.glb").message().find("SCALAR"), std::string::npos);

  EXPECT_FALSE(checkGeodesicPackage(spherePackage(geoMaterial("plaid")), "s.glb").isOk());
  const Status missing =
      checkGeodesicPackage(spherePackage(geoMaterial("isolines", {{"fields", {3}}})), "s.glb");
  EXPECT_NE(missing.message().find("no _GEODESIC_3"), std::string::npos) << missing.describe();

  glb::Package listed = spherePackage(geoMaterial("isolines"));
  listed.extensions["BAKE_geodesic"]["fields"].push_back({{"attribute", "_GEODESIC_5"}});
  EXPECT_NE(checkGeodesicPackage(listed, "s.glb").message().find("_GEODESIC_5"), std::string::npos);
  // Without BAKE_geodesic anywhere, _GEODESIC_k is an ordinary application attribute.
  glb::Package plain = outOfRange;
  plain.extensions.erase("BAKE_geodesic");
  plain.materials = nlohmann::json::array();
  plain.meshes[0].primitives[0].material = -1;
  EXPECT_TRUE(checkGeodesicPackage(plain, "s.glb").isOk());

  glb::Package encoding = spherePackage(geoMaterial("isolines"));
  encoding.extensions["BAKE_geodesic"]["encoding"] = "unorm16";
  EXPECT_FALSE(checkGeodesicPackage(encoding, "s.glb").isOk());
}

// `bakeplay validate` renders each package: every preset's shaders compile and draw, a bare package
// (fields, no material) too, and a broken material fails with its reason.
// Runs `bakeplay validate` on packages; the status, with the verdict lines on failure.
Status validatePackages(const std::vector<std::string>& packages, std::string& verdicts) {
  ValidateSettings settings;
  settings.size = 32;
  settings.common.quiet = true;
  settings.packages = packages;
  Diagnostics diagnostics("bakeplay", true);
  std::FILE* out = std::tmpfile();
  const Status status = runValidate(settings, diagnostics, out);
  std::rewind(out);
  char line[4096];
  while (std::fgets(line, sizeof line, out)) verdicts += line;
  std::fclose(out);
  return status;
}

TEST(GeoTextureValidate, ValidateCommandAcceptsEveryPreset) {
  std::vector<std::string> packages;
  for (const std::string& preset : geoPresetNames()) {
    packages.push_back(writePackage(spherePackage(geoMaterial(preset)), "validate_" + preset).string());
  }
  std::string verdicts;
  const Status status = validatePackages(packages, verdicts);
  EXPECT_TRUE(status.isOk()) << status.describe() << "\n" << verdicts;
}

TEST(GeoTextureValidate, ValidateCommandOnBareAndBrokenPackages) {
  std::string verdicts;
  const Status good = validatePackages(
      {writePackage(spherePackage(nullptr), "validate_bare").string(),
       writePackage(spherePackage(geoMaterial("isolines"), Encoding::Unorm16), "validate_u16").string()},
      verdicts);
  EXPECT_TRUE(good.isOk()) << good.describe() << "\n" << verdicts;
  verdicts.clear();
  const Status bad = validatePackages(
      {writePackage(spherePackage(geoMaterial("isolines", {{"fields", {4}}})), "validate_bad").string()},
      verdicts);
  EXPECT_EQ(bad.code(), ExitCode::InvalidInput);
  EXPECT_NE(verdicts.find("FAIL"), std::string::npos);
  EXPECT_NE(verdicts.find("no _GEODESIC_4 attribute"), std::string::npos) << verdicts;
}

// ---------------------------------------------------------------------------------------------
// Presets, rendered

TEST(GeoTextureRender, IsolinesFollowTheField) {
  const Image image = renderPackage(
      spherePackage(geoMaterial("isolines", {{"isolines", {{"spacing", 0.1}, {"width", 1.5}}}})), "isolines");
  // The colour map: red at the source, towards blue far away.
  EXPECT_GT(share(
                image, [](float d, float) { return d < 0.03f; }, reddish)
                .fraction,
            0.9);
  // Towards yellow and green further out: the green-to-red ratio grows with the distance.
  const auto greenOverRed = [&](float lo, float hi) {
    double sum = 0;
    int n = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const auto hit = unitSphereHit(x, y);
        const float d = hit ? polarDistance(*hit, {0, 0, 1}) : -1;
        const float offset = std::fabs(d / 0.1f - std::round(d / 0.1f));
        if (d < lo || d > hi || offset < 0.25f) continue;  // off the isolines
        const Rgb8 c = pixel(image, x, y);
        sum += c[1] / std::max(c[0], 1e-3f), ++n;
      }
    }
    return n ? sum / n : 0.0;
  };
  EXPECT_LT(greenOverRed(0.0f, 0.1f), 0.6);
  EXPECT_GT(greenOverRed(0.2f, 0.36f), 0.85);
  // Lines: pixels on d = 0.1 k are dark, pixels half-way between are bright.
  double onLine = 0, between = 0;
  int nOn = 0, nBetween = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto hit = unitSphereHit(x, y);
      if (!hit) continue;
      const float d = polarDistance(*hit, {0, 0, 1});
      const float offset = std::fabs(d / 0.1f - std::round(d / 0.1f));
      if (d > 0.05f && offset < 0.04f) onLine += luminance(pixel(image, x, y)), ++nOn;
      if (offset > 0.35f) between += luminance(pixel(image, x, y)), ++nBetween;
    }
  }
  ASSERT_GT(nOn, 30);
  ASSERT_GT(nBetween, 30);
  EXPECT_LT(onLine / nOn, 0.5 * between / nBetween)
      << "isolines are dark where d is a multiple of the spacing";
}

TEST(GeoTextureRender, SandInsideTheFrontWaterBeyond) {
  const Image image = renderPackage(
      spherePackage(geoMaterial("sand-water", {{"thresholds", {0.25}}, {"colors", {kRed, kBlue}}})),
      "sand_water");
  const Share sand = share(
      image, [](float d, float) { return d < 0.2f; }, reddish);
  const Share water = share(
      image, [](float d, float) { return d > 0.3f; }, bluish);
  EXPECT_GT(sand.count, 100);
  EXPECT_GT(water.count, 100);
  EXPECT_GT(sand.fraction, 0.95);
  EXPECT_GT(water.fraction, 0.95);
}

TEST(GeoTextureRender, MossSpreadsOverGranite) {
  const Image image = renderPackage(
      spherePackage(geoMaterial("moss-granite", {{"thresholds", {0.2}}, {"colors", {kGreen, kBlue}}})),
      "moss_granite");
  // The default front noise moves the border by up to 0.04.
  EXPECT_GT(share(
                image, [](float d, float) { return d < 0.14f; }, greenish)
                .fraction,
            0.95);
  EXPECT_GT(share(
                image, [](float d, float) { return d > 0.27f; }, bluish)
                .fraction,
            0.95);
}

TEST(GeoTextureRender, PaintMetalRustNestFromTheSource) {
  const Image image =
      renderPackage(spherePackage(geoMaterial("paint-metal-rust", {{"thresholds", {0.06, 0.17, 0.29}},
                                                                   {"widths", {0.005, 0.01, 0.01}},
                                                                   {"frontNoise", {{"amplitude", 0.0}}},
                                                                   {"colors", {kRed, kRed, kGreen, kBlue}}})),
                    "paint_metal_rust");
  EXPECT_GT(share(
                image, [](float d, float) { return d > 0.08f && d < 0.15f; }, reddish)
                .fraction,
            0.95)
      << "rust";
  EXPECT_GT(share(
                image, [](float d, float) { return d > 0.19f && d < 0.27f; }, greenish)
                .fraction,
            0.95)
      << "metal";
  EXPECT_GT(share(
                image, [](float d, float) { return d > 0.31f; }, bluish)
                .fraction,
            0.95)
      << "paint";
  // Holes: the sphere is cut away around the source, showing its unlit inside, never rust.
  const Share holes = share(
      image, [](float d, float) { return d < 0.04f; }, [](const Rgb8& c) { return !reddish(c); });
  EXPECT_GT(holes.count, 20);
  EXPECT_GT(holes.fraction, 0.95);
}

TEST(GeoTextureRender, WaterAndLavaFollowTheirOwnFields) {
  const Image image = renderPackage(
      spherePackage(geoMaterial("water-lava", {{"thresholds", {0.12, 0.25}},
                                               {"frontNoise", {{"amplitude", 0.0}}},
                                               {"colors", {kBlue, {1.0, 0.3, 0.02}, {0.1, 0.1, 0.1}}}})),
      "water_lava");
  EXPECT_GT(share(
                image, [](float d0, float) { return d0 < 0.1f; }, bluish)
                .fraction,
            0.95)
      << "water from field 0";
  const Share lava = share(
      image, [](float d0, float d1) { return d1 < 0.22f && d0 > 0.15f; }, reddish);
  EXPECT_GT(lava.count, 50);
  EXPECT_GT(lava.fraction, 0.9) << "lava from field 1";
  double lavaLight = 0, rockLight = 0;
  int nLava = 0, nRock = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto hit = unitSphereHit(x, y);
      if (!hit) continue;
      const float d0 = polarDistance(*hit, {0, 0, 1}), d1 = polarDistance(*hit, kSecondSource);
      if (d0 > 0.15f && d1 < 0.22f) lavaLight += luminance(pixel(image, x, y)), ++nLava;
      if (d0 > 0.15f && d1 > 0.28f) rockLight += luminance(pixel(image, x, y)), ++nRock;
    }
  }
  ASSERT_GT(nRock, 50);
  EXPECT_GT(lavaLight / nLava, 1.5 * rockLight / nRock) << "glowing lava over dark burnt rock";
}

TEST(GeoTextureRender, OpacityFrontRevealsTheBackground) {
  const auto material = [](double opacity) {
    return geoMaterial("opacity-front",
                       {{"thresholds", {0.2}}, {"opacity", opacity}, {"colors", {kRed, kGreen}}});
  };
  const Image clear = renderPackage(spherePackage(material(0.0)), "opacity_clear");
  const Rgb8 background = pixel(clear, 2, 2);
  EXPECT_GT(share(
                clear, [](float d, float) { return d < 0.17f; }, reddish)
                .fraction,
            0.95);
  const auto isBackground = [&](const Rgb8& c) {
    return std::fabs(c[0] - background[0]) < 0.01f && std::fabs(c[1] - background[1]) < 0.01f &&
           std::fabs(c[2] - background[2]) < 0.01f;
  };
  EXPECT_GT(share(
                clear, [](float d, float) { return d > 0.23f; }, isBackground)
                .fraction,
            0.95)
      << "fully transparent beyond the front";
  const Image veiled = renderPackage(spherePackage(material(0.5)), "opacity_veiled");
  EXPECT_GT(share(
                veiled, [](float d, float) { return d > 0.23f; },
                [&](const Rgb8& c) { return c[1] > background[1] + 0.05f && !isBackground(c); })
                .fraction,
            0.9)
      << "half transparent: the green far material over the background";
}

TEST(GeoTextureRender, UnreachableVerticesHaveTheirOwnFlatColour) {
  for (Encoding encoding : {Encoding::Float, Encoding::Unorm16}) {
    SCOPED_TRACE(encoding == Encoding::Float ? "float" : "unorm16");
    for (const std::string preset : {"isolines", "sand-water"}) {
      const Image image =
          renderPackage(spherePackage(geoMaterial(preset, {{"unreachableColor", {0.0, 1.0, 1.0}}}), encoding),
                        "unreachable_" + preset);
      const Rgb8 lone = lonePixel(image);
      EXPECT_NEAR(lone[0], 0.0f, 1e-3f) << preset;
      EXPECT_NEAR(lone[1], 1.0f, 1e-3f) << preset;
      EXPECT_NEAR(lone[2], 1.0f, 1e-3f) << preset;
    }
  }
}

TEST(GeoTextureRender, Unorm16FieldsLookLikeFloatFields) {
  const nlohmann::json material = geoMaterial("isolines");
  const Image f = renderPackage(spherePackage(material), "enc_float");
  const Image u = renderPackage(spherePackage(material, Encoding::Unorm16), "enc_unorm16");
  auto difference = compareImages(f, u, 0.1);
  ASSERT_TRUE(difference.isOk());
  EXPECT_LT(difference->rmse, 0.01) << describe(*difference);
}

// normalization "none" stores model units (here radians, up to pi); the presets still see [0, 1].
TEST(GeoTextureRender, FieldsInModelUnitsAreNormalised) {
  const nlohmann::json material = geoMaterial("isolines");
  glb::Package units = spherePackage(material);
  units.extensions["BAKE_geodesic"]["normalization"] = "none";
  for (int k = 0; k < 2; ++k) {
    glb::Attribute& field = units.meshes[0].primitives[0].attributes[std::size_t(2 + k)];
    std::vector<float> values = field.toFloats();
    for (float& v : values) v = v < 0 ? v : v * std::numbers::pi_v<float>;
    field = glb::Attribute::fromFloats(field.name, 1, values);
  }
  EXPECT_TRUE(checkGeodesicPackage(units, "units.glb").isOk());
  auto difference =
      compareImages(renderPackage(spherePackage(material), "units_ref"), renderPackage(units, "units"), 0.1);
  ASSERT_TRUE(difference.isOk());
  EXPECT_LT(difference->rmse, 0.01) << describe(*difference);
}

TEST(GeoTextureRender, AnimatedThresholdAdvancesWithTime) {
  const glb::Package package = spherePackage(
      geoMaterial("sand-water", {{"thresholds", {0.1}}, {"speed", 0.2}, {"colors", {kRed, kBlue}}}));
  const Image early = renderPackage(package, "anim_t0", {"", 0.0f});
  const Image late = renderPackage(package, "anim_t1", {"", 1.0f});  // front at 0.3
  const auto band = [](float d, float) { return d > 0.15f && d < 0.25f; };
  EXPECT_GT(share(early, band, bluish).fraction, 0.95) << "water before the front arrives";
  EXPECT_GT(share(late, band, reddish).fraction, 0.95) << "sand once the front has passed";
}

TEST(GeoTextureRender, PresetOptionChoosesAndOverrides) {
  // A bare geobake package (fields, no material) shows isolines: red at the source.
  const Image bare = renderPackage(spherePackage(nullptr), "bare");
  EXPECT_GT(share(
                bare, [](float d, float) { return d < 0.03f; }, reddish)
                .fraction,
            0.9);
  // --geotexture replaces the preset a material names and keeps its other parameters.
  const Image chosen = renderPackage(spherePackage(geoMaterial("isolines", {{"colors", {kGreen, kBlue}}})),
                                     "override", {"sand-water", 0.0f});
  EXPECT_GT(share(
                chosen, [](float d, float) { return d < 0.25f; }, greenish)
                .fraction,
            0.95);
  EXPECT_GT(share(
                chosen, [](float d, float) { return d > 0.3f; }, bluish)
                .fraction,
            0.95);

  RenderSettings settings;
  settings.view.scenes = {writePackage(spherePackage(nullptr), "override_bad").string()};
  settings.view.geotexture = "plaid";
  settings.output = (fs::path(settings.view.scenes[0]).parent_path() / "x.png").string();
  Diagnostics diagnostics("bakeplay", true);
  EXPECT_EQ(runRender(settings, diagnostics).code(), ExitCode::Usage);
}

// ---------------------------------------------------------------------------------------------
// Wave displacement with adaptive tessellation

struct WaveFrame {
  Image image;
  GLuint64 primitives = 0;
};

class GeoTextureWave : public test::GlTest {
 protected:
  // Draws through SceneRenderer, counting the primitives that reach the rasteriser.
  WaveFrame draw(const nlohmann::json& material, bool withNormals = true, bool loneSphere = true) {
    glb::Package package = spherePackage(material, Encoding::Float, loneSphere);
    if (!withNormals)
      std::erase_if(package.meshes[0].primitives[0].attributes,
                    [](const glb::Attribute& a) { return a.name == "NORMAL"; });
    const fs::path file = writePackage(package, "wave");
    Diagnostics diagnostics("bakeplay", true);
    auto scene = loadScene({file}, diagnostics, [](const std::string&) { return true; });
    EXPECT_TRUE(scene.isOk()) << scene.status().describe();
    gl::ShaderLibrary shaders;
    auto renderer = SceneRenderer::create(*scene, RendererRegistry::builtIn(), shaders);
    EXPECT_TRUE(renderer.isOk()) << renderer.status().describe();
    auto target = OffscreenTarget::create(kSize, kSize);
    Camera camera;
    camera.eye = {0, 0, kEye};
    const Light light;
    const FrameContext frame{*scene,
                             camera,
                             light,
                             lookAt(camera.eye, camera.target, camera.up),
                             perspective(camera.yfov, 1.0f, camera.znear, camera.zfar),
                             kSize,
                             kSize,
                             0.0f};
    target->bind();
    GLuint query = 0;
    glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    renderer->drawFrame(frame);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    WaveFrame out;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &out.primitives);
    glDeleteQueries(1, &query);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    out.image = target->readLinearRgba();
    return out;
  }
  static int coverageDifference(const Image& a, const Image& b) {
    int differing = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const bool coveredA = std::fabs(a.at(x, y, 2) - a.at(0, 0, 2)) > 1e-4f ||
                              std::fabs(a.at(x, y, 0) - a.at(0, 0, 0)) > 1e-4f;
        const bool coveredB = std::fabs(b.at(x, y, 2) - b.at(0, 0, 2)) > 1e-4f ||
                              std::fabs(b.at(x, y, 0) - b.at(0, 0, 0)) > 1e-4f;
        differing += coveredA != coveredB ? 1 : 0;
      }
    }
    return differing;
  }
};

nlohmann::json waveMaterial(double amplitude, bool displace) {
  // The packet d in [0.15, 0.45] covers the silhouette (d = 0.41 from this camera).
  return geoMaterial("wave-displacement", {{"thresholds", {0.45}},
                                           {"wave",
                                            {{"amplitude", amplitude},
                                             {"wavelength", 0.06},
                                             {"reach", 0.3},
                                             {"displace", displace},
                                             {"pixelsPerEdge", 4}}}});
}

TEST_F(GeoTextureWave, TessellationRefinesOnlyWhereTheWaveIs) {
  const WaveFrame flat = draw(waveMaterial(0.08, false));
  const WaveFrame refined = draw(waveMaterial(0.08, true));
  EXPECT_EQ(flat.primitives, 40u * 80u * 2u * 2u) << "both spheres, untessellated";
  EXPECT_GT(refined.primitives, 2 * flat.primitives) << "the wave band is refined";
  // Outside the packet nothing is split: a packet that touches no vertex leaves the count unchanged.
  const WaveFrame away = draw(geoMaterial("wave-displacement", {{"thresholds", {-0.5}}}));
  EXPECT_EQ(away.primitives, flat.primitives);
}

// Without vertex normals the renderer makes smooth ones, so the displaced surface matches the one
// displaced along the package's own (here exact) normals.
TEST_F(GeoTextureWave, PrimitivesWithoutNormalsDisplaceSmoothly) {
  const WaveFrame own = draw(waveMaterial(0.08, true));
  const WaveFrame made = draw(waveMaterial(0.08, true), false);
  EXPECT_EQ(own.primitives, made.primitives);
  EXPECT_LT(coverageDifference(own.image, made.image), 10);
}

TEST_F(GeoTextureWave, DisplacementMovesTheSilhouetteBumpsDoNot) {
  const WaveFrame still = draw(waveMaterial(0.0, true));
  const WaveFrame displaced = draw(waveMaterial(0.08, true));
  const WaveFrame bumped = draw(waveMaterial(0.08, false));
  EXPECT_GT(coverageDifference(still.image, displaced.image), 60) << "the displaced silhouette waves";
  EXPECT_LT(coverageDifference(still.image, bumped.image), 5) << "bump mapping keeps the silhouette";
  auto shading = compareImages(still.image, bumped.image, 0.05);
  ASSERT_TRUE(shading.isOk());
  EXPECT_GT(shading->percentOver, 1.0) << "but bumps change the shading";
}

// The wave of C.6.3, whose amplitude and frequency fall with the distance, against its closed form
// (formats/geodesic-material.md): on the unit sphere alone (object radius 1), seen down the field's
// axis, the displaced surface is a surface of revolution r(theta) = 1 + h(theta / pi), so its outline
// is a circle whose radius is the largest angle any point subtends at the eye. The frame's covered
// area gives the drawn radius in pixels.
double smoothStep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}
double fadingWave(double d, double amplitude, double wavelength, double reach, double front, bool fade = true) {
  const double envelope = smoothStep(front - reach, front - 0.6 * reach, d) * (1 - smoothStep(front - 0.15 * reach, front, d));
  const double falloff = fade ? 1 - std::clamp(d, 0.0, 1.0) : 1.0;
  return amplitude * falloff * envelope * std::sin(2 * std::numbers::pi * (d - front) * falloff / wavelength);
}
double outlineRadiusPixels(const std::function<double(double)>& height) {
  double widest = 0;
  for (int k = 0; k <= 200000; ++k) {
    const double theta = std::numbers::pi * k / 200000;
    const double r = 1 + height(theta / std::numbers::pi);
    widest = std::max(widest, std::atan2(r * std::sin(theta), kEye - r * std::cos(theta)));
  }
  return std::tan(widest) / std::tan(kFov / 2) * kSize / 2;
}

TEST_F(GeoTextureWave, OutlineFollowsTheClosedFormOfTheFadingWave) {
  constexpr double kAmplitude = 0.08, kWavelength = 0.06, kReach = 0.3, kFront = 0.45;
  const nlohmann::json material = geoMaterial("wave-displacement", {{"fields", {0}},
                                                                    {"thresholds", {kFront}},
                                                                    {"wave",
                                                                     {{"amplitude", kAmplitude},
                                                                      {"wavelength", kWavelength},
                                                                      {"reach", kReach},
                                                                      {"displace", true},
                                                                      {"pixelsPerEdge", 2},
                                                                      {"maxLevel", 64}}}});
  const WaveFrame frame = draw(material, true, false);
  int covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      covered += std::fabs(frame.image.at(x, y, 2) - frame.image.at(0, 0, 2)) > 1e-4f ||
                         std::fabs(frame.image.at(x, y, 0) - frame.image.at(0, 0, 0)) > 1e-4f
                     ? 1
                     : 0;
  const double drawn = std::sqrt(covered / std::numbers::pi);
  const double expected = outlineRadiusPixels([&](double d) { return fadingWave(d, kAmplitude, kWavelength, kReach, kFront); });
  const double constantPacket =
      outlineRadiusPixels([&](double d) { return fadingWave(d, kAmplitude, kWavelength, kReach, kFront, false); });
  const double undisplaced = outlineRadiusPixels([](double) { return 0.0; });
  RecordProperty("drawnRadiusPixels", std::to_string(drawn));
  RecordProperty("closedFormRadiusPixels", std::to_string(expected));
  RecordProperty("constantPacketRadiusPixels", std::to_string(constantPacket));
  // The three outlines are told apart, and the frame's is the fading wave's.
  ASSERT_GT(std::abs(expected - constantPacket), 1.0);
  ASSERT_GT(std::abs(expected - undisplaced), 1.0);
  EXPECT_NEAR(drawn, expected, 0.3) << "constant packet " << constantPacket << ", undisplaced " << undisplaced;
}

// C.6.4: with an environment map the wave preset shows the environment along the reflected view.
// The map holds a smooth colour of the direction, so the reference is its closed form at the
// direction the exact sphere reflects each pixel's ray to; the light is behind the sphere (no
// highlight on the visible side) and the wave's amplitude 0 (no bumps).
Vec3 environmentColour(const Vec3& direction) {
  return {0.1f + 0.4f * (1 + direction[0]), 0.1f + 0.4f * (1 + direction[1]), 0.1f + 0.4f * (1 + direction[2])};
}

TEST(GeoTextureEnvironment, ReflectionFollowsTheClosedForm) {
  const fs::path dir = test::freshTempDir("environment_map");
  Image environment;
  environment.width = 512;
  environment.height = 256;
  environment.channels = 3;
  for (int y = 0; y < environment.height; ++y)
    for (int x = 0; x < environment.width; ++x) {
      // The inverse of the stated mapping at the texel's centre: u = 0.5 + atan2(x, -z) / 2 pi, v = acos(y) / pi.
      const double phi = ((x + 0.5) / environment.width - 0.5) * 2 * std::numbers::pi;
      const double theta = (y + 0.5) / environment.height * std::numbers::pi;
      const Vec3 c = environmentColour(
          {float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(-std::sin(theta) * std::cos(phi))});
      environment.pixels.insert(environment.pixels.end(), c.begin(), c.end());
    }
  const Status written = writeImage(dir / "room.exr", environment, PixelType::Half);
  ASSERT_TRUE(written.isOk()) << written.describe();

  const nlohmann::json material =
      geoMaterial("wave-displacement", {{"fields", {0}}, {"wave", {{"amplitude", 0.0}, {"displace", false}}}});
  const fs::path file = writePackage(spherePackage(material, Encoding::Float, false), "environment");
  RenderSettings settings;
  settings.view.scenes = {file.string()};
  settings.view.width = settings.view.height = kSize;
  settings.view.camera = "0,0," + std::to_string(kEye) + ":0,0,0";
  settings.view.light = "0,0,-1";
  settings.view.environmentMap = (dir / "room.exr").string();
  settings.output = (dir / "reflection.exr").string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  ASSERT_TRUE(status.isOk()) << status.describe();
  auto image = readImage(settings.output);
  ASSERT_TRUE(image.isOk()) << image.status().describe();

  int compared = 0;
  double worst = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto hit = unitSphereHit(x, y);
      if (!hit) continue;
      const Vec3 n = normalize(*hit), view = normalize(Vec3{0, 0, kEye} - *hit);
      const Vec3 reflected = n * (2 * dot(n, view)) - view;
      const Vec3 expected = environmentColour(reflected);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::fabs(image->at(x, y, c) - expected[std::size_t(c)])));
      ++compared;
    }
  RecordProperty("comparedPixels", compared);
  RecordProperty("largestError", std::to_string(worst));
  EXPECT_GT(compared, 3000);
  // Interpolated vertex normals of the 40 x 80 sphere against the exact normal, and bilinear
  // filtering of the map, stay within this.
  EXPECT_LT(worst, 0.03);
}

// ---------------------------------------------------------------------------------------------
// Goldens: each preset with its defaults (BAKE_UPDATE_GOLDEN=1 rewrites them). The tolerance allows
// other Mesa versions to rasterise edges and round noise a little differently.

class GeoTextureGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(GeoTextureGolden, MatchesTheGoldenImage) {
  const std::string preset = GetParam();
  const Image image = renderPackage(spherePackage(geoMaterial(preset)), "golden_" + preset);
  const std::string golden = "runtime/geodesic-" + preset + ".v1.png";
  EXPECT_TRUE(test::matchesGoldenImage(image, golden));
}

INSTANTIATE_TEST_SUITE_P(Presets, GeoTextureGolden, ::testing::ValuesIn(geoPresetNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace bake::play
