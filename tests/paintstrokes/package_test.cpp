// The BAKE_paintstrokes package (libbake/paintstrokes/package.h, formats/paintstrokes.md): round trip
// through a file, quantisation errors within the bounds the format states (step / 2 per axis,
// radiusStep / 2, 1/510 for unorm8), culling spheres that hold the densely sampled interpolated tube,
// bufferViews on 256-byte boundaries, the LINES preview, and the reader's refusal of tampered packages.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "bake_formats/paintstrokes.h"
#include "paintstrokes/package/package.h"
#include "support/golden.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;
namespace fmt = format::paintstrokes;

// Strokes with curved, uneven paths (Catmull-Rom overshoots at sharp turns), radii spanning a
// decade, random colours; two styles; one stroke far from the origin.
StrokeSet sampleStrokes() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  StrokeSet set;
  set.units = "m";
  set.styles.resize(2);
  set.styles[1].name = "fuzzy";
  set.styles[1].edgeOpacity = 0.2;
  set.styles[1].specular = {0.3, 0.3, 0.3};
  for (int s = 0; s < 12; ++s) {
    Stroke stroke;
    stroke.style = std::size_t(s % 2);
    const int n = 2 + s % 7;
    const double offset = s == 11 ? 1e4 : 0;
    for (int i = 0; i < n; ++i) {
      StrokePoint p;
      p.position = {offset + unit(rng) * 2 - 1, unit(rng) * 0.5 + i * 0.1, unit(rng) * 3};
      p.radius = 0.001 + 0.02 * unit(rng);
      p.colour = {unit(rng), unit(rng), unit(rng)};
      p.opacity = unit(rng);
      p.reflectance = unit(rng);
      stroke.points.push_back(p);
    }
    set.strokes.push_back(stroke);
  }
  return set;
}

std::size_t pointCount(const StrokeSet& set) {
  std::size_t n = 0;
  for (const Stroke& s : set.strokes) n += s.points.size();
  return n;
}

struct Baked {
  StrokeSet set;
  std::vector<Vec3d> directions;
  std::vector<double> shadows;
  QuantizationError error;
  std::vector<std::uint8_t> bytes;
};

Baked bake(StrokeSet set, std::vector<Vec3d> directions = {{0, 1, 0}, {0.6, 0.8, 0}}) {
  Baked baked;
  baked.set = std::move(set);
  baked.directions = std::move(directions);
  const std::size_t n = pointCount(baked.set) * baked.directions.size();
  for (std::size_t i = 0; i < n; ++i) baked.shadows.push_back(double(i % 97) / 96.0);
  Result<glb::Package> package = buildPaintstrokePackage(baked.set, baked.directions, baked.shadows, nullptr, &baked.error);
  EXPECT_TRUE(package.isOk()) << package.status().describe();
  if (!package.isOk()) return baked;
  Result<std::vector<std::uint8_t>> bytes = glb::encode(package.value());
  EXPECT_TRUE(bytes.isOk());
  baked.bytes = bytes.value();
  return baked;
}

json documentOf(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

// Uniform Catmull-Rom between p1 and p2 (the runtime's evaluation).
double catmullRom(double p0, double p1, double p2, double p3, double u) {
  return 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u + (3 * p1 - p0 - 3 * p2 + p3) * u * u * u);
}

TEST(PaintstrokesPackage, RoundTripKeepsEveryPointWithinTheStatedBounds) {
  const Baked baked = bake(sampleStrokes());
  const std::filesystem::path path = test::freshTempDir("strokes-package") / "strokes.glb";
  ASSERT_TRUE(glb::write(path, glb::decode(baked.bytes).value()).isOk());
  Result<PaintstrokePackage> read = readPaintstrokePackage(path);
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  const PaintstrokePackage& p = read.value();
  EXPECT_EQ(p.version, fmt::kVersion);
  EXPECT_EQ(p.units, "m");
  ASSERT_EQ(p.strokes.size(), baked.set.strokes.size());
  ASSERT_EQ(p.points.size(), pointCount(baked.set));
  ASSERT_EQ(p.styles.size(), 2u);
  EXPECT_EQ(p.styleNames, (std::vector<std::string>{"default", "fuzzy"}));
  EXPECT_FLOAT_EQ(p.styles[1].opacity[1], 0.2f);
  ASSERT_EQ(p.shadowDirections.size(), 2u);
  ASSERT_EQ(p.shadows.size(), baked.shadows.size());
  for (std::size_t i = 0; i < p.shadows.size(); ++i) EXPECT_LE(std::abs(p.shadows[i] / 255.0 - baked.shadows[i]), 1 / 510.0 + 1e-12);

  double worstPosition = 0, worstRadius = 0, worstUnorm = 0;
  for (std::size_t s = 0; s < p.strokes.size(); ++s) {
    const Stroke& in = baked.set.strokes[s];
    const fmt::Stroke& stored = p.strokes[s];
    EXPECT_EQ(stored.info[1], in.points.size());
    EXPECT_EQ(stored.info[2], in.style);
    for (std::size_t i = 0; i < in.points.size(); ++i) {
      const StrokePoint& x = in.points[i];
      const std::array<double, 4> back = p.positionRadius(s, i);
      for (int k = 0; k < 3; ++k) {
        // The bound is half a step of the stored (fp32) step; the dequantisation is done in double.
        const double e = std::abs(back[k] - x.position[k]);
        EXPECT_LE(e, stored.step[k] / 2.0 * (1 + 1e-9)) << "stroke " << s << " point " << i << " axis " << k;
        worstPosition = std::max(worstPosition, e);
      }
      const double er = std::abs(back[3] - x.radius);
      EXPECT_LE(er, stored.origin[3] / 2.0 * (1 + 1e-9)) << "stroke " << s << " point " << i;
      worstRadius = std::max(worstRadius, er);
      const fmt::ControlPoint& q = p.points[stored.info[0] + i];
      for (int k = 0; k < 3; ++k) worstUnorm = std::max(worstUnorm, std::abs(q.colour[k] / 255.0 - x.colour[k]));
      worstUnorm = std::max({worstUnorm, std::abs(q.opacity / 255.0 - x.opacity), std::abs(q.reflectance / 255.0 - x.reflectance)});
    }
  }
  EXPECT_LE(worstUnorm, 1 / 510.0 + 1e-12);
  // The errors the builder reports are the ones measured here.
  EXPECT_DOUBLE_EQ(baked.error.position, worstPosition);
  EXPECT_DOUBLE_EQ(baked.error.radius, worstRadius);
  EXPECT_DOUBLE_EQ(baked.error.unorm, worstUnorm);
  // Every box is at most 3 units on a side (z spans [0, 3]), the one at x = 1e4 included: its fp32
  // origin is at most one ulp (~1e-3) below its smallest x, which widens its x box to under 2.001.
  EXPECT_LT(worstPosition, 3.0 / 65535 / 2 * 1.001);
}

TEST(PaintstrokesPackage, CullingSpheresHoldTheInterpolatedTube) {
  const Baked baked = bake(sampleStrokes());
  const PaintstrokePackage p = decodePaintstrokePackage(glb::decode(baked.bytes).value(), "strokes.glb").value();
  for (std::size_t s = 0; s < baked.set.strokes.size(); ++s) {
    const auto& pts = baked.set.strokes[s].points;
    const float* sphere = p.strokes[s].sphere;
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
      // Beyond either end the neighbour is reflected through the end point (as the runtime does).
      auto at = [&](long j, auto get) {
        if (j < 0) return 2 * get(pts[0]) - get(pts[1]);
        if (j >= long(n)) return 2 * get(pts[n - 1]) - get(pts[n - 2]);
        return get(pts[std::size_t(j)]);
      };
      auto spline = [&](auto get, double u) {
        const long k = long(i);
        return catmullRom(at(k - 1, get), at(k, get), at(k + 1, get), at(k + 2, get), u);
      };
      for (int j = 0; j <= 200; ++j) {
        const double u = j / 200.0;
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
          const double x = spline([k](const StrokePoint& q) { return q.position[k]; }, u);
          d2 += (x - sphere[k]) * (x - sphere[k]);
        }
        const double r = spline([](const StrokePoint& q) { return q.radius; }, u);
        EXPECT_LE(std::sqrt(d2) + std::abs(r), double(sphere[3])) << "stroke " << s << " segment " << i << " u " << u;
      }
    }
    // Every sphere lies inside the package's bounds.
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(p.boundsMin[k], sphere[k] - sphere[3]);
      EXPECT_GE(p.boundsMax[k], sphere[k] + sphere[3]);
    }
  }
}

TEST(PaintstrokesPackage, BufferViewsStartOn256ByteBoundariesAndThePreviewIsLines) {
  const Baked baked = bake(sampleStrokes());
  const json document = documentOf(baked.bytes);
  const json& extension = document["materials"][0]["extensions"][fmt::kExtension];
  ASSERT_EQ(extension["bufferViews"].size(), fmt::kArrayCount);
  for (const auto& [key, view] : extension["bufferViews"].items()) {
    const json& bufferView = document["bufferViews"][view.get<std::size_t>()];
    EXPECT_EQ(bufferView.value("byteOffset", 0) % 256, 0) << key;
  }
  EXPECT_EQ(extension["strides"]["strokes"], 64);
  EXPECT_EQ(extension["strides"]["points"], 16);
  EXPECT_EQ(extension["strides"]["styles"], 48);
  EXPECT_EQ(extension["strides"]["shadows"], 1);
  EXPECT_EQ(document["extensionsUsed"], json::array({fmt::kExtension}));
  EXPECT_FALSE(document.contains("extensionsRequired"));

  const glb::Package package = glb::decode(baked.bytes).value();
  ASSERT_EQ(package.meshes.size(), 1u);
  const glb::Primitive& lines = package.meshes[0].primitives[0];
  EXPECT_EQ(lines.mode, 1);
  const std::size_t points = pointCount(baked.set);
  EXPECT_EQ(lines.vertexCount(), points);
  EXPECT_EQ(lines.indices.size(), 2 * (points - baked.set.strokes.size()));
}

TEST(PaintstrokesPackage, NoDirectionsStoresAnEmptyShadowTableAndAnExtraMeshGetsItsOwnMaterial) {
  glb::Mesh surface;
  surface.name = "ground";
  glb::Primitive triangle;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  triangle.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  surface.primitives.push_back(triangle);
  const StrokeSet set = sampleStrokes();
  Result<glb::Package> built = buildPaintstrokePackage(set, {}, {}, &surface);
  ASSERT_TRUE(built.isOk()) << built.status().describe();
  const glb::Package package = glb::decode(glb::encode(built.value()).value()).value();
  ASSERT_EQ(package.meshes.size(), 2u);
  EXPECT_EQ(package.meshes[1].primitives[0].material, 1);
  EXPECT_FALSE(package.materials[1].contains("extensions"));
  const PaintstrokePackage p = decodePaintstrokePackage(package, "plain.glb").value();
  EXPECT_TRUE(p.shadows.empty());
  EXPECT_TRUE(p.shadowDirections.empty());
}

TEST(PaintstrokesPackage, BuilderRefusesWhatTheFormatCannotHold) {
  StrokeSet set = sampleStrokes();
  set.strokes[3].style = 5;
  Result<glb::Package> r = buildPaintstrokePackage(set, {}, {}, nullptr);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().describe().find("stroke 3: style 5"), std::string::npos) << r.status().describe();
  set = sampleStrokes();
  set.strokes[2].points[1].position[0] = 1e31;
  r = buildPaintstrokePackage(set, {}, {}, nullptr);
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().describe().find("stroke 2, control point 1"), std::string::npos) << r.status().describe();
  r = buildPaintstrokePackage(sampleStrokes(), std::vector<Vec3d>(17, Vec3d{0, 1, 0}), {}, nullptr);
  EXPECT_FALSE(r.isOk());
}

// Edits an encoded package and decodes it again.
Result<PaintstrokePackage> tampered(const Baked& baked, const std::function<void(glb::Package&, json&)>& edit) {
  glb::Package package = glb::decode(baked.bytes).value();
  edit(package, package.materials[0]["extensions"][fmt::kExtension]);
  return decodePaintstrokePackage(package, "edited.glb");
}

template <class T>
void poke(glb::Package& package, std::size_t view, std::size_t item, const std::function<void(T&)>& edit) {
  T value;
  std::memcpy(&value, package.blobs[view].bytes.data() + item * sizeof(T), sizeof(T));
  edit(value);
  std::memcpy(package.blobs[view].bytes.data() + item * sizeof(T), &value, sizeof(T));
}

TEST(PaintstrokesPackage, ReaderRefusesTamperedPackagesNamingMaterialArrayAndItem) {
  const Baked baked = bake(sampleStrokes());
  auto expectRefused = [&](const std::function<void(glb::Package&, json&)>& edit, const char* fragment) {
    Result<PaintstrokePackage> r = tampered(baked, edit);
    ASSERT_FALSE(r.isOk()) << fragment;
    const std::string message = r.status().describe();
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_NE(message.find("edited.glb: material 0 (paintstrokes)"), std::string::npos) << message;
  };
  expectRefused([](glb::Package&, json& e) { e["version"] = 2; }, "version 2");
  expectRefused([](glb::Package&, json& e) { e["strides"]["points"] = 12; }, "strides/points");
  expectRefused([](glb::Package&, json& e) { e["counts"]["strokes"] = 100000; }, "bufferViews/strokes: BAKE_paintstrokes: bufferView 0 holds 12 items");
  expectRefused([](glb::Package&, json& e) { e["bufferViews"]["strokes"] = 99; }, "does not exist");
  expectRefused([](glb::Package&, json& e) { e["counts"]["shadows"] = 3; }, "counts/shadows");
  expectRefused([](glb::Package&, json& e) { e["counts"]["styles"] = 300; }, "counts/styles");
  expectRefused([](glb::Package&, json& e) { e["shadowDirections"][0] = {0, 2, 0}; }, "shadowDirections/0");
  expectRefused([](glb::Package&, json& e) { e["bounds"]["min"] = {0, "x", 0}; }, "bounds/min");
  expectRefused([](glb::Package&, json& e) { e.erase("counts"); }, "counts/strokes");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Stroke>(p, 0, 4, [](fmt::Stroke& s) { s.info[2] = 2; }); },
                "strokes/4: BAKE_paintstrokes: style 2 does not exist");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Stroke>(p, 0, 5, [](fmt::Stroke& s) { s.info[1] = 1; }); }, "strokes/5");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Stroke>(p, 0, 6, [](fmt::Stroke& s) { s.info[0] = 4000000000u; }); },
                "strokes/6");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Stroke>(p, 0, 7, [](fmt::Stroke& s) { s.step[1] = NAN; }); },
                "strokes/7: BAKE_paintstrokes: origin, step or culling sphere is not finite");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Stroke>(p, 0, 1, [](fmt::Stroke& s) { s.origin[3] = 0; }); }, "strokes/1");
  expectRefused([](glb::Package& p, json&) { poke<fmt::ControlPoint>(p, 1, 9, [](fmt::ControlPoint& q) { q.radius = 0; }); },
                "points/9");
  expectRefused([](glb::Package& p, json&) { poke<fmt::Style>(p, 2, 1, [](fmt::Style& s) { s.shading[0] = INFINITY; }); },
                "styles/1");
}

}  // namespace
}  // namespace bake::paintstrokes

namespace bake::paintstrokes {
namespace {

// Extreme placements: far from the origin (fp32 cannot hold the box's corner exactly), tiny strokes,
// flat axes, a radius 1e12 times thinner than its stroke's thickest. The stored values stay finite and
// the position bound (half the stored step) holds by construction of the fp32 box.
TEST(PaintstrokesStiffPackage, ExtremePlacementsKeepTheirBoundsAndFiniteRecords) {
  StrokeSet set;
  set.styles.emplace_back();
  auto stroke = [&](std::vector<Vec3d> positions, std::vector<double> radii) {
    Stroke s;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      StrokePoint p;
      p.position = positions[i];
      p.radius = radii[i];
      s.points.push_back(p);
    }
    set.strokes.push_back(s);
  };
  stroke({{1e25, 0, 0}, {1e25 + 1e-3, 1, 0}, {1e25 + 2e-3, 2, 0}}, {1, 1, 1});
  stroke({{1e-20, 1e-20, 0}, {2e-20, 1.5e-20, 0}}, {1e-21, 2e-21});
  stroke({{0.1, 0.2, 0.3}, {0.1, 0.2, 0.7}}, {1, 1e-12});  // flat x and y axes (0.1 is not an fp32 number)
  stroke({{-1e29, -1e29, 1e29}, {1e29, 1e29, -1e29}}, {1e28, 1e28});
  QuantizationError error;
  Result<glb::Package> built = buildPaintstrokePackage(set, {}, {}, nullptr, &error);
  ASSERT_TRUE(built.isOk()) << built.status().describe();
  Result<PaintstrokePackage> read = decodePaintstrokePackage(glb::decode(glb::encode(built.value()).value()).value(), "stiff.glb");
  ASSERT_TRUE(read.isOk()) << read.status().describe();
  const PaintstrokePackage& p = read.value();
  for (std::size_t s = 0; s < set.strokes.size(); ++s) {
    const fmt::Stroke& stored = p.strokes[s];
    for (int k = 0; k < 4; ++k) {
      EXPECT_TRUE(std::isfinite(stored.origin[k]) && std::isfinite(stored.step[k]) && std::isfinite(stored.sphere[k])) << s;
    }
    for (std::size_t i = 0; i < set.strokes[s].points.size(); ++i) {
      const std::array<double, 4> back = p.positionRadius(s, i);
      for (int k = 0; k < 3; ++k)
        EXPECT_LE(std::abs(back[k] - set.strokes[s].points[i].position[k]), stored.step[k] / 2.0 * (1 + 1e-9)) << s << " " << i << " " << k;
      EXPECT_GT(back[3], 0.0);
    }
  }
  // The flat axes of stroke 2 have a tiny non-zero step (0.1 and 0.2 are not fp32 numbers), so their
  // error is far below a float's rounding of 0.1.
  EXPECT_GT(p.strokes[2].step[0], 0.0f);
  EXPECT_LT(std::abs(p.positionRadius(2, 0)[0] - 0.1), 1e-12);
  // The radius 1e12 times thinner than its stroke's largest is stored as one step (the documented
  // exception to the radius bound): its error is below one step, not half.
  EXPECT_LE(std::abs(p.positionRadius(2, 1)[3] - 1e-12), double(p.strokes[2].origin[3]));
  // Stroke 0: 1e25 lies in [2^83, 2^84) (fp32 ulp 2^60, about 1.2e18); the 2e-3 extent is lost in it and the step
  // covers at most one ulp of the corner.
  EXPECT_LE(p.strokes[0].step[0], 1.3e18f / 65535 * 2);
}

}  // namespace
}  // namespace bake::paintstrokes

namespace bake::paintstrokes {
namespace {

// A radius below half a quantisation step (1e-6 on a 0.35-thick stroke) is stored as one step: the
// stated radius bound must cover it, for that stroke and in the package as a whole.
TEST(PaintstrokesPackage, RadiusBoundHoldsForRadiiBelowHalfAStep) {
  StrokeSet set;
  set.styles.resize(1);
  Stroke stroke;
  for (double radius : {0.35, 1e-6, 0.2}) {
    StrokePoint p;
    p.position = {double(stroke.points.size()), 0, 0};
    p.radius = radius;
    stroke.points.push_back(p);
  }
  set.strokes.push_back(stroke);
  const Baked baked = bake(set, {{0, 1, 0}});
  const double step = 0.35 / fmt::kRadiusLevels;
  EXPECT_GT(baked.error.radius, 0.5 * step * (1 + 1e-6));  // the thin radius is off by nearly a step
  EXPECT_LE(baked.error.radius, baked.error.radiusBound);
  EXPECT_LT(baked.error.radiusBound, 1.01 * step);
  // Without thin radii the bound is half a step.
  set.strokes[0].points[1].radius = 0.1;
  const Baked plain = bake(set, {{0, 1, 0}});
  EXPECT_LE(plain.error.radius, plain.error.radiusBound);
  EXPECT_LT(plain.error.radiusBound, 0.51 * step);
}

}  // namespace
}  // namespace bake::paintstrokes
