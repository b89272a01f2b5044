#include <gtest/gtest.h>

#include <cmath>

#include "play/render.h"
#include "scene/scene.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

glb::Package trianglePackage() {
  glb::Primitive primitive;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  glb::Package package;
  package.meshes.push_back({"tri", {primitive}});
  return package;
}

bool noTechniques(const std::string&) { return false; }

TEST(Scene, TakesCameraAndLightFromTheFile) {
  glb::Package package = trianglePackage();
  package.cameras = nlohmann::json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 50}}}}});
  package.extensions["KHR_lights_punctual"] = {{"lights", {{{"type", "directional"}, {"color", {1.0, 0.5, 0.25}}}}}};
  glb::Node mesh{"mesh", 0, {}, std::nullopt};
  glb::Node camera{"camera", -1, {}, std::nullopt};
  camera.translation = {0, 0, 5};
  camera.camera = 0;
  glb::Node sun{"sun", -1, {}, std::nullopt};
  sun.rotation = {-0.70710678, 0, 0, 0.70710678};  // -90 degrees about x: local -Z points down
  sun.extensions["KHR_lights_punctual"] = {{"light", 0}};
  package.nodes = {mesh, camera, sun};
  const fs::path dir = test::freshTempDir("scene_camera");
  ASSERT_TRUE(glb::write(dir / "scene.glb", package).isOk());

  Diagnostics diagnostics("test", true);
  auto scene = loadScene({dir / "scene.glb"}, diagnostics, noTechniques);
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  ASSERT_TRUE(scene->fileCamera.has_value());
  EXPECT_FLOAT_EQ(scene->fileCamera->eye[2], 5.0f);
  EXPECT_NEAR(scene->fileCamera->target[2], 4.0f, 1e-6);  // looking down -Z
  EXPECT_FLOAT_EQ(scene->fileCamera->yfov, 0.5f);
  ASSERT_TRUE(scene->fileLight.has_value());
  EXPECT_NEAR(scene->fileLight->direction[1], 1.0f, 1e-6);  // shines down, so the light is above
  EXPECT_FLOAT_EQ(scene->fileLight->colour[1], 0.5f);
  EXPECT_EQ(scene->instances.size(), 1u);
  EXPECT_EQ(scene->boundsMax[0], 1.0f);
}

TEST(Scene, MalformedCamerasAndLightsAreIgnoredNotThrown) {
  // Each part of a camera or light of the wrong JSON type: the scene loads without them.
  const std::vector<std::pair<nlohmann::json, nlohmann::json>> cases = {
      {nlohmann::json::array({{{"type", "perspective"}, {"perspective", 5}}}), {{"lights", {{{"type", "directional"}}}}}},
      {nlohmann::json::array({{{"type", 7}, {"perspective", {{"yfov", "wide"}}}}}), {{"lights", 3}}},
      {nlohmann::json::array({{{"type", "perspective"}, {"perspective", {{"yfov", "wide"}}}}}),
       {{"lights", {{{"type", "directional"}, {"color", {"red", 0, 0}}}}}}},
      {nlohmann::json::array({"camera"}), "lights"},
  };
  for (std::size_t c = 0; c < cases.size(); ++c) {
    SCOPED_TRACE("case " + std::to_string(c));
    glb::Package package = trianglePackage();
    package.cameras = cases[c].first;
    package.extensions["KHR_lights_punctual"] = cases[c].second;
    glb::Node mesh{"mesh", 0, {}, std::nullopt};
    glb::Node camera{"camera", -1, {}, std::nullopt};
    camera.camera = 0;
    glb::Node sun{"sun", -1, {}, std::nullopt};
    sun.extensions["KHR_lights_punctual"] = {{"light", c == 3 ? nlohmann::json("first") : nlohmann::json(0)}};
    package.nodes = {mesh, camera, sun};
    const fs::path dir = test::freshTempDir("scene_malformed_camera");
    ASSERT_TRUE(glb::write(dir / "scene.glb", package).isOk());
    Diagnostics diagnostics("test", true);
    auto scene = loadScene({dir / "scene.glb"}, diagnostics, noTechniques);
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    EXPECT_EQ(scene->instances.size(), 1u);
    if (c == 2) {
      // A perspective camera with a bad yfov keeps the default; a light with a bad colour stays white.
      ASSERT_TRUE(scene->fileCamera.has_value());
      EXPECT_FLOAT_EQ(scene->fileCamera->yfov, 0.7f);
      ASSERT_TRUE(scene->fileLight.has_value());
      EXPECT_FLOAT_EQ(scene->fileLight->colour[0], 1.0f);
    } else {
      EXPECT_FALSE(scene->fileCamera.has_value()) << "only a perspective object makes a camera";
    }
  }
}

TEST(Scene, UnknownExtensionsWarnOrFailWhenRequired) {
  glb::Package package = trianglePackage();
  package.extensions["BAKE_future"] = {{"version", 1}};
  const fs::path dir = test::freshTempDir("scene_extensions");
  ASSERT_TRUE(glb::write(dir / "optional.glb", package).isOk());
  package.extensionsRequired = {"BAKE_future"};
  ASSERT_TRUE(glb::write(dir / "required.glb", package).isOk());

  Diagnostics diagnostics("test", true);
  ASSERT_TRUE(loadScene({dir / "optional.glb"}, diagnostics, noTechniques).isOk());
  EXPECT_EQ(diagnostics.warnings().at("unknown-extension").count, 1);
  const auto required = loadScene({dir / "required.glb"}, diagnostics, noTechniques);
  EXPECT_EQ(required.status().code(), ExitCode::Unsupported);
  EXPECT_NE(required.status().message().find("BAKE_future"), std::string::npos);
  EXPECT_TRUE(loadScene({dir / "required.glb"}, diagnostics, [](const std::string& e) { return e == "BAKE_future"; }).isOk());
}

TEST(Scene, SeveralFilesMakeOneScene) {
  const fs::path dir = test::freshTempDir("scene_files");
  ASSERT_TRUE(glb::write(dir / "a.glb", trianglePackage()).isOk());
  glb::Package moved = trianglePackage();
  moved.nodes.push_back(glb::Node{"moved", 0, {}, std::nullopt});
  moved.nodes[0].translation = {10, 0, 0};
  ASSERT_TRUE(glb::write(dir / "b.glb", moved).isOk());
  Diagnostics diagnostics("test", true);
  auto scene = loadScene({dir / "a.glb", dir / "b.glb"}, diagnostics, noTechniques);
  ASSERT_TRUE(scene.isOk());
  EXPECT_EQ(scene->instances.size(), 2u);
  EXPECT_FLOAT_EQ(scene->boundsMax[0], 11.0f);
}

TEST(Scene, CommandLineViewsAreParsedStrictly) {
  const Scene scene = defaultScene();
  auto camera = parseCamera("1,2,3:0,0,0", scene, 1.0f);
  ASSERT_TRUE(camera.isOk());
  EXPECT_EQ(camera->eye, (Vec3{1, 2, 3}));
  EXPECT_EQ(parseCamera("1,2", scene, 1.0f).status().code(), ExitCode::Usage);
  EXPECT_EQ(parseCamera("0,0,0:0,0,0", scene, 1.0f).status().code(), ExitCode::Usage);
  EXPECT_EQ(parseCamera("1,2,nan", scene, 1.0f).status().code(), ExitCode::Usage);
  auto light = parseLight("0,3,4");
  ASSERT_TRUE(light.isOk());
  EXPECT_FLOAT_EQ(light->direction[2], 0.8f);
  EXPECT_EQ(parseLight("0,0,0").status().code(), ExitCode::Usage);
  ViewSettings view;
  EXPECT_TRUE(parseSize("640x360", view).isOk());
  EXPECT_EQ(view.width, 640);
  EXPECT_EQ(parseSize("640", view).code(), ExitCode::Usage);
  EXPECT_EQ(parseSize("0x10", view).code(), ExitCode::Usage);
  EXPECT_EQ(parseSize("10x10junk", view).code(), ExitCode::Usage);
}

TEST(Scene, FramedCameraSeesTheWholeScene) {
  const Scene scene = defaultScene();
  const Camera camera = frameBounds(scene, 1.0f);
  const Vec3 centre = (scene.boundsMin + scene.boundsMax) * 0.5f;
  const float radius = length(scene.boundsMax - scene.boundsMin) * 0.5f;
  const float distance = length(camera.eye - centre);
  EXPECT_GE(std::asin(radius / distance), 0.0f);
  EXPECT_LE(std::asin(radius / distance), camera.yfov / 2 + 1e-5f);  // the bounding sphere fits the view
  EXPECT_LT(camera.znear, distance - radius);
  EXPECT_GT(camera.zfar, distance + radius);
}

TEST(Percentiles, NearestRank) {
  EXPECT_EQ(percentiles({}).median, 0.0);
  const Percentiles p = percentiles({5, 1, 4, 2, 3, 6, 7, 8, 9, 10});
  EXPECT_EQ(p.median, 5.0);
  EXPECT_EQ(p.p95, 10.0);
}

}  // namespace
}  // namespace bake::play
