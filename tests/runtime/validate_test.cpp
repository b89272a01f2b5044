#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bake/core/atomic_file.h"
#include "play/validate.h"
#include "support/golden.h"

namespace bake::play {
namespace {
namespace fs = std::filesystem;

glb::Package quadPackage() {
  glb::Primitive primitive;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<float> field = {0.0f, 0.25f, 0.5f, 1.0f};
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("_FIELD_0", 1, field));
  primitive.indices = {0, 1, 2, 0, 2, 3};
  glb::Package package;
  package.meshes.push_back({"quad", {primitive}});
  package.extensions["BAKE_test"] = {{"version", 1}};
  return package;
}

TEST(ValidateStructure, AcceptsAGoodPackage) {
  EXPECT_TRUE(checkPackageStructure(quadPackage(), "good.glb").isOk());
}

TEST(ValidateStructure, RejectsNaNNamingAttributeAndVertex) {
  glb::Package package = quadPackage();
  std::vector<float> field = {0.0f, 0.25f, NAN, 1.0f};
  package.meshes[0].primitives[0].attributes[1] = glb::Attribute::fromFloats("_FIELD_0", 1, field);
  const Status status = checkPackageStructure(package, "nan.glb");
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_EQ(status.describe(), "nan.glb: mesh 0 primitive 0: attribute _FIELD_0 vertex 2 holds NaN");
}

TEST(ValidateStructure, RejectsVendorExtensionsWithoutVersion) {
  glb::Package package = quadPackage();
  package.extensions["BAKE_test"] = {{"grid", 0}};
  EXPECT_EQ(checkPackageStructure(package, "x.glb").describe(),
            "x.glb: extensions: extension BAKE_test lacks its \"version\" field");
  package.extensions["BAKE_test"] = {{"version", "one"}};
  EXPECT_EQ(checkPackageStructure(package, "x.glb").code(), ExitCode::InvalidInput);
  package = quadPackage();
  package.materials = nlohmann::json::array({{{"extensions", {{"BAKE_test", {{"version", 0}}}}}}});
  const Status material = checkPackageStructure(package, "x.glb");
  EXPECT_EQ(material.where().element, "material 0");
}

TEST(ValidateStructure, RejectsWrongStandardAttributeTypes) {
  glb::Package package = quadPackage();
  package.meshes[0].primitives[0].attributes.push_back(
      glb::Attribute::fromFloats("NORMAL", 2, std::vector<float>(8, 0.0f)));
  EXPECT_NE(checkPackageStructure(package, "x.glb").message().find("NORMAL must be float VEC3"), std::string::npos);
}

// The whole command, on llvmpipe: verdict lines, exit codes, and the damaged packages the runtime
// must refuse (out-of-range index, truncated buffer, NaN, missing extension field).
class ValidateCommand : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTempDir(std::string("validate_") + ::testing::UnitTest::GetInstance()->current_test_info()->name()); }

  std::string write(const std::string& name, const glb::Package& package) {
    const fs::path path = dir_ / name;
    EXPECT_TRUE(glb::write(path, package).isOk());
    return path.string();
  }

  // Runs validate; returns the exit code and fills `verdicts` with stdout.
  ExitCode run(ValidateSettings settings, std::string& verdicts) {
    char buffer[4096] = {};
    std::FILE* out = ::fmemopen(buffer, sizeof buffer, "w");
    Diagnostics diagnostics("bakeplay", true);
    const Status status = runValidate(settings, diagnostics, out);
    std::fclose(out);
    verdicts = buffer;
    return status.code();
  }

  fs::path dir_;
};

TEST_F(ValidateCommand, GoodPackagePassesAndMatchesItsOwnRendering) {
  ValidateSettings settings;
  settings.packages = {write("good.glb", quadPackage())};
  settings.viewsDirectory = dir_.string();
  std::string verdicts;
  ASSERT_EQ(run(settings, verdicts), ExitCode::Ok) << verdicts;
  EXPECT_EQ(verdicts.rfind("PASS ", 0), 0u) << verdicts;
  ASSERT_TRUE(fs::exists(dir_ / "good.view0.png"));
  settings.goldens = {(dir_ / "good.view0.png").string()};
  settings.viewsDirectory.clear();
  EXPECT_EQ(run(settings, verdicts), ExitCode::Ok) << verdicts;
  EXPECT_NE(verdicts.find("matches"), std::string::npos);
  // Against another view's picture the package must fail, with the metric in the verdict.
  settings.goldens = {(dir_ / "good.view1.png").string()};
  EXPECT_EQ(run(settings, verdicts), ExitCode::InvalidInput);
  EXPECT_NE(verdicts.find("DIFFERS"), std::string::npos);
  EXPECT_NE(verdicts.find("RMSE"), std::string::npos);
}

TEST_F(ValidateCommand, DamagedPackagesFailNamingTheFault) {
  glb::Package nan = quadPackage();
  nan.meshes[0].primitives[0].attributes[1] = glb::Attribute::fromFloats("_FIELD_0", 1, std::vector<float>{0, NAN, 0, 0});
  glb::Package noVersion = quadPackage();
  noVersion.extensions["BAKE_test"] = nlohmann::json::object();
  const std::string good = write("good.glb", quadPackage());

  // An index past the vertices: patch the 16-bit index buffer of a good file.
  std::vector<std::uint8_t> bytes = test::readAll(good);
  const std::vector<std::uint8_t> indices = {0, 0, 1, 0, 2, 0, 0, 0, 2, 0, 3, 0};
  const auto at = std::search(bytes.begin(), bytes.end(), indices.begin(), indices.end());
  ASSERT_NE(at, bytes.end());
  *(at + 10) = 40;
  ASSERT_TRUE(writeFileAtomic(dir_ / "index.glb", bytes).isOk());
  // A truncated file: the BIN chunk runs past the end.
  bytes = test::readAll(good);
  bytes.resize(bytes.size() - 16);
  ASSERT_TRUE(writeFileAtomic(dir_ / "truncated.glb", bytes).isOk());

  ValidateSettings settings;
  settings.packages = {good, write("nan.glb", nan), write("noversion.glb", noVersion), (dir_ / "index.glb").string(),
                       (dir_ / "truncated.glb").string()};
  std::string verdicts;
  EXPECT_EQ(run(settings, verdicts), ExitCode::InvalidInput);
  EXPECT_NE(verdicts.find("PASS " + good), std::string::npos) << verdicts;
  EXPECT_NE(verdicts.find("FAIL " + (dir_ / "nan.glb").string() + ": " + (dir_ / "nan.glb").string() +
                          ": mesh 0 primitive 0: attribute _FIELD_0 vertex 1 holds NaN"), std::string::npos) << verdicts;
  EXPECT_NE(verdicts.find("lacks its \"version\" field"), std::string::npos) << verdicts;
  EXPECT_NE(verdicts.find("index 5 is 40, past the 4 vertices"), std::string::npos) << verdicts;
  EXPECT_NE(verdicts.find("truncated"), std::string::npos) << verdicts;
}

}  // namespace
}  // namespace bake::play
