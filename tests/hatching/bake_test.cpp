// tambake's run (hatching/bake.h) end to end: the KTX2 TAM read back by our reader and by ktx-parse
// (layers = tones, full mip chain, format, metadata), the threshold texture against the TAM it
// comes from, the package read back with io/glb.h (material extension, embedded KTX2, mesh with unit
// normals), the report's quality entries, and the smooth normals the package computes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "bake/core/atomic_file.h"
#include "bake/hatching/bake.h"
#include "bake/io/glb.h"
#include "hatching/bake/bake_stages.h"
#include "io/ktx2.h"
#include "support/golden.h"
#include "support/node_check.h"

namespace bake::hatching {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path dataFile(const std::string& name) { return test::sourceDir() / "tests" / "hatching" / "data" / name; }

Settings smallSettings(const fs::path& dir) {
  Settings settings;
  settings.style = dataFile("small.json").string();
  settings.output = (dir / "tam.ktx2").string();
  settings.common.quiet = true;
  return settings;
}

Status runQuietly(const Settings& settings) {
  Diagnostics diagnostics("tambake", true);
  return run(settings, diagnostics);
}

double meanOf(const std::vector<std::uint8_t>& bytes, std::size_t begin, std::size_t count) {
  double sum = 0;
  for (std::size_t i = begin; i < begin + count; ++i) sum += bytes[i];
  return sum / double(count);
}

TEST(TamBake, KtxHoldsOneLayerPerToneWithTheFullMipChainAndTheTones) {
  const fs::path dir = test::freshTempDir("tam_bake_ktx");
  const Settings settings = smallSettings(dir);
  const Status status = runQuietly(settings);
  ASSERT_TRUE(status.isOk()) << status.describe();

  Result<ktx2::Texture> read = ktx2::read(settings.output);
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  const ktx2::Texture& texture = read.value();
  EXPECT_EQ(texture.format, ktx2::Format::R8);
  EXPECT_EQ(texture.width, 64u);
  EXPECT_EQ(texture.height, 64u);
  EXPECT_EQ(texture.layers, 3u);
  ASSERT_EQ(texture.levels.size(), 7u);  // 64 .. 1
  const json metadata = json::parse(texture.text("BAKE_tam"));
  EXPECT_EQ(metadata["version"], 1);
  EXPECT_EQ(metadata["tones"].get<std::vector<double>>(), (std::vector<double>{0.3, 0.6, 0.9}));
  EXPECT_EQ(metadata["strokeLevels"], 2);
  EXPECT_EQ(metadata["style"], "hatching");
  EXPECT_EQ(metadata["seed"], 3);
  EXPECT_EQ(metadata["colour"], false);
  EXPECT_FALSE(metadata.contains("threshold"));

  // Layers are tones light to dark at every level, and the box-filtered levels below the stroke
  // levels keep the mean of the last stroke level (so layers and levels are where they belong).
  for (std::uint32_t level = 0; level < texture.levels.size(); ++level) {
    const std::size_t texels = std::size_t(texture.levelWidth(level)) * texture.levelHeight(level);
    ASSERT_EQ(texture.levels[level].size(), texels * 3) << level;
    double previous = 256;
    for (std::uint32_t layer = 0; layer < 3; ++layer) {
      const double mean = meanOf(texture.levels[level], layer * texels, texels);
      EXPECT_LT(mean, previous) << "level " << level << ", layer " << layer;
      previous = mean;
      const double darkness = 1 - mean / 255;
      EXPECT_NEAR(darkness, metadata["tones"][layer].get<double>(), 0.08) << "level " << level << ", layer " << layer;
      if (level >= 2) {
        const std::size_t stroked = std::size_t(texture.levelWidth(1)) * texture.levelHeight(1);
        EXPECT_NEAR(mean, meanOf(texture.levels[1], layer * stroked, stroked), 1.0) << "level " << level << ", layer " << layer;
      }
    }
  }

  // An independent reader agrees.
  const json parsed = test::runNodeChecker("check_ktx2.mjs", {settings.output});
  ASSERT_TRUE(parsed.is_object());
  EXPECT_EQ(parsed["vkFormat"], ktx2::vkFormatOf(ktx2::Format::R8));
  EXPECT_EQ(parsed["pixelWidth"], 64);
  EXPECT_EQ(parsed["pixelHeight"], 64);
  EXPECT_EQ(parsed["layerCount"], 3);
  EXPECT_EQ(parsed["levelCount"], 7);
  EXPECT_EQ(parsed["supercompressionScheme"], 0);
  EXPECT_EQ(json::parse(parsed["keyValue"]["BAKE_tam"].get<std::string>()), metadata);
  ASSERT_EQ(parsed["levels"].size(), 7u);
  EXPECT_EQ(parsed["levels"][6]["byteLength"], 3);  // 1 x 1 x 3 layers
}

// The written threshold texture (Webb et al. 2002) against the written TAM: texels no tone inks hold
// 255; a texel first inked by a lighter tone never holds more than one first inked by a darker tone
// (placement order kept, within one 8-bit step); the values are graded (many per tone).
TEST(TamBake, ThresholdTextureGradesTexelsInTheOrderTheirTonesInkedThem) {
  const fs::path dir = test::freshTempDir("tam_bake_threshold");
  Settings settings = smallSettings(dir);
  settings.threshold = (dir / "threshold.ktx2").string();
  const Status status = runQuietly(settings);
  ASSERT_TRUE(status.isOk()) << status.describe();
  Result<ktx2::Texture> tam = ktx2::read(settings.output);
  Result<ktx2::Texture> threshold = ktx2::read(settings.threshold);
  ASSERT_TRUE(tam.isOk() && threshold.isOk());
  EXPECT_EQ(threshold->format, ktx2::Format::R8);
  EXPECT_EQ(threshold->layers, 0u);
  EXPECT_EQ(threshold->width, 64u);
  ASSERT_EQ(threshold->levels.size(), tam->levels.size());
  const json metadata = json::parse(threshold->text("BAKE_tam"));
  EXPECT_EQ(metadata["threshold"], true);
  const std::size_t texels = 64 * 64;
  int inked = 0;
  std::vector<std::set<int>> valuesPerTone(3);
  for (std::size_t i = 0; i < texels; ++i) {
    const int value = threshold->levels[0][i];
    int first = -1;  // the first tone whose texel is inked (brightness <= 0.5, within quantisation)
    bool ambiguous = false;  // brightness at 0.5 itself quantises to 128
    for (int k = 0; k < 3; ++k) ambiguous |= tam->levels[0][k * texels + i] == 128;
    for (int k = 0; k < 3 && first < 0; ++k)
      if (tam->levels[0][k * texels + i] <= 127) first = k;
    if (ambiguous) continue;
    if (first >= 0) {
      ++inked;
      valuesPerTone[std::size_t(first)].insert(value);
    } else {
      EXPECT_EQ(value, 255) << "texel " << i;
    }
  }
  EXPECT_GT(inked, int(texels / 2));  // the darkest tone (0.9) inks most texels
  for (int k = 0; k < 3; ++k) {
    ASSERT_FALSE(valuesPerTone[std::size_t(k)].empty()) << "tone " << k;
    EXPECT_GT(valuesPerTone[std::size_t(k)].size(), 5u) << "tone " << k << " is not graded";
    if (k > 0) EXPECT_LE(*valuesPerTone[std::size_t(k - 1)].rbegin(), *valuesPerTone[std::size_t(k)].begin() + 1) << "tone " << k;
  }

  const json parsed = test::runNodeChecker("check_ktx2.mjs", {settings.threshold});
  ASSERT_TRUE(parsed.is_object());
  EXPECT_EQ(parsed["layerCount"], 0);
  EXPECT_EQ(parsed["levelCount"], 7);
}

// --skip-levels: the TAM and the threshold texture lose their finest levels; what remains is the full
// bake's levels, byte for byte, and the metadata says how many were left out.
TEST(TamBake, SkipLevelsKeepsTheFullBakesCoarserLevels) {
  const fs::path dir = test::freshTempDir("tam_bake_skip");
  Settings full = smallSettings(dir);
  full.threshold = (dir / "threshold.ktx2").string();
  Settings skipped = smallSettings(dir);
  skipped.output = (dir / "skipped.ktx2").string();
  skipped.threshold = (dir / "skipped-threshold.ktx2").string();
  skipped.skipLevels = 2;
  ASSERT_TRUE(runQuietly(full).isOk());
  ASSERT_TRUE(runQuietly(skipped).isOk());
  for (const auto& [whole, part] : {std::pair{full.output, skipped.output}, std::pair{full.threshold, skipped.threshold}}) {
    Result<ktx2::Texture> a = ktx2::read(whole);
    Result<ktx2::Texture> b = ktx2::read(part);
    ASSERT_TRUE(a.isOk() && b.isOk());
    EXPECT_EQ(b->width, a->width / 4);
    ASSERT_EQ(b->levels.size() + 2, a->levels.size());
    for (std::size_t level = 0; level < b->levels.size(); ++level) EXPECT_EQ(b->levels[level], a->levels[level + 2]) << level;
    const json metadata = json::parse(b->text("BAKE_tam"));
    EXPECT_EQ(metadata["skippedLevels"], 2);
    EXPECT_EQ(metadata["strokeLevels"], std::max(0, json::parse(a->text("BAKE_tam"))["strokeLevels"].get<int>() - 2));
  }
  Settings tooMany = smallSettings(dir);
  tooMany.output = (dir / "none.ktx2").string();
  tooMany.skipLevels = 7;  // 64 x 64 has 7 levels: none would remain
  EXPECT_EQ(runQuietly(tooMany).code(), ExitCode::Usage);
  EXPECT_FALSE(fs::exists(tooMany.output));
}

TEST(TamBake, ZstdKeepsTheTexelsAndThreadsKeepTheBytes) {
  const fs::path dir = test::freshTempDir("tam_bake_zstd");
  Settings plain = smallSettings(dir);
  plain.common.threads = 1;
  ASSERT_TRUE(runQuietly(plain).isOk());
  Settings packed = smallSettings(dir);
  packed.output = (dir / "packed.ktx2").string();
  packed.zstd = true;
  packed.common.threads = 2;
  ASSERT_TRUE(runQuietly(packed).isOk());
  Result<ktx2::Texture> a = ktx2::read(plain.output);
  Result<ktx2::Texture> b = ktx2::read(packed.output);
  ASSERT_TRUE(a.isOk() && b.isOk());
  EXPECT_EQ(a->levels, b->levels);
  const json parsed = test::runNodeChecker("check_ktx2.mjs", {packed.output});
  ASSERT_TRUE(parsed.is_object());
  EXPECT_EQ(parsed["supercompressionScheme"], 2);  // Zstandard

  Settings again = smallSettings(dir);
  again.output = (dir / "again.ktx2").string();
  again.common.threads = 2;
  ASSERT_TRUE(runQuietly(again).isOk());
  EXPECT_EQ(test::readAll(plain.output), test::readAll(again.output));
}

TEST(TamBake, ColouredInkGivesRgbaWithTheBrightnessInAlpha) {
  const fs::path dir = test::freshTempDir("tam_bake_colour");
  Settings settings = smallSettings(dir);
  settings.style = dataFile("image.json").string();  // image strokes, ink (0.1, 0.2, 0.6)
  const Status status = runQuietly(settings);
  ASSERT_TRUE(status.isOk()) << status.describe();
  Result<ktx2::Texture> texture = ktx2::read(settings.output);
  ASSERT_TRUE(texture.isOk()) << texture.status().describe();
  EXPECT_EQ(texture->format, ktx2::Format::RGBA8);
  EXPECT_EQ(texture->layers, 2u);
  EXPECT_EQ(texture->width, 32u);
  EXPECT_EQ(texture->levels.size(), 6u);
  const json metadata = json::parse(texture->text("BAKE_tam"));
  EXPECT_EQ(metadata["colour"], true);
  EXPECT_EQ(metadata["style"], "image");
  // Untouched paper is white in every channel; elsewhere the blue ink absorbs more red than blue.
  const std::vector<std::uint8_t>& level = texture->levels[0];
  double redInk = 0, blueInk = 0, darkness = 0;
  for (std::size_t i = 0; i < level.size(); i += 4) {
    if (level[i + 3] == 255) {
      EXPECT_EQ(level[i], 255);
      EXPECT_EQ(level[i + 2], 255);
    }
    redInk += 255 - level[i];
    blueInk += 255 - level[i + 2];
    darkness += 255 - level[i + 3];
  }
  EXPECT_GT(redInk, blueInk);
  EXPECT_GT(darkness, 0);
  const json parsed = test::runNodeChecker("check_ktx2.mjs", {settings.output});
  ASSERT_TRUE(parsed.is_object());
  EXPECT_EQ(parsed["vkFormat"], ktx2::vkFormatOf(ktx2::Format::RGBA8));
  EXPECT_EQ(parsed["layerCount"], 2);
}

TEST(TamBake, SeedOverrideChangesTheStrokes) {
  const fs::path dir = test::freshTempDir("tam_bake_seed");
  Settings first = smallSettings(dir);
  ASSERT_TRUE(runQuietly(first).isOk());
  Settings other = smallSettings(dir);
  other.output = (dir / "other.ktx2").string();
  other.seed = 99;
  other.resolution = 32;
  other.candidates = 2;
  ASSERT_TRUE(runQuietly(other).isOk());
  Result<ktx2::Texture> texture = ktx2::read(other.output);
  ASSERT_TRUE(texture.isOk());
  EXPECT_EQ(texture->width, 32u);
  EXPECT_EQ(texture->levels.size(), 6u);
  EXPECT_EQ(json::parse(texture->text("BAKE_tam"))["seed"], 99);
}

TEST(TamBake, PackageCarriesTheMaterialAndTheEmbeddedKtx) {
  const fs::path dir = test::freshTempDir("tam_bake_package");
  Settings settings = smallSettings(dir);
  settings.threshold = (dir / "threshold.ktx2").string();
  settings.material.mesh = dataFile("cube.obj").string();
  settings.material.package = (dir / "cube.glb").string();
  settings.material.tilesPerUnit = 3;
  settings.material.rotationDegrees = 45;
  settings.material.translation = {0.25, -0.5};
  settings.material.orientation = "across-light";
  settings.material.baseColour = {0.9, 0.5, 0.25};
  settings.material.position = {1, 2, 3};
  settings.material.scale = 2;
  settings.common.reportPath = (dir / "report.json").string();
  const Status status = runQuietly(settings);
  ASSERT_TRUE(status.isOk()) << status.describe();

  Result<glb::Package> read = glb::read(settings.material.package);
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  const glb::Package& package = read.value();
  EXPECT_NE(std::find(package.extensionsUsed.begin(), package.extensionsUsed.end(), "BAKE_hatching"), package.extensionsUsed.end());
  ASSERT_EQ(package.materials.size(), 1u);
  const json& material = package.materials[0];
  EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"], json({0.9, 0.5, 0.25, 1.0}));
  const json& hatching = material["extensions"]["BAKE_hatching"];
  EXPECT_EQ(hatching["version"], 1);
  EXPECT_EQ(hatching["tones"].get<std::vector<double>>(), (std::vector<double>{0.3, 0.6, 0.9}));
  EXPECT_EQ(hatching["tilesPerUnit"], 3.0);
  EXPECT_NEAR(hatching["rotation"].get<double>(), std::numbers::pi / 4, 1e-12);
  EXPECT_EQ(hatching["translation"], json({0.25, -0.5}));
  EXPECT_EQ(hatching["orientation"], "across-light");
  EXPECT_EQ(hatching["baseColor"], json({0.9, 0.5, 0.25}));

  // The embedded images are the very KTX2 files written beside the package.
  for (const auto& [key, file] : {std::pair{"tam", settings.output}, std::pair{"threshold", settings.threshold}}) {
    ASSERT_TRUE(hatching.contains(key)) << key;
    const json& image = package.images.at(hatching[key].get<std::size_t>());
    EXPECT_EQ(image["mimeType"], "image/ktx2");
    const std::vector<std::uint8_t>& embedded = package.blobs.at(image["bufferView"].get<std::size_t>()).bytes;
    EXPECT_EQ(embedded, test::readAll(file)) << key;
    Result<ktx2::Texture> decoded = ktx2::decode(embedded, key);
    ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
    Result<ktx2::Texture> onDisk = ktx2::read(file);
    ASSERT_TRUE(onDisk.isOk());
    EXPECT_EQ(decoded->levels, onDisk->levels);
    EXPECT_EQ(decoded->text("BAKE_tam"), onDisk->text("BAKE_tam"));
  }

  // The cube: 8 corners, 12 triangles, unit normals pointing out of it.
  ASSERT_EQ(package.meshes.size(), 1u);
  ASSERT_EQ(package.meshes[0].primitives.size(), 1u);
  const glb::Primitive& primitive = package.meshes[0].primitives[0];
  EXPECT_EQ(primitive.material, 0);
  EXPECT_EQ(primitive.indices.size(), 36u);
  const glb::Attribute* positions = primitive.find("POSITION");
  const glb::Attribute* normals = primitive.find("NORMAL");
  ASSERT_TRUE(positions && normals);
  const std::vector<float> p = positions->toFloats(), n = normals->toFloats();
  ASSERT_EQ(p.size(), 24u);
  ASSERT_EQ(n.size(), 24u);
  for (int v = 0; v < 8; ++v) {
    EXPECT_NEAR(std::hypot(n[3 * v], n[3 * v + 1], n[3 * v + 2]), 1.0, 1e-6);
    EXPECT_GT(n[3 * v] * p[3 * v] + n[3 * v + 1] * p[3 * v + 1] + n[3 * v + 2] * p[3 * v + 2], 0.0) << "vertex " << v;
  }
  ASSERT_EQ(package.nodes.size(), 1u);
  EXPECT_EQ(package.nodes[0].mesh, 0);
  EXPECT_EQ(package.nodes[0].translation, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(package.nodes[0].scale, (std::array<double, 3>{2, 2, 2}));

  // The report holds the quality figures as scalars next to their references, the arrays in statistics.
  std::ifstream in(settings.common.reportPath);
  const json report = json::parse(in);
  ASSERT_TRUE(report["accuracy"].is_array());
  EXPECT_GE(report["accuracy"].size(), 4u);
  for (const json& entry : report["accuracy"])
    for (const auto& [name, value] : entry["metrics"].items()) EXPECT_TRUE(value.is_number()) << name;
  EXPECT_TRUE(report["statistics"].contains("quality"));
  // Rounding to 8 bits moves a layer's mean by at most half a step.
  const json& tone = report["accuracy"][0]["metrics"];
  EXPECT_LE(tone["maxToneErrorStored8Bit"].get<double>(), tone["maxToneError"].get<double>() + 0.5 / 255 + 1e-12);
  EXPECT_EQ(report["statistics"]["mesh"]["normalsComputed"], 8);
  std::vector<std::string> stages;
  for (const json& stage : report["stages"]) stages.push_back(stage["name"]);
  EXPECT_EQ(stages, (std::vector<std::string>{"read", "build", "measure", "encode", "write"}));
}

TEST(TamBake, FailureWritesNothingAndKeepsEarlierOutputs) {
  const fs::path dir = test::freshTempDir("tam_bake_failure");
  Settings settings = smallSettings(dir);
  settings.threshold = (dir / "threshold.ktx2").string();
  settings.material.mesh = (dir / "missing.obj").string();
  settings.material.package = (dir / "out.glb").string();
  ASSERT_TRUE(writeFileAtomic(settings.output, std::string("earlier")).isOk());
  const Status status = runQuietly(settings);
  EXPECT_EQ(status.code(), ExitCode::Io);
  EXPECT_EQ(status.where().file, settings.material.mesh);
  std::ifstream in(settings.output);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "earlier");
  EXPECT_FALSE(fs::exists(settings.threshold));
  EXPECT_FALSE(fs::exists(settings.material.package));
}

TEST(TamBake, SettingsAreChecked) {
  const fs::path dir = test::freshTempDir("tam_bake_settings");
  Settings settings = smallSettings(dir);
  settings.material.mesh = dataFile("cube.obj").string();
  EXPECT_EQ(runQuietly(settings).code(), ExitCode::Usage);  // --apply-to without --package
  settings = smallSettings(dir);
  settings.candidates = 0;
  EXPECT_EQ(runQuietly(settings).code(), ExitCode::Usage);
  settings = smallSettings(dir);
  settings.resolution = 48;
  EXPECT_EQ(runQuietly(settings).code(), ExitCode::Usage);
  settings = smallSettings(dir);
  settings.output = (dir / "tam.png").string();
  EXPECT_EQ(runQuietly(settings).code(), ExitCode::Usage);
  EXPECT_FALSE(fs::exists(dir / "tam.ktx2"));
}

// Extreme styles: the smallest tile, the most tones in it, tones at the ends of (0, 1), strokes too
// faint to reach their tone. Each bakes a decodable TAM whose layers darken monotonically, or says
// what it could not do; none hangs or writes garbage silently.
Result<ktx2::Texture> bakeStyle(const fs::path& dir, const std::string& name, const std::string& text, Diagnostics& diagnostics) {
  std::ofstream(dir / (name + ".json")) << text;
  Settings settings;
  settings.style = (dir / (name + ".json")).string();
  settings.output = (dir / (name + ".ktx2")).string();
  BAKE_RETURN_IF_ERROR(run(settings, diagnostics));
  return ktx2::read(settings.output);
}

TEST(TamBakeStiff, ExtremeStylesGiveMonotoneDecodableTams) {
  const fs::path dir = test::freshTempDir("tam_bake_stiff");
  const std::pair<const char*, const char*> styles[] = {
      {"smallest", R"({"tones": [0.5], "resolution": 8, "levels": 1})"},
      {"most_tones", R"({"tones": 16, "resolution": 8, "candidates": 2})"},
      {"extreme_tones", R"({"tones": [0.01, 0.999], "resolution": 16})"},
      {"wide_strokes", R"({"tones": 3, "resolution": 16, "stroke": {"width": {"min": 6, "max": 8}}})"},
      {"dots", R"({"tones": 4, "resolution": 32, "stroke": {"kind": "stippling"}})"},
  };
  for (const auto& [name, text] : styles) {
    Diagnostics diagnostics("tambake", true);
    Result<ktx2::Texture> texture = bakeStyle(dir, name, text, diagnostics);
    ASSERT_TRUE(texture.isOk()) << name << ": " << texture.status().describe();
    const std::uint32_t layers = texture->layers;
    EXPECT_EQ(texture->levels.size(), ktx2::fullMipCount(texture->width, texture->height)) << name;
    for (std::uint32_t level = 0; level < texture->levels.size(); ++level) {
      const std::vector<double> darkness = storedDarkness(texture.value(), level);
      ASSERT_EQ(darkness.size(), layers);
      for (std::uint32_t k = 1; k < layers; ++k)
        EXPECT_GE(darkness[k], darkness[k - 1] - 1e-12) << name << ": level " << level << ", layer " << k;
    }
  }
}

TEST(TamBakeStiff, UnreachableToneIsAWarningNamingIt) {
  const fs::path dir = test::freshTempDir("tam_bake_stiff_faint");
  Diagnostics diagnostics("tambake", true);
  Result<ktx2::Texture> texture =
      bakeStyle(dir, "faint", R"({"tones": [0.5], "resolution": 16, "levels": 1, "stroke": {"opacity": 0.001}})", diagnostics);
  ASSERT_TRUE(texture.isOk()) << texture.status().describe();
  ASSERT_EQ(diagnostics.warnings().count("tone-missed"), 1u);
  const std::string& message = diagnostics.warnings().at("tone-missed").message;
  EXPECT_NE(message.find("faint.json: tone 0 (target darkness 0.5)"), std::string::npos) << message;
}

TEST(TamBakeStored, DarknessIsReadFromRedOrAlpha) {
  ktx2::Texture grey;
  grey.format = ktx2::Format::R8;
  grey.width = grey.height = 2;
  grey.layers = 2;
  grey.levels = {{255, 255, 255, 255, 0, 255, 0, 255}, {255, 0}};
  EXPECT_EQ(storedDarkness(grey, 0), (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(storedDarkness(grey, 1), (std::vector<double>{0.0, 1.0}));
  ktx2::Texture colour;
  colour.format = ktx2::Format::RGBA8;
  colour.width = colour.height = 1;
  colour.layers = 1;
  colour.levels = {{0, 0, 0, 51}};
  EXPECT_NEAR(storedDarkness(colour, 0)[0], 0.8, 1e-12);
}

TEST(TamBakeNormals, OctahedronNormalsPointAlongTheVertices) {
  TriangleMesh mesh;
  mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {5, 5, 5}};  // + one unused vertex
  const std::uint32_t x[2] = {0, 1}, y[2] = {2, 3}, z[2] = {4, 5};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        // Counter-clockwise seen from outside: (x, y, z) is right-handed when the signs' product is +.
        const bool flip = (i + j + k) % 2 == 1;
        mesh.triangles.push_back(flip ? Triangle{x[i], z[k], y[j]} : Triangle{x[i], y[j], z[k]});
      }
  EXPECT_EQ(ensureUnitNormals(mesh), 7u);
  ASSERT_EQ(mesh.normals.size(), 7u);
  for (int v = 0; v < 6; ++v)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mesh.normals[v][c], mesh.positions[v][c], 1e-6) << v << " " << c;
  EXPECT_EQ(mesh.normals[6], (Vec3f{0, 0, 1}));  // no triangle gives it a direction
}

TEST(TamBakeNormals, GivenNormalsAreOnlyNormalised) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  mesh.normals = {{0, 0, 2}, {3, 4, 0}, {0, 0, 0}};
  EXPECT_EQ(ensureUnitNormals(mesh), 0u);
  EXPECT_EQ(mesh.normals[0], (Vec3f{0, 0, 1}));
  EXPECT_NEAR(mesh.normals[1][0], 0.6f, 1e-7);
  EXPECT_NEAR(mesh.normals[1][1], 0.8f, 1e-7);
  EXPECT_EQ(mesh.normals[2], (Vec3f{0, 0, 1}));
}

}  // namespace
}  // namespace bake::hatching
