// The scene description reader (pipe/scene.h): the example scenes, and errors that name the element.
#include <gtest/gtest.h>

#include <algorithm>

#include "pipe/scene.h"
#include "pipe/technique_hooks.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kGeodesic = std::string(BAKE_SOURCE_DIR) + "/pipelines/geodesic/";

json geodesicScene() {
  return {{"version", 1},
          {"objects", {{{"name", "p"}, {"technique", "geodesic"}, {"input", kGeodesic + "sources.json"},
                        {"sources", kGeodesic + "sources.json"}, {"material", "m"}}}},
          {"materials", {{{"name", "m"}, {"technique", "geodesic"}, {"geotexture", {{"fields", {"rims"}}}}}}}};
}

// The error of parsing `document`: its element and a fragment of its message.
void expectError(const json& document, const std::string& element, const std::string& fragment) {
  const Result<Scene> scene = parseScene(document, fs::path(BAKE_TEST_TMP) / "scene.json");
  ASSERT_FALSE(scene.isOk()) << document.dump();
  EXPECT_EQ(scene.status().code(), ExitCode::InvalidInput);
  EXPECT_EQ(scene.status().where().element, element) << scene.status().describe();
  EXPECT_NE(scene.status().message().find(fragment), std::string::npos) << scene.status().describe();
}

TEST(PipeScene, ReadsTheExampleScenes) {
  // Every example folder with a scene (one per technique in the registry: none is left out).
  std::size_t scenes = 0;
  for (const fs::directory_entry& folder : fs::directory_iterator(fs::path(BAKE_SOURCE_DIR) / "pipelines")) {
    const fs::path file = folder.path() / "scene.json";
    if (!fs::exists(file)) continue;
    const Result<Scene> scene = readScene(file);
    ASSERT_TRUE(scene.isOk()) << scene.status().describe();
    EXPECT_EQ(scene->name, folder.path().filename().string());
    EXPECT_FALSE(scene->objects.empty());
    ++scenes;
  }
  EXPECT_EQ(scenes, sceneTechniques().size());
  const Result<Scene> geodesic = readScene(kGeodesic + "scene.json");
  ASSERT_TRUE(geodesic.isOk());
  EXPECT_EQ(geodesic->objects[0].fieldNames, (std::vector<std::string>{"left tip", "right tip", "rims"}));
  EXPECT_EQ(geodesic->fieldsRead(geodesic->objects[0]), (std::vector<std::string>{"left tip"}));
  EXPECT_TRUE(geodesic->objects[0].input.generated);
  // Grooves: the record turned by its rotation, the column drawn on a generated mesh.
  const Result<Scene> grooves = readScene(fs::path(BAKE_SOURCE_DIR) / "pipelines/grooves/scene.json");
  ASSERT_TRUE(grooves.isOk()) << grooves.status().describe();
  const auto named = [&](const std::string& name) {
    return *std::find_if(grooves->objects.begin(), grooves->objects.end(), [&](const Object& o) { return o.name == name; });
  };
  EXPECT_NEAR(named("record").rotation[1], -0.130526, 1e-6);
  EXPECT_EQ(named("tiles").rotation, (std::array<double, 4>{0, 0, 0, 1}));
  ASSERT_TRUE(named("column").mesh.has_value());
  EXPECT_TRUE(named("column").mesh->generated);
  // Hatching: lit by a spot light.
  const Result<Scene> hatching = readScene(fs::path(BAKE_SOURCE_DIR) / "pipelines/hatching/scene.json");
  ASSERT_TRUE(hatching.isOk()) << hatching.status().describe();
  ASSERT_EQ(hatching->lights.size(), 1u);
  EXPECT_EQ(hatching->lights[0].type, "spot");
  EXPECT_EQ(hatching->lights[0].cutoffDegrees, 38);
  EXPECT_EQ(hatching->lights[0].exponent, 6);
  EXPECT_FALSE(named("plate").mesh.has_value());
}

TEST(PipeScene, DefaultFieldIsTheFirst) {
  json document = geodesicScene();
  document["materials"][0].erase("geotexture");
  const Result<Scene> scene = parseScene(document, fs::path(BAKE_TEST_TMP) / "scene.json");
  ASSERT_TRUE(scene.isOk()) << scene.status().describe();
  EXPECT_EQ(scene->fieldsRead(scene->objects[0]), (std::vector<std::string>{"left tip"}));
}

TEST(PipeScene, ErrorsNameTheElement) {
  expectError({{"version", 1}, {"materials", json::array()}}, "/objects", "is missing");
  expectError({{"version", 2}, {"objects", json::array()}, {"materials", json::array()}}, "/version", "must be 1");
  json typo = geodesicScene();
  typo["objects"][0]["postion"] = {0, 0, 0};
  expectError(typo, "/objects/0/postion", "did you mean \"position\"");
  json field = geodesicScene();
  field["materials"][0]["geotexture"]["fields"] = {"nose"};
  expectError(field, "/materials/0/geotexture/fields/0", "no field \"nose\"");
  json technique = geodesicScene();
  technique["materials"][0]["technique"] = "grooves";
  technique["materials"][0].erase("geotexture");
  expectError(technique, "/objects/0/material", "is a grooves material");
  json missing = geodesicScene();
  missing["objects"][0]["input"] = "no-such-mesh.obj";
  expectError(missing, "/objects/0/input", "is not a file");
  json name = geodesicScene();
  name["objects"][0]["name"] = "a/b";
  expectError(name, "/objects/0/name", "letters, digits");
  json twice = geodesicScene();
  twice["objects"].push_back(twice["objects"][0]);
  expectError(twice, "/objects/1/name", "names two objects");
  json nan = geodesicScene();
  nan["objects"][0]["scale"] = -1;
  expectError(nan, "/objects/0/scale", "must be positive");
  json reads = geodesicScene();
  reads["materials"][0]["reads"] = {{"threshold", true}};
  expectError(reads, "/materials/0/reads/threshold", "hatching materials only");
  json mesh = geodesicScene();
  mesh["objects"][0]["mesh"] = kGeodesic + "sources.json";
  expectError(mesh, "/objects/0/mesh", "is for hatching and grooves objects only");
  json rotation = geodesicScene();
  rotation["objects"][0]["rotation"] = {0, 0, 0, 2};
  expectError(rotation, "/objects/0/rotation", "length is 2");
  rotation["objects"][0]["rotation"] = {0, 0, 1};
  expectError(rotation, "/objects/0/rotation", "unit quaternion [x, y, z, w]");
  json camera = geodesicScene();
  camera["cameras"] = {{{"eye", {0, 0, 1}}, {"target", {0, 0, 1}}, {"yfov", 40}, {"width", 64}, {"height", 64}}};
  expectError(camera, "/cameras/0/target", "must differ from the eye");
  json light = geodesicScene();
  light["lights"] = {{{"type", "area"}, {"position", {0, 1, 0}}}};
  expectError(light, "/lights/0/type", "known: directional, point, spot");
  light["lights"] = {{{"type", "spot"}, {"position", {0, 1, 0}}}};
  expectError(light, "/lights/0/target", "a spot light shines toward it");
  light["lights"] = {{{"type", "point"}, {"position", {0, 1, 0}}, {"cutoff", 30}}};
  expectError(light, "/lights/0", "a point light takes no target, cutoff or exponent");
  light["lights"] = {{{"type", "spot"}, {"position", {0, 1, 0}}, {"target", {0, 0, 0}}, {"cutoff", 120}}};
  expectError(light, "/lights/0/cutoff", "at most 90 degrees");
  light["lights"] = {{{"type", "directional"}, {"position", {0, 1, 0}}, {"target", {0, 0, 0}}, {"exponent", 2}}};
  expectError(light, "/lights/0", "only a spot light takes a cutoff and an exponent");
}

TEST(PipeScene, UnreadableFilesAreIoErrors) {
  const Result<Scene> missing = readScene(fs::path(BAKE_TEST_TMP) / "no-such-scene.json");
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), ExitCode::Io);
  const Result<Scene> directory = readScene(BAKE_SOURCE_DIR);
  ASSERT_FALSE(directory.isOk());
  EXPECT_EQ(directory.status().code(), ExitCode::Io);
}

}  // namespace
}  // namespace bake::pipe
