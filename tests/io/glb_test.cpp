#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "bake/core/atomic_file.h"
#include "bake/io/glb.h"
#include "support/golden.h"
#include "support/node_check.h"

namespace bake::glb {
namespace {
namespace fs = std::filesystem;

// A wavy n x n grid with positions, normals, uvs, one float and one unorm16 application attribute,
// a vendor extension pointing at a blob, and a named node.
Package samplePackage(int n = 10) {
  std::vector<float> positions, normals, uvs, field0, field1;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float u = float(i) / float(n - 1), v = float(j) / float(n - 1);
      positions.insert(positions.end(), {u * 2.0f - 1.0f, 0.1f * std::sin(6.0f * u) * v, v * 2.0f - 1.0f});
      normals.insert(normals.end(), {0.0f, 1.0f, 0.0f});
      uvs.insert(uvs.end(), {u, v});
      field0.push_back(std::hypot(u - 0.3f, v - 0.6f) * 7.5f);
      field1.push_back(std::hypot(u, v) / std::sqrt(2.0f));
    }
  }
  Primitive primitive;
  primitive.attributes.push_back(Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(Attribute::fromFloats("NORMAL", 3, normals));
  primitive.attributes.push_back(Attribute::fromFloats("TEXCOORD_0", 2, uvs));
  primitive.attributes.push_back(Attribute::fromFloats("_GEODESIC_0", 1, field0));
  primitive.attributes.push_back(Attribute::fromUnorm16("_GEODESIC_1", 1, field1));
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
      primitive.indices.insert(primitive.indices.end(), {a, c, b, b, c, d});
    }
  }
  primitive.material = 0;
  Package package;
  package.meshes.push_back({"grid", {primitive}});
  package.nodes.push_back(Node{"grid", 0, {}, std::nullopt});
  package.materials = nlohmann::json::array({{{"name", "geodesic"},
                                              {"extensions", {{"BAKE_test", {{"version", 1}, {"field", 0}}}}}}});
  package.extensions["BAKE_test"] = {{"version", 1}, {"table", {{"bufferView", 0}}}};
  package.blobs.push_back(Blob{{1, 2, 3, 4, 5, 6, 7}, 16});
  return package;
}

TEST(Glb, RoundTripKeepsEveryValue) {
  const Package original = samplePackage();
  auto bytes = encode(original);
  ASSERT_TRUE(bytes.isOk()) << bytes.status().describe();
  auto decoded = decode(*bytes, "sample.glb");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  ASSERT_EQ(decoded->meshes.size(), 1u);
  const Primitive& a = original.meshes[0].primitives[0];
  const Primitive& b = decoded->meshes[0].primitives[0];
  EXPECT_EQ(a.indices, b.indices);
  ASSERT_EQ(a.attributes.size(), b.attributes.size());
  for (const Attribute& attribute : a.attributes) {
    const Attribute* read = b.find(attribute.name);
    ASSERT_NE(read, nullptr) << attribute.name;
    EXPECT_EQ(read->componentType, attribute.componentType) << attribute.name;
    EXPECT_EQ(read->normalized, attribute.normalized) << attribute.name;
    EXPECT_EQ(read->bytes, attribute.bytes) << attribute.name;
  }
  EXPECT_EQ(decoded->extensions["BAKE_test"]["version"], 1);
  EXPECT_EQ(decoded->materials[0]["extensions"]["BAKE_test"]["field"], 0);
  ASSERT_GE(decoded->blobs.size(), 1u);
  EXPECT_EQ(decoded->blobs[0].bytes, original.blobs[0].bytes);
  EXPECT_EQ(decoded->nodes.at(0).name, "grid");
  EXPECT_NE(std::find(decoded->extensionsUsed.begin(), decoded->extensionsUsed.end(), "BAKE_test"),
            decoded->extensionsUsed.end());
}

TEST(Glb, OutputIsDeterministic) {
  WriteOptions draco;
  draco.draco.enabled = true;
  EXPECT_EQ(encode(samplePackage()).value(), encode(samplePackage()).value());
  EXPECT_EQ(encode(samplePackage(), draco).value(), encode(samplePackage(), draco).value());
}

TEST(Glb, Unorm16QuantisesToNearest) {
  const std::vector<float> values = {0.0f, 1.0f, 0.5f, 1.0f / 65535.0f, 2.0f, -1.0f};
  const std::vector<float> back = Attribute::fromUnorm16("_X", 1, values).toFloats();
  EXPECT_EQ(back[0], 0.0f);
  EXPECT_EQ(back[1], 1.0f);
  EXPECT_NEAR(back[2], 0.5f, 0.5 / 65535.0);
  EXPECT_FLOAT_EQ(back[3], 1.0f / 65535.0f);
  EXPECT_EQ(back[4], 1.0f);  // clamped
  EXPECT_EQ(back[5], 0.0f);
}

// For Draco's reordered output: the original vertex closest to each decoded one.
std::vector<std::size_t> matchVertices(const Attribute& original, const Attribute& decoded) {
  const std::vector<float> a = original.toFloats(), b = decoded.toFloats();
  std::vector<std::size_t> match(decoded.count());
  for (std::size_t i = 0; i < decoded.count(); ++i) {
    double best = INFINITY;
    for (std::size_t j = 0; j < original.count(); ++j) {
      double d = 0;
      for (int c = 0; c < 3; ++c) d += std::pow(double(a[3 * j + c]) - b[3 * i + c], 2);
      if (d < best) best = d, match[i] = j;
    }
  }
  return match;
}

std::set<std::array<std::size_t, 3>> triangleSet(const std::vector<std::uint32_t>& indices,
                                                 const std::vector<std::size_t>& map) {
  std::set<std::array<std::size_t, 3>> out;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::array<std::size_t, 3> tri = {map[indices[t]], map[indices[t + 1]], map[indices[t + 2]]};
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());  // keep winding
    out.insert(tri);
  }
  return out;
}

void expectDracoRoundTrip(bool preserveOrder) {
  const Package original = samplePackage();
  WriteOptions options;
  options.draco.enabled = true;
  options.draco.preserveOrder = preserveOrder;
  auto bytes = encode(original, options);
  ASSERT_TRUE(bytes.isOk()) << bytes.status().describe();
  auto decoded = decode(*bytes, "draco.glb");
  ASSERT_TRUE(decoded.isOk()) << decoded.status().describe();
  const Primitive& a = original.meshes[0].primitives[0];
  const Primitive& b = decoded->meshes[0].primitives[0];
  ASSERT_EQ(b.vertexCount(), a.vertexCount());
  ASSERT_EQ(b.indices.size(), a.indices.size());

  std::vector<std::size_t> map(b.vertexCount());
  if (preserveOrder) {
    for (std::size_t i = 0; i < map.size(); ++i) map[i] = i;
  } else {
    map = matchVertices(*a.find("POSITION"), *b.find("POSITION"));
  }
  std::vector<std::size_t> identity(a.vertexCount());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = i;
  EXPECT_EQ(triangleSet(b.indices, map), triangleSet(a.indices, identity));

  for (const char* name : {"POSITION", "TEXCOORD_0", "_GEODESIC_0", "_GEODESIC_1"}) {
    const Attribute& source = *a.find(name);
    // The documented bound, plus float rounding of the dequantised value itself.
    const double bound = dracoQuantizationBound(source, options.draco) * (1 + 1e-6) + 1e-7;
    const std::vector<float> x = source.toFloats(), y = b.find(name)->toFloats();
    double worst = 0;
    for (std::size_t i = 0; i < map.size(); ++i) {
      for (int c = 0; c < source.components; ++c) {
        worst = std::max(worst, std::abs(double(y[i * source.components + c]) - x[map[i] * source.components + c]));
      }
    }
    if (source.componentType == ComponentType::F32) {
      EXPECT_GT(bound, 0.0) << name;
      EXPECT_LE(worst, bound) << name << " exceeds the quantization bound";
    } else {
      EXPECT_EQ(worst, 0.0) << name << " is integer data: Draco stores it losslessly";
    }
  }
}

TEST(Glb, DracoRoundTripWithinQuantizationBound) { expectDracoRoundTrip(false); }
TEST(Glb, DracoSequentialKeepsOrder) { expectDracoRoundTrip(true); }

TEST(Glb, DracoIsSmaller) {
  WriteOptions options;
  options.draco.enabled = true;
  EXPECT_LT(encode(samplePackage(40), options)->size(), encode(samplePackage(40))->size());
}

TEST(Glb, KhronosValidatorReportsNoErrors) {
  const fs::path dir = test::freshTempDir("glb_validator");
  WriteOptions draco;
  draco.draco.enabled = true;
  ASSERT_TRUE(write(dir / "plain.glb", samplePackage()).isOk());
  ASSERT_TRUE(write(dir / "draco.glb", samplePackage(), draco).isOk());
  for (const char* file : {"plain.glb", "draco.glb"}) {
    const nlohmann::json report = test::runNodeChecker("validate_gltf.mjs", {(dir / file).string()});
    ASSERT_FALSE(report.is_null());
    EXPECT_EQ(report["numErrors"], 0) << file << ": " << report.dump(2);
    EXPECT_EQ(report["numWarnings"], 0) << file << ": " << report.dump(2);
  }
}

TEST(Glb, RejectsBadPrimitives) {
  Package package = samplePackage();
  package.meshes[0].primitives[0].indices.push_back(1000);
  EXPECT_EQ(encode(package).status().code(), ExitCode::InvalidInput);
  package = samplePackage();
  package.meshes[0].primitives[0].attributes.push_back(Attribute::fromFloats("GEODESIC", 1, std::vector<float>(100)));
  EXPECT_EQ(encode(package).status().code(), ExitCode::InvalidInput);
  package = samplePackage();
  package.meshes[0].primitives[0].attributes.push_back(Attribute::fromFloats("_SHORT", 1, std::vector<float>(3)));
  EXPECT_EQ(encode(package).status().code(), ExitCode::InvalidInput);
}

// Pins the bytes of format version 1 (see tests/golden/README.md for the update mode).
TEST(Glb, GoldenPackageV1) {
  const auto bytes = encode(samplePackage(4));
  ASSERT_TRUE(bytes.isOk());
  EXPECT_TRUE(test::matchesGolden("io/glb/sample.bake-v1.glb", *bytes));
  // The committed golden must keep decoding, whatever the writer does today.
  const auto golden = read(test::goldenPath("io/glb/sample.bake-v1.glb"));
  ASSERT_TRUE(golden.isOk()) << golden.status().describe();
  EXPECT_EQ(golden->meshes.at(0).primitives.at(0).vertexCount(), 16u);
}

TEST(Glb, DamagedFilesGiveErrorsNeverCrashes) {
  std::vector<std::uint8_t> good = encode(samplePackage(3)).value();
  for (std::size_t size = 0; size < good.size(); size += 7) {
    const auto result = decode(std::span(good.data(), size), "cut.glb");
    EXPECT_FALSE(result.isOk()) << "prefix of " << size << " bytes decoded";
    if (!result.isOk()) EXPECT_NE(result.status().code(), ExitCode::Internal);
  }
  // Flip bytes through the whole file: errors or (harmless) successes, never a crash.
  for (std::size_t i = 0; i < good.size(); i += 3) {
    std::vector<std::uint8_t> bad = good;
    bad[i] ^= 0x5A;
    const auto result = decode(bad, "flipped.glb");
    if (!result.isOk()) EXPECT_NE(result.status().code(), ExitCode::Internal) << "byte " << i;
  }
  std::vector<std::uint8_t> wrongMagic = good;
  wrongMagic[0] = 'X';
  const auto magic = decode(wrongMagic, "x.glb");
  EXPECT_EQ(magic.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(magic.status().describe().find("x.glb: header: not a GLB file"), std::string::npos);
}

}  // namespace
}  // namespace bake::glb
