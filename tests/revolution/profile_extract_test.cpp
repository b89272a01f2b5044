// Profiles from meshes of revolution and from coverage images.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "bake/io/glb.h"
#include "bake/revolution/bake.h"
#include "revolution/input/profile_extract.h"
#include "support/golden.h"

namespace bake::revolution {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalised(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

// Revolves the polyline (r, h) about the axis through `origin` along `axis` with `sectors` meridians;
// the ends of the polyline must lie on the axis (r = 0) so the mesh is closed.
TriangleMesh revolve(const std::vector<Point2>& polyline, int sectors, Vec3 origin, Vec3 axis) {
  axis = normalised(axis);
  const Vec3 seed = std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
  const Vec3 u = normalised(cross(axis, seed));
  const Vec3 v = cross(axis, u);
  TriangleMesh mesh;
  auto point = [&](Point2 p, double angle) {
    Vec3f out;
    for (int k = 0; k < 3; ++k)
      out[k] = float(origin[k] + p.h * axis[k] + p.r * (std::cos(angle) * u[k] + std::sin(angle) * v[k]));
    return out;
  };
  // Poles once; ring vertices per sector.
  const std::size_t rings = polyline.size() - 2;
  mesh.positions.push_back(point(polyline.front(), 0));
  for (std::size_t i = 1; i + 1 < polyline.size(); ++i)
    for (int s = 0; s < sectors; ++s) mesh.positions.push_back(point(polyline[i], 2 * std::numbers::pi * s / sectors));
  mesh.positions.push_back(point(polyline.back(), 0));
  const auto top = std::uint32_t(mesh.positions.size() - 1);
  auto ring = [&](std::size_t i, int s) { return std::uint32_t(1 + i * sectors + (s % sectors)); };
  for (int s = 0; s < sectors; ++s) {
    mesh.triangles.push_back({0, ring(0, s + 1), ring(0, s)});
    for (std::size_t i = 0; i + 1 < rings; ++i) {
      mesh.triangles.push_back({ring(i, s), ring(i, s + 1), ring(i + 1, s + 1)});
      mesh.triangles.push_back({ring(i, s), ring(i + 1, s + 1), ring(i + 1, s)});
    }
    mesh.triangles.push_back({ring(rings - 1, s), ring(rings - 1, s + 1), top});
  }
  return mesh;
}

const std::vector<Point2> kVaseLike{{0, 0}, {0.6, 0.05}, {0.9, 0.4}, {0.7, 0.9}, {0.4, 1.2}, {0.55, 1.5}, {0, 1.55}};

TEST(MeshProfile, AxisOfATiltedRevolvedMeshIsFound) {
  const Vec3 origin{0.3, -2.0, 5.0};
  const Vec3 axis = normalised({0.2, 1.0, -0.4});
  const TriangleMesh mesh = revolve(kVaseLike, 96, origin, axis);
  auto fit = fitRevolutionAxis(mesh, "vase");
  ASSERT_TRUE(fit.isOk()) << fit.status().describe();
  const double dot = fit->direction[0] * axis[0] + fit->direction[1] * axis[1] + fit->direction[2] * axis[2];
  EXPECT_GT(std::abs(dot), std::cos(1e-3)) << "axis off by more than a milliradian";
  // The fitted point lies on the true axis.
  const Vec3 d{fit->point[0] - origin[0], fit->point[1] - origin[1], fit->point[2] - origin[2]};
  const double along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
  const double off = std::sqrt(std::max(0.0, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along));
  EXPECT_LT(off, 1e-3);
  EXPECT_LT(std::abs(fit->pitch), 1e-3);
}

TEST(MeshProfile, SectionOfARevolvedMeshIsItsProfileWithinTheChordError) {
  const int sectors = 64;
  const TriangleMesh mesh = revolve(kVaseLike, sectors, {1, 2, 3}, {0, 0, 1});
  auto profile = profileOfMesh(mesh, "vase");
  ASSERT_TRUE(profile.isOk()) << profile.status().describe();
  ASSERT_EQ(profile->profile.contours.size(), 1u);
  // Between meridians the facets sag inwards by at most r (1 - cos(pi / sectors)); vertices lie on the
  // true profile, so no vertex is further than that from the section.
  const double sag = 0.9 * (1 - std::cos(std::numbers::pi / sectors));
  EXPECT_LE(profile->maxDeviation, sag * 1.05 + 1e-6);
  EXPECT_GT(profile->maxDeviation, 0.0);
  // The section spans the profile's height.
  const Bounds2 bounds = profileBounds(profile->profile);
  EXPECT_NEAR(bounds.hMax - bounds.hMin, 1.55, 1e-3);
  EXPECT_NEAR(bounds.rMax, 0.9, 0.9 * (1 - std::cos(std::numbers::pi / sectors)) + 1e-4);
}

TEST(MeshProfile, ABoxIsFarFromASurfaceOfRevolution) {
  TriangleMesh box;
  for (int k = 0; k < 8; ++k) box.positions.push_back({float(k & 1), float((k >> 1) & 1) * 2.0f, float((k >> 2) & 1)});
  const std::vector<Triangle> faces{{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  box.triangles = faces;
  auto profile = profileOfMesh(box, "box");
  ASSERT_TRUE(profile.isOk()) << profile.status().describe();
  EXPECT_GT(profile->maxDeviation / profile->objectSize, 0.05);
}

TEST(MeshProfile, RevolbakeTakesAMeshOfRevolutionAndPutsTheObjectBackOnIt) {
  const Vec3 origin{2.0, -1.0, 0.5};
  const Vec3 axis = normalised({1.0, 0.3, 0.0});
  const TriangleMesh mesh = revolve(kVaseLike, 64, origin, axis);
  const auto dir = test::freshTempDir("mesh_input");
  std::ofstream obj(dir / "vase.obj");
  for (const Vec3f& p : mesh.positions) obj << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const Triangle& t : mesh.triangles) obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  obj.close();
  Settings settings;
  settings.input = (dir / "vase.obj").string();
  settings.output = (dir / "vase.glb").string();
  settings.common.reportPath = (dir / "report.json").string();
  settings.resolution = 128;
  Diagnostics quiet("revolbake", true);
  const Status status = run(settings, quiet);
  ASSERT_TRUE(status.isOk()) << status.describe();
  nlohmann::json report;
  std::ifstream(settings.common.reportPath) >> report;
  const nlohmann::json& fit = report["statistics"]["meshOfRevolution"];
  EXPECT_LT(fit["maxDeviation"].get<double>(), 0.9 * (1 - std::cos(std::numbers::pi / 64)) * 1.05 + 1e-5);
  // The node's matrix maps the object's axis (+y) onto the mesh's axis, through a point on it.
  auto package = glb::read(settings.output);
  ASSERT_TRUE(package.isOk());
  ASSERT_TRUE(package->nodes[0].matrix.has_value());
  const auto& m = *package->nodes[0].matrix;
  const Vec3 y{m[4], m[5], m[6]};
  EXPECT_GT(std::abs(y[0] * axis[0] + y[1] * axis[1] + y[2] * axis[2]), std::cos(1e-3));
  const Vec3 d{m[12] - origin[0], m[13] - origin[1], m[14] - origin[2]};
  const double along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
  EXPECT_LT(std::sqrt(std::max(0.0, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along)), 1e-3);
}

CoverageImage discImage(int size, double radius, Point2 centre) {
  CoverageImage image;
  image.width = image.height = size;
  image.texelSize = 1.0 / size;
  image.coverage.resize(std::size_t(size) * size);
  const int sub = 16;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      int in = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          const double r = (i + (a + 0.5) / sub) / size, h = (j + (b + 0.5) / sub) / size;
          in += (r - centre.r) * (r - centre.r) + (h - centre.h) * (h - centre.h) < radius * radius ? 1 : 0;
        }
      image.coverage[std::size_t(j) * size + i] = float(in) / (sub * sub);
    }
  return image;
}

TEST(ImageProfile, ContourOfAnOffAxisDiscIsOneClosedCircle) {
  const CoverageImage image = discImage(128, 0.2, {0.5, 0.5});
  const Profile profile = contourOfCoverage(image);
  ASSERT_EQ(profile.contours.size(), 1u);
  EXPECT_TRUE(profile.contours[0].closed);
  for (const Segment& s : profile.contours[0].segments) {
    const double d = std::hypot(s.a.r - 0.5, s.a.h - 0.5) - 0.2;
    EXPECT_LT(std::abs(d), 0.1 / 128) << "contour point off the circle by more than 0.1 texel";
  }
}

TEST(ImageProfile, ADiscOnTheAxisGivesAnOpenContourEndingOnTheAxis) {
  const CoverageImage image = discImage(64, 0.3, {0.0, 0.5});
  const Profile profile = contourOfCoverage(image);
  ASSERT_EQ(profile.contours.size(), 1u);
  const Contour& contour = profile.contours[0];
  EXPECT_FALSE(contour.closed);
  EXPECT_EQ(contour.segments.front().a.r, 0.0);
  EXPECT_EQ(contour.segments.back().b.r, 0.0);
  for (const Segment& s : contour.segments) EXPECT_GE(s.a.r, 0.0);
}

}  // namespace
}  // namespace bake::revolution
