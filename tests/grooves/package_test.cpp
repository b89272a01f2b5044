// The BAKE_grooves package (libbake/grooves/package/package.h, formats/grooves.md): round trip through a file,
// bufferView offsets on 256-byte boundaries, std430 strides, the decoded geometry against the scene's
// double geometry (within fp32 rounding of a cell-local offset), the preview plane, and the reader's
// refusal of damaged packages.
#include <cmath>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "bake_formats/grooves.h"
#include "grooves/package/package.h"
#include "support/golden.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
namespace fmt = format::grooves;

GrooveScene exampleScene() {
  Result<GrooveScene> r = readGrooveScene((test::sourceDir() / "tests/grooves/data/example-scene.json").string());
  EXPECT_TRUE(r.isOk()) << r.status().describe();
  return r.isOk() ? r.value() : GrooveScene{};
}

struct Baked {
  GrooveScene scene;
  GrooveGrid grid;
  std::vector<std::uint8_t> bytes;
};

Baked bake(GrooveScene scene) {
  Baked baked;
  baked.scene = std::move(scene);
  Result<GrooveGrid> grid = buildGrooveGrid(baked.scene, {});
  EXPECT_TRUE(grid.isOk()) << grid.status().describe();
  baked.grid = grid.value();
  Result<glb::Package> package = buildGroovePackage(baked.scene, baked.grid);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  Result<std::vector<std::uint8_t>> bytes = glb::encode(package.value());
  EXPECT_TRUE(bytes.isOk());
  baked.bytes = bytes.value();
  return baked;
}

// The GLB's JSON chunk.
json documentOf(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

TEST(GroovePackage, RoundTripThroughAFileKeepsEveryArray) {
  const Baked baked = bake(exampleScene());
  const std::filesystem::path path = test::freshTempDir("groove-package") / "example.glb";
  ASSERT_TRUE(glb::write(path, glb::decode(baked.bytes).value()).isOk());
  Result<GroovePackage> read = readGroovePackage(path);
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  const GroovePackage& p = read.value();
  const GrooveGrid& grid = baked.grid;
  EXPECT_EQ(p.header.version, fmt::kVersion);
  EXPECT_EQ(p.header.cells[0], grid.cells[0]);
  EXPECT_EQ(p.header.cells[1], grid.cells[1]);
  EXPECT_DOUBLE_EQ(p.header.cellSize[0], grid.cellSize.u);
  EXPECT_TRUE(p.header.wrapRepeat);
  EXPECT_EQ(p.header.units, "mm");
  EXPECT_DOUBLE_EQ(p.header.wmax, baked.scene.wmax);
  EXPECT_EQ(p.cellStart, grid.cellStart);
  EXPECT_EQ(p.primitiveRefs, grid.primitiveRefs);
  EXPECT_EQ(p.recordStart, grid.recordStart);
  EXPECT_EQ(p.recordRefs, grid.recordRefs);
  ASSERT_EQ(p.records.size(), grid.records.size());
  for (std::size_t r = 0; r < p.records.size(); ++r) {
    EXPECT_EQ(p.records[r].info[0], std::uint32_t(grid.records[r].kind));
    EXPECT_EQ(p.records[r].info[1], grid.records[r].primitive[0]);
    EXPECT_EQ(p.records[r].info[2], grid.records[r].primitive[1]);
  }
  ASSERT_EQ(p.primitives.size(), baked.scene.primitives.size());
  for (std::size_t i = 0; i < p.primitives.size(); ++i) {
    const Primitive& q = baked.scene.primitives[i];
    EXPECT_EQ(p.primitives[i].groove, q.groove);
    EXPECT_EQ((p.primitives[i].flags & fmt::kPrimitiveArc) != 0, q.kind == Primitive::Kind::Arc);
    EXPECT_EQ((p.primitives[i].flags & fmt::kPrimitiveCornerAtStart) != 0, q.cornerAtStart);
    EXPECT_EQ((p.primitives[i].flags & fmt::kPrimitiveEndAtEnd) != 0, q.endAtEnd);
    EXPECT_FLOAT_EQ(p.primitives[i].measure[2], float(q.length));
    // The anchor is the cell holding the start point.
    EXPECT_EQ(p.primitives[i].anchor[0], std::int32_t(std::floor(q.a.u / grid.cellSize.u)));
  }
  ASSERT_EQ(p.grooves.size(), baked.scene.grooves.size());
  for (std::size_t g = 0; g < p.grooves.size(); ++g) {
    EXPECT_EQ(p.grooves[g].indices[2], baked.scene.grooves[g].firstPrimitive);
    EXPECT_EQ(p.grooves[g].indices[3], baked.scene.grooves[g].primitiveCount);
    EXPECT_FLOAT_EQ(p.grooves[g].bounds[0], float(baked.scene.grooves[g].wmax));
  }
  ASSERT_EQ(p.profiles.size(), baked.scene.profiles.size());
  const Profile& scratch = baked.scene.profiles[1];
  const fmt::Profile& stored = p.profiles[1];
  ASSERT_EQ(stored.points[1], scratch.points.size());
  for (std::size_t k = 0; k < scratch.points.size(); ++k) {
    EXPECT_FLOAT_EQ(p.profilePoints[2 * (stored.points[0] + k)], float(scratch.points[k].u));
    EXPECT_FLOAT_EQ(p.profilePoints[2 * (stored.points[0] + k) + 1], float(scratch.points[k].v));
  }
  ASSERT_EQ(p.materials.size(), baked.scene.materials.size());
  EXPECT_FLOAT_EQ(p.materials[0].albedo[3], float(baked.scene.materials[0].shininess));
  EXPECT_EQ(p.materials[0].specular[3], baked.scene.materials[0].hasMirror ? 1.0f : 0.0f);
  EXPECT_EQ(p.header.materialNames.size(), baked.scene.materials.size());
}

TEST(GroovePackage, StoredGeometryIsWithinFp32RoundingOfCellLocalOffsets) {
  const Baked baked = bake(exampleScene());
  const GroovePackage p = decodeGroovePackage(glb::decode(baked.bytes).value(), "example.glb").value();
  const StoredGeometryError error = storedGeometryError(baked.scene, baked.grid, p);
  // Offsets are at most a primitive's length (90 mm lines) from the anchor corner: half an ulp of 128
  // is 2^-17 ~ 7.6e-6; positions rebuilt in double add no error of their own.
  EXPECT_GT(error.maxPosition, 0.0);
  EXPECT_LT(error.maxPosition, 7.7e-6);
  EXPECT_LT(error.maxNormal, 1e-7);
  EXPECT_LT(error.maxArcEndpoint, 1e-3);
  // A scene moved far from the origin keeps the same error: offsets are cell-local.
  GrooveScene far = baked.scene;
  for (Primitive& q : far.primitives) {
    for (Vec2* x : {&q.a, &q.b, &q.centre}) x->u += 1e6;
  }
  far.domain[0] += 2e6;
  const Baked farBaked = bake(far);
  const GroovePackage farStored = decodeGroovePackage(glb::decode(farBaked.bytes).value(), "far.glb").value();
  EXPECT_LT(storedGeometryError(farBaked.scene, farBaked.grid, farStored).maxPosition, 7.7e-6);
}

TEST(GroovePackage, BufferViewsStartOn256ByteBoundariesWithStd430Strides) {
  const Baked baked = bake(exampleScene());
  const json document = documentOf(baked.bytes);
  const json& extension = document["materials"][0]["extensions"][fmt::kExtension];
  ASSERT_EQ(extension["bufferViews"].size(), fmt::kArrayCount);
  for (const auto& [key, view] : extension["bufferViews"].items()) {
    const json& bufferView = document["bufferViews"][view.get<std::size_t>()];
    EXPECT_EQ(bufferView.value("byteOffset", 0) % 256, 0) << key;
  }
  EXPECT_EQ(extension["strides"]["primitives"], 96);
  EXPECT_EQ(extension["strides"]["records"], 64);
  EXPECT_EQ(extension["counts"]["cells"], baked.grid.cellCount());
  EXPECT_EQ(extension["grid"]["cells"][0], baked.grid.cells[0]);
  EXPECT_EQ(extension["wrap"], "repeat");
}

TEST(GroovePackage, PreviewPlaneCoversTheDomainInTheXYPlane) {
  const Baked baked = bake(exampleScene());
  const glb::Package package = glb::decode(baked.bytes).value();
  ASSERT_EQ(package.meshes.size(), 1u);
  const glb::Primitive& plane = package.meshes[0].primitives[0];
  const std::vector<float> positions = plane.find("POSITION")->toFloats();
  const std::vector<float> texcoords = plane.find("TEXCOORD_0")->toFloats();
  ASSERT_EQ(positions.size(), 12u);
  for (std::size_t v = 0; v < 4; ++v) {
    EXPECT_FLOAT_EQ(positions[3 * v + 2], 0.0f);
    EXPECT_FLOAT_EQ(texcoords[2 * v], positions[3 * v] / 100.0f);  // u / U
    EXPECT_FLOAT_EQ(texcoords[2 * v + 1], positions[3 * v + 1] / 100.0f);
  }
  EXPECT_FLOAT_EQ(plane.find("NORMAL")->toFloats()[2], 1.0f);
  EXPECT_EQ(plane.material, 0);
}

TEST(GroovePackage, EmptyArraysAreStoredAsOneZeroedItemWithCountZero) {
  // No grooves: no primitives, references or records, yet every bufferView exists (glTF forbids
  // empty ones) and the reader returns empty arrays.
  GrooveScene scene = exampleScene();
  scene.grooves.clear();
  scene.primitives.clear();
  const Baked baked = bake(scene);
  const GroovePackage p = decodeGroovePackage(glb::decode(baked.bytes).value(), "empty.glb").value();
  EXPECT_TRUE(p.primitives.empty());
  EXPECT_TRUE(p.records.empty());
  EXPECT_TRUE(p.primitiveRefs.empty());
  EXPECT_EQ(p.cellStart.size(), baked.grid.cellCount() + 1);
}

// Edits the extension of an encoded package and decodes it again.
Result<GroovePackage> withExtension(const Baked& baked, const std::function<void(json&)>& edit) {
  glb::Package package = glb::decode(baked.bytes).value();
  edit(package.materials[0]["extensions"][fmt::kExtension]);
  return decodeGroovePackage(package, "edited.glb");
}

TEST(GroovePackage, ReaderRefusesDamagedPackages) {
  const Baked baked = bake(exampleScene());
  auto expectRefused = [&](const std::function<void(json&)>& edit, const char* fragment) {
    Result<GroovePackage> r = withExtension(baked, edit);
    ASSERT_FALSE(r.isOk()) << fragment;
    EXPECT_NE(r.status().describe().find(fragment), std::string::npos) << r.status().describe();
  };
  expectRefused([](json& e) { e["version"] = fmt::kVersion + 1; }, ("version " + std::to_string(fmt::kVersion + 1)).c_str());
  expectRefused([](json& e) { e["version"] = 0; }, "version 0");
  expectRefused([](json& e) { e["far"]["cells"] = {0, 4}; }, "far/cells");
  expectRefused([](json& e) { e["counts"]["farTable"] = 5; }, "farTable");
  expectRefused([](json& e) { e["counts"]["primitives"] = 1000000; }, "fewer than");
  expectRefused([](json& e) { e["bufferViews"]["records"] = 99; }, "does not exist");
  expectRefused([](json& e) { e["grid"]["cells"][0] = 3; }, "does not match");
  expectRefused([](json& e) { e["counts"]["primitives"] = 3; }, "out of range");  // references to later primitives
  expectRefused([](json& e) { e["baseMaterial"] = 7; }, "baseMaterial");
  expectRefused([](json& e) { e["wrap"] = "mirror"; }, "wrap");
  glb::Package package = glb::decode(baked.bytes).value();
  package.materials[0]["extensions"].erase(fmt::kExtension);
  EXPECT_FALSE(decodeGroovePackage(package, "plain.glb").isOk());
}

TEST(GroovePackage, BytesDoNotDependOnTheThreadCount) {
  const GrooveScene scene = exampleScene();
  GridSettings settings;
  settings.threads = 1;
  const GrooveGrid one = buildGrooveGrid(scene, settings).value();
  settings.threads = 3;
  const GrooveGrid three = buildGrooveGrid(scene, settings).value();
  EXPECT_EQ(glb::encode(buildGroovePackage(scene, one).value()).value(),
            glb::encode(buildGroovePackage(scene, three).value()).value());
}

}  // namespace
}  // namespace bake::grooves
