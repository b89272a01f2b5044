#include <gtest/gtest.h>

#include "bake/core/atomic_file.h"
#include "bake/io/image.h"
#include "io/image_compare.h"
#include "play/render.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

Image renderExample(const fs::path& file, int width = 256, int height = 192) {
  RenderSettings settings;
  settings.view.width = width;
  settings.view.height = height;
  settings.output = file.string();
  Diagnostics diagnostics("bakeplay", true);
  const Status status = runRender(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  auto image = readImage(file);
  EXPECT_TRUE(image.isOk());
  return image.isOk() ? *image : Image{};
}

// The bundled example scene against its golden picture (BAKE_UPDATE_GOLDEN=1 rewrites it). The
// tolerance allows for other Mesa versions rasterising edges a little differently.
TEST(ExampleScene, MatchesTheGoldenImage) {
  const fs::path dir = test::freshTempDir("example_scene");
  const Image image = renderExample(dir / "example.png");
  const std::string golden = "runtime/example-scene.v1.png";
  if (test::updatingGoldens()) {
    fs::create_directories(test::goldenPath(golden).parent_path());
    fs::copy_file(dir / "example.png", test::goldenPath(golden), fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "updated " << golden;
  }
  auto expected = readImage(test::goldenPath(golden));
  ASSERT_TRUE(expected.isOk()) << expected.status().describe();
  auto difference = compareImages(image, *expected, 0.1);
  ASSERT_TRUE(difference.isOk()) << difference.status().describe();
  EXPECT_TRUE(withinTolerance(*difference, {0.01, 0.1, 0.5})) << describe(*difference);
}

TEST(ExampleScene, RenderingIsDeterministic) {
  const fs::path dir = test::freshTempDir("example_twice");
  renderExample(dir / "a.png");
  renderExample(dir / "b.png");
  EXPECT_EQ(test::readAll(dir / "a.png"), test::readAll(dir / "b.png"));
  RenderSettings settings;
  settings.output = (dir / "a.exr").string();
  settings.view.width = settings.view.height = 64;
  Diagnostics diagnostics("bakeplay", true);
  ASSERT_TRUE(runRender(settings, diagnostics).isOk());
  auto exr = readImage(dir / "a.exr");
  ASSERT_TRUE(exr.isOk());
  EXPECT_EQ(exr->sourceType, PixelType::Half);
}

TEST(ExampleScene, BadOutputsAreRefused) {
  const fs::path dir = test::freshTempDir("example_bad");
  RenderSettings settings;
  Diagnostics diagnostics("bakeplay", true);
  settings.output = (dir / "frame.jpg").string();
  EXPECT_EQ(runRender(settings, diagnostics).code(), ExitCode::Usage);
  settings.output = (dir / "missing" / "frame.png").string();
  EXPECT_EQ(runRender(settings, diagnostics).code(), ExitCode::Io);
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

// `bakeplay view` in a real window under Xvfb: after a few frames its screenshot must show the same
// picture as `render` (both share the renderer and the sRGB encoding).
TEST(ExampleScene, WindowShowsTheSamePictureUnderXvfb) {
  const fs::path dir = test::freshTempDir("example_window");
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null"), 0) << "xvfb-run is missing: run scripts/setup.sh";
  const std::string command = std::string("xvfb-run -a -s '-screen 0 640x480x24' '") + BAKEPLAY_PATH +
                              "' view --size 160x120 --frames 3 --screenshot '" + (dir / "window.png").string() + "' -q";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Image rendered = renderExample(dir / "render.png", 160, 120);
  auto window = readImage(dir / "window.png");
  ASSERT_TRUE(window.isOk()) << window.status().describe();
  auto difference = compareImages(*window, rendered, 2.5 / 255.0);
  ASSERT_TRUE(difference.isOk()) << difference.status().describe();
  EXPECT_LE(difference->maxError, 2.5 / 255.0) << describe(*difference);
}

// Leaving out what a scene does not use: a scene without normals compiles no HAS_NORMALS variant
// and uploads no normals; the report lists exactly the variants compiled.
TEST(ExampleScene, OnlyTheVariantsTheSceneUsesAreCompiled) {
  const fs::path dir = test::freshTempDir("variants");
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  primitive.attributes.push_back(glb::Attribute::fromFloats("_UNUSED_0", 1, std::vector<float>{1, 2, 3}));
  glb::Package package;
  package.meshes.push_back({"flat", {primitive}});
  ASSERT_TRUE(glb::write(dir / "flat.glb", package).isOk());

  RenderSettings settings;
  settings.view.scenes = {(dir / "flat.glb").string()};
  settings.view.width = settings.view.height = 32;
  settings.output = (dir / "flat.png").string();
  settings.common.reportPath = (dir / "report.json").string();
  Diagnostics diagnostics("bakeplay", true);
  ASSERT_TRUE(runRender(settings, diagnostics).isOk());
  const auto bytes = test::readAll(dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(bytes.begin(), bytes.end());
  EXPECT_EQ(report["statistics"]["shaderVariants"], nlohmann::json::array({"standard/mesh.vert+standard/mesh.frag[]"}));
  EXPECT_EQ(report["statistics"]["gpuBytes"], 3 * 12) << "only POSITION is uploaded";
}

}  // namespace
}  // namespace bake::play
