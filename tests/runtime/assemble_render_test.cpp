// Scene packages made by `bakepipe assemble` (pipe/assemble.h) in the runtime: leaving out what no
// material reads must not change a pixel. For a geodesic torus that reads one of three fields, a
// revolved vase whose material reads no displacement map beside a hatched torus (no threshold
// texture), and two groove plates (one reading special cases, one not), the pruned and the
// keep-unused packages are rendered by `bakeplay render`'s entry point and must be identical
// (largest channel difference 0), the pruned file smaller, and both must pass `bakeplay validate`.
// (bakeplay's groove shader does not area-sample special cases yet, so at this view the records
// change no pixel even where a material reads them, measured; the groove case mostly guards the
// layout of the emptied record arrays and that each plate of one package draws with its own grid.)
#include <gtest/gtest.h>

#include <cstdio>

#include "bake/core/diagnostics.h"
#include "bake/io/image.h"
#include "io/image_compare.h"
#include "pipe/assemble.h"
#include "pipe/assemble_support.h"
#include "play/render.h"
#include "play/validate.h"
#include "support/golden.h"

namespace bake::play {
namespace {

namespace fs = std::filesystem;

// This file's variants of the baked inputs (pipe/assemble_support.h): tori of resolution 16 (the
// geodesic and the hatched one), and a larger TAM tiled twice per object unit.
const test::TorusFieldsOptions kTorusFields{.torusResolution = 16, .sourceStep = 40};
const test::HatchedTorusOptions kHatchedTorus{
    .torusResolution = 16, .style = R"({"tones": 4, "resolution": 64, "levels": 2, "candidates": 4})", .tilesPerUnit = 2};

struct Rendered {
  Image image;
  std::uintmax_t bytes = 0;
};

// Assembles, writes and renders the scene; the image (sRGB PNG read back) and the file size.
Rendered assembleAndRender(const pipe::Scene& scene, const std::vector<fs::path>& packages, bool keepUnused,
                           const fs::path& file, const std::string& camera) {
  pipe::AssembleSettings settings;
  settings.keepUnused = keepUnused;
  auto assembled = pipe::assemble(scene, packages, settings);
  EXPECT_TRUE(assembled.isOk()) << assembled.status().describe();
  if (!assembled.isOk()) return {};
  EXPECT_TRUE(glb::write(file, *assembled).isOk());
  RenderSettings render;
  render.view.scenes = {file.string()};
  render.view.width = 160;
  render.view.height = 120;
  render.view.camera = camera;
  render.view.light = "0.3,0.5,1";
  render.output = fs::path(file).replace_extension(".png").string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(render, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  auto image = readImage(render.output);
  EXPECT_TRUE(image.isOk()) << image.status().describe();
  return {image.isOk() ? *image : Image{}, fs::file_size(file)};
}

Status validate(const fs::path& file, std::string& verdicts) {
  ValidateSettings settings;
  settings.size = 32;
  settings.common.quiet = true;
  settings.packages = {file.string()};
  Diagnostics diagnostics("bakeplay", true);
  std::FILE* out = std::tmpfile();
  const Status status = runValidate(settings, diagnostics, out);
  std::rewind(out);
  char line[4096];
  while (std::fgets(line, sizeof line, out)) verdicts += line;
  std::fclose(out);
  return status;
}

// Renders both assemblies; they must match exactly, the pruned one be smaller, and both validate.
void expectSameImageSmallerFile(const pipe::Scene& scene, const std::vector<fs::path>& packages, const fs::path& dir,
                                const std::string& camera) {
  const Rendered pruned = assembleAndRender(scene, packages, false, dir / "pruned.glb", camera);
  const Rendered kept = assembleAndRender(scene, packages, true, dir / "kept.glb", camera);
  auto difference = compareImages(pruned.image, kept.image, 0.0);
  ASSERT_TRUE(difference.isOk()) << difference.status().describe();
  EXPECT_EQ(difference->maxError, 0.0) << describe(*difference);
  EXPECT_LT(pruned.bytes, kept.bytes);
  ::testing::Test::RecordProperty("prunedBytes", std::to_string(pruned.bytes));
  ::testing::Test::RecordProperty("keptBytes", std::to_string(kept.bytes));
  // The picture shows something: not a single flat colour.
  float lo = 1, hi = 0;
  for (float v : pruned.image.pixels) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GT(hi - lo, 0.2f);
  for (const char* name : {"pruned.glb", "kept.glb"}) {
    std::string verdicts;
    const Status status = validate(dir / name, verdicts);
    EXPECT_TRUE(status.isOk()) << name << ": " << status.describe() << "\n" << verdicts;
  }
}

TEST(AssembleRender, GeodesicFieldsLeftOutDoNotChangeThePicture) {
  const fs::path dir = test::freshTempDir("assemble_render_geodesic");
  pipe::Scene scene;
  pipe::Object torus = test::objectOf("torus", "geodesic");
  torus.fieldNames = {"a", "b", "c"};
  torus.position = {0.5, 0, 0};
  scene.objects = {torus};
  pipe::Material sand = test::materialOf("sand", "geodesic");
  sand.fields = {"b"};
  sand.geotexture = {{"version", 1}, {"texture", "isolines"}, {"fields", {"b"}}};
  scene.materials = {sand};
  expectSameImageSmallerFile(scene, {test::bakeTorusFields(dir, kTorusFields)}, dir, "0.5,2,3:0.5,0,0");
}

TEST(AssembleRender, DisplacementAndThresholdLeftOutDoNotChangeThePicture) {
  const fs::path dir = test::freshTempDir("assemble_render_revolution_hatching");
  pipe::Scene scene;
  pipe::Object vase = test::objectOf("vase", "revolution");
  vase.position = {-0.8, -0.5, 0};
  pipe::Object torus = test::objectOf("torus", "hatching", 1);
  torus.position = {0.8, 0, 0};
  torus.scale = 0.6;
  scene.objects = {vase, torus};
  pipe::Material smooth = test::materialOf("smooth", "revolution");
  smooth.readsDisplacement = false;
  scene.materials = {smooth, test::materialOf("ink", "hatching")};
  const std::vector<fs::path> packages = {test::bakeVase(dir, {.resolution = 128, .heightScale = 0.02}),
                                          test::bakeHatchedTorus(dir, kHatchedTorus)};
  expectSameImageSmallerFile(scene, packages, dir, "0,1,3.5:0,0,0");
}

TEST(AssembleRender, GrooveRecordsLeftOutDoNotChangeThePicture) {
  const fs::path dir = test::freshTempDir("assemble_render_grooves");
  pipe::Scene scene;
  for (const char* name : {"near", "far"}) {
    pipe::Object plate = test::objectOf(name, "grooves", scene.objects.size());
    plate.position = {scene.objects.empty() ? -10.5 : 0.5, -5, 0};
    scene.objects.push_back(plate);
    pipe::Material material = test::materialOf(name, "grooves");
    material.readsSpecialCases = scene.objects.size() == 1;  // "near" reads them, "far" does not
    scene.materials.push_back(material);
  }
  test::GroovePlateOptions plate{.halfWidth = 0.4, .depth = 0.3, .lineStart = 0.5, .albedo = {0.7, 0.3, 0.2}};
  const fs::path nearPlate = test::bakeGroovePlate(dir, "near-plate", plate);
  plate.albedo = {0.2, 0.3, 0.7};
  const std::vector<fs::path> packages = {nearPlate, test::bakeGroovePlate(dir, "far-plate", plate)};
  const std::string camera = "0,-6,16:0,0,0";
  expectSameImageSmallerFile(scene, packages, dir, camera);

  // Each plate draws with its own grid and materials (one package, two groove materials): the
  // reddish plate on the left, the bluish one on the right.
  const Rendered pruned = assembleAndRender(scene, packages, false, dir / "pruned.glb", camera);
  const Image& image = pruned.image;
  ASSERT_GE(image.channels, 3);
  double left[3] = {0, 0, 0}, right[3] = {0, 0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) (x < image.width / 2 ? left : right)[c] += image.at(x, y, c);
  EXPECT_GT(left[0], left[2]);
  EXPECT_GT(right[2], right[0]);
}

}  // namespace
}  // namespace bake::play
