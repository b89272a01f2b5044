// geobake --fields (Settings::onlyFields): only the named fields of the sources file are baked, in
// file order, with the same values as in a bake of all fields (fields are independent unless the
// normalisation is global).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bake/geodesic/bake.h"
#include "bake/io/glb.h"

namespace bake::geodesic {
namespace {

namespace fs = std::filesystem;

// One folder per test: CTest runs the tests of this file in parallel processes.
fs::path testDir() {
  return fs::path(BAKE_TEST_TMP) / "geodesic-fields" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// A tetrahedron and three single-vertex fields a, b, c.
Settings tetrahedron(const std::string& output) {
  const fs::path dir = testDir();
  fs::create_directories(dir);
  writeText(dir / "mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
  writeText(dir / "sources.json",
            R"({"fields": [{"name": "a", "sources": [{"vertex": 0}]}, {"name": "b", "sources": [{"vertex": 1}]},
                           {"name": "c", "sources": [{"vertex": 2}]}]})");
  Settings settings;
  settings.input = (dir / "mesh.obj").string();
  settings.sourcesFile = (dir / "sources.json").string();
  settings.output = (dir / output).string();
  settings.common.quiet = true;
  return settings;
}

glb::Package bakeOk(const Settings& settings) {
  Diagnostics diagnostics("geobake");
  diagnostics.setQuiet(true);
  const Status status = run(settings, diagnostics);
  EXPECT_TRUE(status.isOk()) << status.describe();
  Result<glb::Package> package = glb::read(settings.output);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  return package.isOk() ? package.value() : glb::Package{};
}

std::vector<std::string> fieldNames(const glb::Package& package) {
  std::vector<std::string> names;
  for (const auto& field : package.extensions["BAKE_geodesic"]["fields"]) names.push_back(field["name"]);
  return names;
}

TEST(GeodesicFields, OnlyTheNamedFieldsInFileOrderWithTheFullBakesValues) {
  const glb::Package all = bakeOk(tetrahedron("all.glb"));
  Settings some = tetrahedron("some.glb");
  some.onlyFields = {"c", "a"};
  const glb::Package selected = bakeOk(some);
  ASSERT_EQ(fieldNames(all), (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(fieldNames(selected), (std::vector<std::string>{"a", "c"}));
  const glb::Primitive& full = all.meshes.at(0).primitives.at(0);
  const glb::Primitive& part = selected.meshes.at(0).primitives.at(0);
  EXPECT_EQ(part.find("_GEODESIC_2"), nullptr);
  ASSERT_NE(part.find("_GEODESIC_1"), nullptr);
  EXPECT_EQ(part.find("_GEODESIC_0")->bytes, full.find("_GEODESIC_0")->bytes);  // a
  EXPECT_EQ(part.find("_GEODESIC_1")->bytes, full.find("_GEODESIC_2")->bytes);  // c
}

TEST(GeodesicFields, AnUnknownNameIsAnInputError) {
  Settings settings = tetrahedron("bad.glb");
  settings.onlyFields = {"a", "nose"};
  Diagnostics diagnostics("geobake");
  diagnostics.setQuiet(true);
  const Status status = run(settings, diagnostics);
  ASSERT_FALSE(status.isOk());
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_NE(status.message().find("\"nose\""), std::string::npos) << status.describe();
  EXPECT_FALSE(fs::exists(settings.output));
}

}  // namespace
}  // namespace bake::geodesic
