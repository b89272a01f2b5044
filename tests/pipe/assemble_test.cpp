// Scene assembly (pipe/assemble.h): packages baked with the bakers' library entry points
// (pipe/assemble_support.h: a geodesic torus with three fields, groove plates with and without
// special-case records, a revolved profile with a displacement map and a base colour) are merged,
// and the result is checked against the originals: node placement, counts, every extension index
// pointing at the same bytes as before, the renumbered geodesic fields, the dropped list, that
// keepUnused copies every baked byte while the materials still read only what the scene says, and
// that the checked readers accept the result.
#include <gtest/gtest.h>

#include <bake_formats/geodesic.h>
#include <bake_formats/grooves.h>
#include <bake_formats/revolution.h>
#include <bake_formats/tam.h>

#include <algorithm>
#include <cstring>

#include "bake/geodesic/bake.h"
#include "grooves/package/package.h"
#include "pipe/assemble.h"
#include "pipe/assemble_support.h"
#include "support/golden.h"

namespace bake::pipe {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
namespace geo = format::geodesic;
namespace grv = format::grooves;
namespace rev = format::revolution;

using test::materialOf;
using test::objectOf;

// A torus reading field "b" (sand-water) and a groove plate without special cases.
Scene torusAndPlate() {
  Scene scene;
  scene.name = "mixed";
  Object torus = objectOf("torus", "geodesic", 0);
  torus.fieldNames = {"a", "b", "c"};
  torus.position = {1, 2, 3};
  torus.scale = 0.5;
  Object plate = objectOf("plate", "grooves", 1);
  plate.position = {-1, 0, 0};
  plate.rotation = {0, 0.6, 0, 0.8};
  scene.objects = {torus, plate};
  Material sand = materialOf("sand", "geodesic");
  sand.fields = {"b"};
  sand.geotexture = {{"version", 1}, {"texture", "sand-water"}, {"fields", {"b"}}, {"thresholds", {0.3}}};
  Material steel = materialOf("steel", "grooves");
  steel.readsSpecialCases = false;
  scene.materials = {sand, steel};
  return scene;
}

struct Inputs {
  fs::path dir, geodesic, grooves;
};

const Inputs& inputs() {
  static const Inputs baked = [] {
    Inputs in;
    in.dir = test::freshTempDir("assemble_inputs");
    in.geodesic = test::bakeTorusFields(in.dir);
    in.grooves = test::bakeGroovePlate(in.dir, "plate");
    return in;
  }();
  return baked;
}

glb::Package readBack(const fs::path& path) {
  auto package = glb::read(path);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  return package.isOk() ? *package : glb::Package{};
}

// The assembled package after a round trip through its bytes (what a reader sees).
glb::Package encodedAndRead(const glb::Package& package) {
  auto bytes = glb::encode(package);
  EXPECT_TRUE(bytes.isOk()) << bytes.status().describe();
  auto decoded = glb::decode(*bytes, "assembled.glb");
  EXPECT_TRUE(decoded.isOk()) << decoded.status().describe();
  return decoded.isOk() ? *decoded : glb::Package{};
}

// The package with only material `index` (the groove reader reads the last groove material).
glb::Package withOnlyMaterial(glb::Package package, std::size_t index) {
  package.materials = json::array({package.materials[index]});
  return package;
}

int materialNamed(const glb::Package& package, const std::string& name) {
  for (std::size_t m = 0; m < package.materials.size(); ++m)
    if (package.materials[m].value("name", "") == name) return int(m);
  return -1;
}

const glb::Attribute* attribute(const glb::Package& package, const std::string& mesh, const std::string& name) {
  for (const glb::Mesh& m : package.meshes)
    if (m.name == mesh) return m.primitives.at(0).find(name);
  return nullptr;
}

std::size_t blobBytes(const glb::Package& package) {
  std::size_t total = 0;
  for (const glb::Blob& blob : package.blobs) total += blob.bytes.size();
  return total;
}

TEST(PipeAssemble, PlacesEachObjectUnderItsNode) {
  const Scene scene = torusAndPlate();
  AssembleReport report;
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package& p = *assembled;
  ASSERT_EQ(p.sceneRoots.size(), 2u);
  const glb::Node& torus = p.nodes.at(std::size_t(p.sceneRoots[0]));
  const glb::Node& plate = p.nodes.at(std::size_t(p.sceneRoots[1]));
  EXPECT_EQ(torus.name, "torus");
  EXPECT_EQ(torus.translation, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(torus.scale, (std::array<double, 3>{0.5, 0.5, 0.5}));
  EXPECT_EQ(plate.name, "plate");
  EXPECT_EQ(plate.translation, (std::array<double, 3>{-1, 0, 0}));
  EXPECT_EQ(plate.rotation, (std::array<double, 4>{0, 0.6, 0, 0.8}));
  EXPECT_EQ(torus.rotation, (std::array<double, 4>{0, 0, 0, 1}));
  // Each object node holds its package's node, which draws that package's mesh.
  ASSERT_EQ(torus.children.size(), 1u);
  ASSERT_EQ(plate.children.size(), 1u);
  EXPECT_EQ(p.meshes.at(std::size_t(p.nodes.at(std::size_t(torus.children[0])).mesh)).name, "geodesic");
  EXPECT_EQ(p.meshes.at(std::size_t(p.nodes.at(std::size_t(plate.children[0])).mesh)).name, "groove domain");
  EXPECT_EQ(p.nodes.size(), 4u);
  EXPECT_EQ(p.meshes.size(), 2u);
  EXPECT_EQ(p.materials.size(), 2u);
  EXPECT_GT(report.inputBytes, fs::file_size(inputs().geodesic));
}

// The scene's camera becomes a glTF perspective camera on a root node at the eye, looking down its
// local -Z at the target, with +Y up as near the world's +Y as the view allows.
TEST(PipeAssemble, TheScenesCameraFramesTheAssembledScene) {
  Scene scene = torusAndPlate();
  Camera camera;
  camera.name = "front";
  camera.eye = {0, 3, 4};
  camera.target = {0, 0, 0};
  camera.yfovDegrees = 45;
  camera.width = 800;
  camera.height = 400;
  scene.cameras = {camera};
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {});
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package p = encodedAndRead(*assembled);
  ASSERT_EQ(p.cameras.size(), 1u);
  EXPECT_EQ(p.cameras[0]["type"], "perspective");
  EXPECT_NEAR(p.cameras[0]["perspective"]["yfov"].get<double>(), 45 * std::acos(-1.0) / 180, 1e-12);
  EXPECT_DOUBLE_EQ(p.cameras[0]["perspective"]["aspectRatio"].get<double>(), 2.0);
  ASSERT_EQ(p.sceneRoots.size(), 3u);
  const glb::Node& node = p.nodes.at(std::size_t(p.sceneRoots[2]));
  EXPECT_EQ(node.name, "front");
  EXPECT_EQ(node.camera, 0);
  const std::array<double, 16> m = node.localMatrix();
  EXPECT_NEAR(m[12], 0, 1e-12);  // translation: the eye
  EXPECT_NEAR(m[13], 3, 1e-12);
  EXPECT_NEAR(m[14], 4, 1e-12);
  EXPECT_NEAR(-m[8], 0, 1e-12);  // -Z: towards the target, (0, -3, -4) / 5
  EXPECT_NEAR(-m[9], -0.6, 1e-12);
  EXPECT_NEAR(-m[10], -0.8, 1e-12);
  EXPECT_NEAR(m[0], 1, 1e-12);  // +X: to the right, level
  EXPECT_NEAR(m[5], 0.8, 1e-12);  // +Y: up, tilted with the view
}

// The scene's lights as KHR_lights_punctual lights, each on a node pointing down -Z at its target;
// the spot's cone and OpenGL exponent where bakeplay reads them.
TEST(PipeAssemble, TheScenesLightsBecomePunctualLights) {
  Scene scene = torusAndPlate();
  SceneLight spot;
  spot.name = "lamp";
  spot.type = "spot";
  spot.position = {0, 3, 4};
  spot.target = {0, 0, 0};
  spot.cutoffDegrees = 30;
  spot.exponent = 5;
  SceneLight point;
  point.type = "point";
  point.position = {1, 2, 3};
  point.colour = {1, 0.5, 0.25};
  scene.lights = {spot, point};
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {});
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package p = encodedAndRead(*assembled);
  const json& lights = p.extensions["KHR_lights_punctual"]["lights"];
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0]["type"], "spot");
  EXPECT_NEAR(lights[0]["spot"]["outerConeAngle"].get<double>(), 30 * std::acos(-1.0) / 180, 1e-12);
  EXPECT_EQ(lights[0]["extras"]["spotExponent"], 5);
  EXPECT_EQ(lights[1]["type"], "point");
  EXPECT_EQ(lights[1]["color"], json::array({1, 0.5, 0.25}));
  ASSERT_EQ(p.sceneRoots.size(), 4u);
  const glb::Node& lamp = p.nodes.at(std::size_t(p.sceneRoots[2]));
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.extensions["KHR_lights_punctual"]["light"], 0);
  const std::array<double, 16> m = lamp.localMatrix();
  EXPECT_NEAR(m[13], 3, 1e-12);
  EXPECT_NEAR(-m[9], -0.6, 1e-12);  // -Z toward the target, (0, -3, -4) / 5
  EXPECT_NEAR(-m[10], -0.8, 1e-12);
  const glb::Node& bulb = p.nodes.at(std::size_t(p.sceneRoots[3]));
  EXPECT_EQ(bulb.extensions["KHR_lights_punctual"]["light"], 1);
  EXPECT_NEAR(bulb.localMatrix()[14], 3, 1e-12);
  EXPECT_NE(std::find(p.extensionsUsed.begin(), p.extensionsUsed.end(), "KHR_lights_punctual"), p.extensionsUsed.end());
}

TEST(PipeAssemble, KeepsOnlyTheFieldsTheMaterialReadsRenumbered) {
  const Scene scene = torusAndPlate();
  const glb::Package original = readBack(inputs().geodesic);
  AssembleReport report;
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package p = encodedAndRead(*assembled);

  // Field "b" (_GEODESIC_1 as baked) is now _GEODESIC_0, the only one; its values unchanged.
  const json& fields = p.extensions.at(geo::kExtension).at(geo::kKeyFields);
  ASSERT_EQ(fields.size(), 1u);
  EXPECT_EQ(fields[0][geo::kFieldName], "b");
  EXPECT_EQ(fields[0][geo::kFieldAttribute], "_GEODESIC_0");
  const glb::Attribute* kept = attribute(p, "geodesic", "_GEODESIC_0");
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(attribute(p, "geodesic", "_GEODESIC_1"), nullptr);
  EXPECT_EQ(kept->bytes, original.meshes[0].primitives[0].find("_GEODESIC_1")->bytes);
  // The other attributes are untouched.
  EXPECT_EQ(attribute(p, "geodesic", "POSITION")->bytes, original.meshes[0].primitives[0].find("POSITION")->bytes);

  // The material is the scene's, its field names resolved to the new index.
  const int sand = materialNamed(p, "sand");
  ASSERT_GE(sand, 0);
  const json& material = p.materials[std::size_t(sand)]["extensions"][geo::kExtension];
  EXPECT_EQ(material["texture"], "sand-water");
  EXPECT_EQ(material["fields"], json::array({0}));
  EXPECT_EQ(material["thresholds"], json::array({0.3}));
  for (const glb::Mesh& mesh : p.meshes)
    if (mesh.name == "geodesic") EXPECT_EQ(mesh.primitives[0].material, sand);

  EXPECT_NE(std::find(report.dropped.begin(), report.dropped.end(), "torus: field 'a' (_GEODESIC_0)"), report.dropped.end());
  EXPECT_NE(std::find(report.dropped.begin(), report.dropped.end(), "torus: field 'c' (_GEODESIC_2)"), report.dropped.end());
}

TEST(PipeAssemble, EmptiesUnreadGrooveRecordsAndRenumbersTheArrays) {
  const Scene scene = torusAndPlate();
  const glb::Package originalPackage = readBack(inputs().grooves);
  auto original = grooves::decodeGroovePackage(originalPackage, "plate.glb");
  ASSERT_TRUE(original.isOk()) << original.status().describe();
  ASSERT_GT(original->records.size(), 0u) << "the test scene must have special cases";

  AssembleReport report;
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package p = encodedAndRead(*assembled);
  const int steel = materialNamed(p, "steel");
  ASSERT_GE(steel, 0);
  auto decoded = grooves::decodeGroovePackage(withOnlyMaterial(p, std::size_t(steel)), "assembled.glb");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  EXPECT_TRUE(decoded->records.empty());
  EXPECT_TRUE(decoded->recordRefs.empty());
  EXPECT_EQ(decoded->recordStart.size(), original->recordStart.size());
  EXPECT_TRUE(std::all_of(decoded->recordStart.begin(), decoded->recordStart.end(), [](std::uint32_t s) { return s == 0; }));
  // Everything else decodes to the same bytes as baked.
  EXPECT_EQ(decoded->cellStart, original->cellStart);
  EXPECT_EQ(decoded->primitiveRefs, original->primitiveRefs);
  ASSERT_EQ(decoded->primitives.size(), original->primitives.size());
  EXPECT_EQ(std::memcmp(decoded->primitives.data(), original->primitives.data(),
                        decoded->primitives.size() * sizeof(grv::Primitive)), 0);
  EXPECT_EQ(decoded->profilePoints, original->profilePoints);
  // The assembled package's blobs (before writing; a read-back package also lists its vertex data)
  // are the 10 grooves arrays: the three new empty record arrays replace the baked ones.
  EXPECT_EQ(assembled->blobs.size(), grv::kArrayCount);
  for (const glb::Blob& blob : assembled->blobs) EXPECT_EQ(blob.alignment, grv::kBufferAlignment);
  EXPECT_NE(std::find(report.dropped.begin(), report.dropped.end(),
                      "plate: special-case records (" + std::to_string(original->records.size()) + " records, " +
                          std::to_string(original->recordRefs.size()) + " cell references)"),
            report.dropped.end());
}

TEST(PipeAssemble, GrooveArraysStayOn256ByteBoundariesInTheFile) {
  auto assembled = assemble(torusAndPlate(), {inputs().geodesic, inputs().grooves}, {});
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  auto bytes = glb::encode(*assembled);
  ASSERT_TRUE(bytes.isOk());
  std::uint32_t length = 0;
  std::memcpy(&length, bytes->data() + 12, 4);
  const json document = json::parse(bytes->begin() + 20, bytes->begin() + 20 + length);
  const json& views = document["materials"][1]["extensions"][grv::kExtension][grv::kBufferViews];
  for (const char* key : grv::kArrayKeys)
    EXPECT_EQ(document["bufferViews"][views[key].get<std::size_t>()]["byteOffset"].get<std::size_t>() % grv::kBufferAlignment, 0u)
        << key;
}

TEST(PipeAssemble, KeepUnusedCopiesEveryBakedByteButReadsTheSame) {
  const Scene scene = torusAndPlate();
  AssembleSettings keep;
  keep.keepUnused = true;
  AssembleReport pruneReport, keepReport;
  auto pruned = assemble(scene, {inputs().geodesic, inputs().grooves}, {}, &pruneReport);
  auto kept = assemble(scene, {inputs().geodesic, inputs().grooves}, keep, &keepReport);
  ASSERT_TRUE(pruned.isOk() && kept.isOk());
  EXPECT_TRUE(keepReport.dropped.empty());
  EXPECT_EQ(pruneReport.dropped.size(), 3u);

  // Every field and every baked grooves array is there, plus the three empty record arrays.
  const glb::Package originalGeodesic = readBack(inputs().geodesic);
  EXPECT_EQ(kept->extensions[geo::kExtension][geo::kKeyFields], originalGeodesic.extensions[geo::kExtension][geo::kKeyFields]);
  EXPECT_NE(attribute(*kept, "geodesic", "_GEODESIC_2"), nullptr);
  EXPECT_EQ(kept->blobs.size(), grv::kArrayCount + 3);
  EXPECT_GT(blobBytes(*kept), blobBytes(*pruned));

  // The materials read the same data: field "b" (index 1 here), and no records.
  const int sand = materialNamed(*kept, "sand");
  EXPECT_EQ(kept->materials[std::size_t(sand)]["extensions"][geo::kExtension]["fields"], json::array({1}));
  const int steel = materialNamed(*kept, "steel");
  auto decoded = grooves::decodeGroovePackage(withOnlyMaterial(encodedAndRead(*kept), std::size_t(steel)), "kept.glb");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  EXPECT_TRUE(decoded->records.empty());

  auto prunedBytes = glb::encode(*pruned);
  auto keptBytes = glb::encode(*kept);
  ASSERT_TRUE(prunedBytes.isOk() && keptBytes.isOk());
  EXPECT_LT(prunedBytes->size(), keptBytes->size());
}

TEST(PipeAssemble, GlobalNormalizationKeepsEveryFieldAndSaysWhy) {
  const fs::path dir = test::freshTempDir("assemble_global");
  const fs::path global = test::bakeTorusFields(dir, {.normalization = geodesic::Normalization::Global});
  Scene scene = torusAndPlate();
  scene.objects.resize(1);
  AssembleReport report;
  auto assembled = assemble(scene, {global}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  EXPECT_EQ(assembled->extensions[geo::kExtension][geo::kKeyFields].size(), 3u);
  EXPECT_TRUE(report.dropped.empty());
  ASSERT_EQ(report.kept.size(), 1u);
  EXPECT_NE(report.kept[0].find("global"), std::string::npos);
  EXPECT_EQ(assembled->materials[0]["extensions"][geo::kExtension]["fields"], json::array({1}));
}

TEST(PipeAssemble, RevolutionDropsAnUnreadDisplacementMapAndKeepsItsOtherMaps) {
  const fs::path dir = test::freshTempDir("assemble_revolution");
  const fs::path vase = test::bakeVase(dir);
  const glb::Package original = readBack(vase);
  const json& baked = original.materials[0]["extensions"][rev::kExtension];
  ASSERT_TRUE(baked.contains(rev::kDisplacementMap));
  Scene scene;
  scene.objects = {objectOf("ring", "revolution", 0)};
  scene.materials = {materialOf("smooth", "revolution")};
  scene.materials[0].readsDisplacement = false;

  AssembleReport report;
  // After the grooves plate, so every index moves.
  scene.objects.insert(scene.objects.begin(), objectOf("plate", "grooves", 1));
  scene.materials.push_back(materialOf("steel", "grooves"));
  auto assembled = assemble(scene, {inputs().grooves, vase}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  const glb::Package p = encodedAndRead(*assembled);
  const int smooth = materialNamed(p, "smooth");
  ASSERT_GE(smooth, 0);
  const json& extension = p.materials[std::size_t(smooth)]["extensions"][rev::kExtension];
  EXPECT_FALSE(extension.contains(rev::kDisplacementMap));
  const int shape = extension[rev::kShapeMap][rev::kBufferView].get<int>();
  EXPECT_GE(shape, int(grv::kArrayCount));
  EXPECT_EQ(p.blobs.at(std::size_t(shape)).bytes,
            original.blobs.at(baked[rev::kShapeMap][rev::kBufferView].get<std::size_t>()).bytes);
  // The base colour still reaches the same PNG bytes through texture -> image -> bufferView.
  const int texture = p.materials[std::size_t(smooth)]["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>();
  const int image = p.textures.at(std::size_t(texture))["source"].get<int>();
  const int view = p.images.at(std::size_t(image))["bufferView"].get<int>();
  const int originalView = original.images[0]["bufferView"].get<int>();
  EXPECT_EQ(p.blobs.at(std::size_t(view)).bytes, original.blobs.at(std::size_t(originalView)).bytes);
  // Ten grooves arrays, the shape map, the arc-length map if any and the PNG; no displacement map.
  const std::size_t arcLength = baked.contains(rev::kArcLengthMap) ? 1 : 0;
  EXPECT_EQ(assembled->blobs.size(), grv::kArrayCount + 2 + arcLength);
  EXPECT_EQ(report.dropped.size(), 1u);
  EXPECT_NE(report.dropped.at(0).find("ring: displacement map"), std::string::npos);

  // Keeping unused data, the displacement map's bytes are in the package, but unreferenced.
  AssembleSettings keep;
  keep.keepUnused = true;
  auto kept = assemble(scene, {inputs().grooves, vase}, keep);
  ASSERT_TRUE(kept.isOk()) << kept.status().describe();
  EXPECT_EQ(kept->blobs.size(), grv::kArrayCount + 3 + arcLength);
  const auto& displacement = original.blobs.at(baked[rev::kDisplacementMap][rev::kBufferView].get<std::size_t>()).bytes;
  EXPECT_TRUE(std::any_of(kept->blobs.begin(), kept->blobs.end(), [&](const glb::Blob& b) { return b.bytes == displacement; }));
  EXPECT_FALSE(kept->materials[std::size_t(materialNamed(*kept, "smooth"))]["extensions"][rev::kExtension].contains(rev::kDisplacementMap));
}

TEST(PipeAssemble, RevolutionWithoutBaseColourDropsTheImage) {
  const fs::path dir = test::freshTempDir("assemble_revolution_colour");
  const fs::path vase = test::bakeVase(dir);
  Scene scene;
  scene.objects = {objectOf("vase", "revolution", 0)};
  scene.materials = {materialOf("plain", "revolution")};
  scene.materials[0].readsBaseColor = false;
  AssembleReport report;
  auto assembled = assemble(scene, {vase}, {}, &report);
  ASSERT_TRUE(assembled.isOk()) << assembled.status().describe();
  EXPECT_TRUE(assembled->images.empty());
  EXPECT_TRUE(assembled->textures.empty());
  EXPECT_FALSE(assembled->materials[0]["pbrMetallicRoughness"].contains("baseColorTexture"));
  EXPECT_TRUE(assembled->materials[0]["extensions"][rev::kExtension].contains(rev::kDisplacementMap));
  ASSERT_EQ(report.dropped.size(), 1u);
  EXPECT_NE(report.dropped[0].find("vase: base colour texture"), std::string::npos);
}

TEST(PipeAssemble, HatchingDropsTheUnreadThresholdTextureAndKeepsTheTam) {
  const fs::path dir = test::freshTempDir("assemble_hatching");
  const fs::path hatched = test::bakeHatchedTorus(dir);
  const glb::Package original = readBack(hatched);
  namespace tam = format::tam;  // the TAM format: the hatching package's constants
  const json& baked = original.materials[0]["extensions"][tam::kExtension];
  ASSERT_TRUE(baked.contains(tam::kThresholdImage));
  const auto imageBytes = [](const glb::Package& p, int image) {
    return p.blobs.at(p.images.at(std::size_t(image))["bufferView"].get<std::size_t>()).bytes;
  };
  Scene scene = torusAndPlate();
  scene.objects.push_back(objectOf("pen", "hatching", 2));
  scene.materials.push_back(materialOf("ink", "hatching"));  // reads no threshold (the default)

  AssembleReport report;
  auto pruned = assemble(scene, {inputs().geodesic, inputs().grooves, hatched}, {}, &report);
  ASSERT_TRUE(pruned.isOk()) << pruned.status().describe();
  const int ink = materialNamed(*pruned, "ink");
  ASSERT_GE(ink, 0);
  const json& extension = (*pruned).materials[std::size_t(ink)]["extensions"][tam::kExtension];
  EXPECT_FALSE(extension.contains(tam::kThresholdImage));
  EXPECT_EQ(pruned->images.size(), 1u);
  EXPECT_EQ(imageBytes(*pruned, extension[tam::kTamImage].get<int>()), imageBytes(original, baked[tam::kTamImage].get<int>()));
  EXPECT_NE(std::find(report.dropped.begin(), report.dropped.end(),
                      "pen: threshold texture (image " + std::to_string(baked[tam::kThresholdImage].get<int>()) + ")"),
            report.dropped.end());

  AssembleSettings keep;
  keep.keepUnused = true;
  auto kept = assemble(scene, {inputs().geodesic, inputs().grooves, hatched}, keep);
  ASSERT_TRUE(kept.isOk()) << kept.status().describe();
  EXPECT_EQ(kept->images.size(), 2u);  // the threshold texture stays, unreferenced
  EXPECT_FALSE(kept->materials[std::size_t(ink)]["extensions"][tam::kExtension].contains(tam::kThresholdImage));
}

TEST(PipeAssemble, AMissingPackageOrTheWrongTechniqueNamesTheFileAndTheObject) {
  const Scene scene = torusAndPlate();
  auto missing = assemble(scene, {inputs().dir / "nothing.glb", inputs().grooves}, {});
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), ExitCode::Io);
  EXPECT_NE(missing.status().describe().find("nothing.glb"), std::string::npos);
  EXPECT_NE(missing.status().describe().find("torus"), std::string::npos);

  auto swapped = assemble(scene, {inputs().grooves, inputs().geodesic}, {});
  ASSERT_FALSE(swapped.isOk());
  EXPECT_EQ(swapped.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(swapped.status().describe().find("plate.glb"), std::string::npos);
  EXPECT_NE(swapped.status().describe().find("'torus'"), std::string::npos);
  EXPECT_NE(swapped.status().describe().find(geo::kExtension), std::string::npos);
}

TEST(PipeAssemble, GeodesicObjectsShareTheRootFieldListOnlyWhenItAgrees) {
  Scene scene = torusAndPlate();
  Object second = scene.objects[0];
  second.name = "torus2";
  scene.objects[1] = second;  // two geodesic objects with the same material: one field list
  auto same = assemble(scene, {inputs().geodesic, inputs().geodesic}, {});
  ASSERT_TRUE(same.isOk()) << same.status().describe();
  EXPECT_EQ(same->extensions[geo::kExtension][geo::kKeyFields].size(), 1u);
  EXPECT_EQ(same->meshes.size(), 2u);
  EXPECT_EQ(same->materials.size(), 2u);

  Material other = scene.materials[0];
  other.name = "other";
  other.fields = {"c"};
  other.geotexture["fields"] = {"c"};
  scene.materials[1] = other;
  scene.objects[1].material = 1;  // field "c" is _GEODESIC_0 there, "b" here: the lists differ
  auto differ = assemble(scene, {inputs().geodesic, inputs().geodesic}, {});
  ASSERT_FALSE(differ.isOk());
  EXPECT_EQ(differ.status().code(), ExitCode::Unsupported);
  EXPECT_NE(differ.status().describe().find("torus2"), std::string::npos);
}

TEST(PipeAssemble, AFieldThePackageLacksIsAnError) {
  Scene scene = torusAndPlate();
  scene.materials[0].fields = {"d"};
  auto assembled = assemble(scene, {inputs().geodesic, inputs().grooves}, {});
  ASSERT_FALSE(assembled.isOk());
  EXPECT_NE(assembled.status().describe().find("'d'"), std::string::npos);
}

}  // namespace
}  // namespace bake::pipe
