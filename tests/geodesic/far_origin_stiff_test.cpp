// Stiff cases (label stiff): a mesh far from the origin, at offsets no float can hold (1e7 + a
// fraction), written as OBJ, OFF and ASCII PLY text in full double precision and as a glTF whose node
// translation carries the offset. Read with MeshReadOptions::nearOrigin, every geodesic method must give
// the distances it gives at the origin (exact to 1e-6 of the largest distance, the others to round-off
// of their own arithmetic) and the same heat error against exact. Read as plain floats, the same file
// loses the mesh (the last check shows the test can tell).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "bake/geodesic/surface.h"
#include "bake/io/glb.h"
#include "bake/io/mesh.h"
#include "geodesic/bake/methods.h"

namespace bake::geodesic {
namespace {

namespace fs = std::filesystem;

// A bumpy 32 x 32 sheet over [0, 1]^2 (z = 0.08 sin 5x cos 4y): distances are not Euclidean.
struct Sheet {
  std::vector<Vec3d> points;
  std::vector<Triangle> triangles;
};

Sheet bumpySheet() {
  constexpr int n = 32;
  Sheet sheet;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      sheet.points.push_back({x, y, 0.08 * std::sin(5.0 * x) * std::cos(4.0 * y)});
    }
  auto at = [](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      sheet.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      sheet.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return sheet;
}

std::string exactText(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

fs::path writeText(const Sheet& sheet, const Vec3d& offset, const std::string& format, const std::string& stem) {
  const fs::path path = fs::path(BAKE_TEST_TMP) / (stem + "." + format);
  fs::create_directories(path.parent_path());
  std::ofstream out(path);
  auto point = [&](const Vec3d& p) {
    return exactText(p[0] + offset[0]) + " " + exactText(p[1] + offset[1]) + " " + exactText(p[2] + offset[2]);
  };
  if (format == "obj") {
    for (const Vec3d& p : sheet.points) out << "v " << point(p) << "\n";
    for (const Triangle& t : sheet.triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  } else if (format == "off") {
    out << "OFF\n" << sheet.points.size() << " " << sheet.triangles.size() << " 0\n";
    for (const Vec3d& p : sheet.points) out << point(p) << "\n";
    for (const Triangle& t : sheet.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  } else {
    out << "ply\nformat ascii 1.0\nelement vertex " << sheet.points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << sheet.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Vec3d& p : sheet.points) out << point(p) << "\n";
    for (const Triangle& t : sheet.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  return path;
}

// The sheet in float at the origin, placed by its node's translation (double in the JSON).
fs::path writeGltf(const Sheet& sheet, const Vec3d& offset, const std::string& stem) {
  glb::Primitive primitive;
  std::vector<float> flat;
  for (const Vec3d& p : sheet.points) flat.insert(flat.end(), {float(p[0]), float(p[1]), float(p[2])});
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, flat));
  for (const Triangle& t : sheet.triangles) primitive.indices.insert(primitive.indices.end(), t.begin(), t.end());
  glb::Package package;
  package.meshes.push_back({"sheet", {primitive}});
  glb::Node node;
  node.mesh = 0;
  node.translation = offset;
  package.nodes.push_back(node);
  const fs::path path = fs::path(BAKE_TEST_TMP) / (stem + ".glb");
  fs::create_directories(path.parent_path());
  const Status written = glb::write(path, package);
  EXPECT_TRUE(written.isOk()) << written.describe();
  return path;
}

struct Fields {
  std::vector<double> exact, heat, fmm;
};

// Every method from input vertex 0 (the sheet's corner).
Fields solveAll(const fs::path& path, bool nearOrigin) {
  MeshReadOptions options;
  options.nearOrigin = nearOrigin;
  Result<TriangleMesh> mesh = readMesh(path, options);
  EXPECT_TRUE(mesh.isOk()) << mesh.status().describe();
  if (!mesh.isOk()) return {};
  const SurfaceBuild build = buildSurface(mesh.value());
  const std::vector<SurfacePoint> sources{vertexPoint(build.surface, build.vertexMap[0])};
  Fields fields;
  auto perInput = [&](const std::vector<double>& onSurface) {
    std::vector<double> out;
    for (std::uint32_t v : build.vertexMap) out.push_back(onSurface[v]);
    return out;
  };
  fields.exact = perInput(exactDistances(build.surface, sources));
  fields.fmm = perInput(fastMarchingDistances(build.surface, sources));
  Result<HeatSolver> heat = HeatSolver::build(build.surface);
  EXPECT_TRUE(heat.isOk()) << heat.status().describe();
  if (heat.isOk()) fields.heat = perInput(heat.value().distances(sources));
  return fields;
}

// Largest |a - b| over the largest |b|.
double relativeGap(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double gap = 0.0, largest = 0.0;
  for (std::size_t v = 0; v < a.size() && v < b.size(); ++v) {
    gap = std::max(gap, std::abs(a[v] - b[v]));
    largest = std::max(largest, std::abs(b[v]));
  }
  return largest > 0.0 ? gap / largest : gap;
}

// Mean |heat - exact| relative to the largest exact distance.
double meanHeatError(const Fields& fields) {
  double sum = 0.0, largest = 0.0;
  for (double d : fields.exact) largest = std::max(largest, d);
  for (std::size_t v = 0; v < fields.exact.size(); ++v) sum += std::abs(fields.heat[v] - fields.exact[v]);
  return sum / double(fields.exact.size()) / largest;
}

// Offsets whose fractions no float at their magnitude holds.
const Vec3d kOffsets[] = {{1.0e7 + 0.123456789, -2.5e6 - 0.314159265, 3.3e5 + 0.271828183},
                          {1.0e3 + 0.1, 1.0e5 + 0.7, -7.0e4 - 0.3},
                          {-1.0e7 - 0.9, 1.0e7 + 0.45, 0.0}};

class StiffFarFromOrigin : public ::testing::TestWithParam<std::string> {};

TEST_P(StiffFarFromOrigin, SameDistancesAsAtTheOrigin) {
  const Sheet sheet = bumpySheet();
  const std::string format = GetParam();
  auto write = [&](const Vec3d& offset, const std::string& stem) {
    return format == "glb" ? writeGltf(sheet, offset, stem) : writeText(sheet, offset, format, stem);
  };
  const Fields atOrigin = solveAll(write({0, 0, 0}, "far-origin-0-" + format), true);
  ASSERT_FALSE(atOrigin.exact.empty());
  for (std::size_t o = 0; o < std::size(kOffsets); ++o) {
    SCOPED_TRACE(format + " offset " + std::to_string(o));
    const Fields far = solveAll(write(kOffsets[o], "far-origin-" + std::to_string(o + 1) + "-" + format), true);
    ASSERT_FALSE(far.exact.empty());
    std::printf("[ far ] %s offset %zu: exact %.2g, fmm %.2g, heat %.2g of the largest distance; heat error %.6f vs %.6f\n",
                format.c_str(), o, relativeGap(far.exact, atOrigin.exact), relativeGap(far.fmm, atOrigin.fmm),
                relativeGap(far.heat, atOrigin.heat), meanHeatError(far), meanHeatError(atOrigin));
    EXPECT_LE(relativeGap(far.exact, atOrigin.exact), 1e-6);
    EXPECT_LE(relativeGap(far.fmm, atOrigin.fmm), 1e-6);
    EXPECT_LE(relativeGap(far.heat, atOrigin.heat), 1e-5);
    EXPECT_NEAR(meanHeatError(far), meanHeatError(atOrigin), 1e-6);
  }
}

TEST_P(StiffFarFromOrigin, PlainFloatsLoseTheMeshThere) {
  // The same file read without nearOrigin: at 1e7 a float's step is 1, the sheet is 1 across.
  const Sheet sheet = bumpySheet();
  const std::string format = GetParam();
  const fs::path path = format == "glb" ? writeGltf(sheet, kOffsets[0], "far-origin-plain-" + format)
                                        : writeText(sheet, kOffsets[0], format, "far-origin-plain-" + format);
  const Fields atOrigin = solveAll(format == "glb" ? writeGltf(sheet, {0, 0, 0}, "far-origin-plain-0-" + format)
                                                   : writeText(sheet, {0, 0, 0}, format, "far-origin-plain-0-" + format),
                                   false);
  const Fields plain = solveAll(path, false);
  ASSERT_FALSE(plain.exact.empty());
  EXPECT_GT(relativeGap(plain.exact, atOrigin.exact), 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Formats, StiffFarFromOrigin, ::testing::Values("obj", "off", "ply", "glb"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace bake::geodesic
