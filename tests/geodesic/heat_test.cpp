// The heat method: its intrinsic triangulation (tufted cover, mollification, Delaunay flips), the time
// step rule, and distances against analytic answers (a sphere: R * angle; a plane: Euclidean).
#include "bake/geodesic/heat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "geodesic/bake/heat_intrinsic.h"
#include "geodesic/bake/heat_timestep.h"
#include "geodesic/heat_meshes.h"

namespace bake::geodesic {
namespace {

using testing::FieldError;
using testing::geodesicSphere;
using testing::planarGrid;
using testing::relativeError;

HeatSolver buildSolver(const Surface& surface, const HeatOptions& options = {}) {
  Result<HeatSolver> solver = HeatSolver::build(surface, options);
  EXPECT_TRUE(solver.isOk()) << solver.status().describe();
  return std::move(solver).value();
}

std::vector<double> euclideanFrom(const Surface& s, const std::vector<Vec3d>& points) {
  std::vector<double> d(s.vertexCount(), kUnreachable);
  for (std::size_t v = 0; v < s.vertexCount(); ++v)
    for (const Vec3d& p : points)
      d[v] = std::min(d[v], std::hypot(s.positions[v][0] - p[0], s.positions[v][1] - p[1],
                                       s.positions[v][2] - p[2]));
  return d;
}

void expectFiniteNonNegative(const std::vector<double>& d) {
  for (double x : d) {
    EXPECT_FALSE(std::isnan(x));
    EXPECT_GE(x, 0.0);
  }
}

// Every halfedge has a distinct twin running the other way along an edge of the same length.
void expectClosedComplex(const IntrinsicTriangulation& m) {
  for (std::uint32_t h = 0; h < m.tail.size(); ++h) {
    const std::uint32_t t = m.twin[h];
    ASSERT_NE(t, h);
    EXPECT_EQ(m.twin[t], h);
    EXPECT_EQ(m.edgeOf[t], m.edgeOf[h]);
    EXPECT_EQ(m.tail[t], m.tail[IntrinsicTriangulation::next(h)]);
  }
}

TEST(HeatIntrinsic, TuftedCoverGluesANonManifoldEdgeInACycle) {
  // Three pages of a book on the spine 0-1.
  const Surface s = makeSurface({{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {-0.5, 0.8, 0.5}, {-0.5, -0.8, 0.5}},
                                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  IntrinsicBuildStats stats;
  const IntrinsicTriangulation m = buildTuftedCover(s, stats);
  EXPECT_EQ(stats.nonManifoldEdges, 1u);
  EXPECT_TRUE(stats.doubled);
  EXPECT_EQ(m.faceCount(), 6u);
  EXPECT_EQ(m.edgeCount(), 9u);  // 3 spine gluings + 6 boundary edges glued to their own other side
  expectClosedComplex(m);
}

TEST(HeatIntrinsic, ClosedOrientedSurfaceTakesEachFaceOnce) {
  const Surface s = geodesicSphere(1, 1.0);
  IntrinsicBuildStats stats;
  const IntrinsicTriangulation m = buildTuftedCover(s, stats);
  EXPECT_FALSE(stats.doubled);
  EXPECT_EQ(m.faceCount(), s.triangleCount());
  EXPECT_EQ(m.edgeCount(), s.edgeCount());
  expectClosedComplex(m);
}

TEST(HeatIntrinsic, MollifyGivesEveryTriangleTheMargin) {
  // A flat triangle (collinear corners) and a needle.
  const Surface s = makeSurface({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1e-9, 0}}, {{0, 1, 2}, {0, 3, 1}});
  IntrinsicBuildStats stats;
  IntrinsicTriangulation m = buildTuftedCover(s, stats);
  const double delta = 1e-3;
  EXPECT_GT(mollify(m, delta), 0.0);
  for (std::uint32_t f = 0; f < m.faceCount(); ++f) {
    const double a = m.lengthOf(3 * f), b = m.lengthOf(3 * f + 1), c = m.lengthOf(3 * f + 2);
    EXPECT_GE(b + c - a, delta * (1 - 1e-9));
    EXPECT_GE(c + a - b, delta * (1 - 1e-9));
    EXPECT_GE(a + b - c, delta * (1 - 1e-9));
  }
}

TEST(HeatIntrinsic, FlipReplacesTheLongDiagonalOfAThinKite) {
  // Triangles (0, 1, 2) and (1, 0, 3) share the long diagonal 0-1; the angles facing it are obtuse.
  const Surface s = makeSurface({{0, 0, 0}, {2, 0, 0}, {1, 0.2, 0}, {1, -0.2, 0}}, {{0, 1, 2}, {1, 0, 3}});
  IntrinsicBuildStats stats;
  IntrinsicTriangulation m = buildTuftedCover(s, stats);
  EXPECT_EQ(flipToDelaunay(m), 2u);  // once on each side of the doubled cover
  std::size_t shortDiagonals = 0;
  for (double l : m.length) shortDiagonals += std::abs(l - 0.4) < 1e-12;
  EXPECT_EQ(shortDiagonals, 2u);
  expectClosedComplex(m);
  // Delaunay now: every pair of opposite angles sums to at most pi.
  for (std::uint32_t e = 0; e < m.edgeCount(); ++e) {
    double cotSum = 0.0;
    for (std::uint32_t h : {m.edgeHalfedge[e], m.twin[m.edgeHalfedge[e]]}) {
      const double a = m.lengthOf(h), b = m.lengthOf(IntrinsicTriangulation::next(h)),
                   c = m.lengthOf(IntrinsicTriangulation::prev(h));
      cotSum += cotangentOpposite(a, b, c, triangleArea(a, b, c));
    }
    EXPECT_GE(cotSum, -1e-12);
  }
}

TEST(HeatTimeStep, BoundedBelowByTheExtent) {
  EXPECT_DOUBLE_EQ(heatTimeStep(0.1, 2.0, 0.0), 0.01);  // small mesh: t = h^2
  const double floor = 1000.0 / kMaxDecayLengths;
  EXPECT_DOUBLE_EQ(heatTimeStep(1.0, 1000.0, 0.0), floor * floor);
  EXPECT_DOUBLE_EQ(heatTimeStep(0.5, 1000.0, 3.0), 0.75);  // an explicit factor wins
}

TEST(HeatTimeStep, ExtentOfASquareLiesBetweenItsDiagonalAndTwoSides) {
  const Surface s = planarGrid(8, 1.0);
  const double extent = estimateGeodesicExtent(s);  // along edges: never shorter than the true geodesic
  EXPECT_GE(extent, std::sqrt(2.0) - 1e-12);
  EXPECT_LE(extent, 2.0 + 1e-12);
}

TEST(HeatSolver, SphereDistanceIsRadiusTimesAngle) {
  const double radius = 2.0;
  const Surface s = geodesicSphere(3, radius);
  const HeatSolver solver = buildSolver(s);
  const std::vector<SurfacePoint> source{vertexPoint(s, 0)};
  const std::vector<double> d = solver.distances(source);
  std::vector<double> exact(s.vertexCount());
  for (std::size_t v = 0; v < s.vertexCount(); ++v) {
    double c = 0.0;
    for (int k = 0; k < 3; ++k) c += s.positions[0][k] * s.positions[v][k] / (radius * radius);
    exact[v] = radius * std::acos(std::clamp(c, -1.0, 1.0));
  }
  const FieldError error = relativeError(d, exact);
  EXPECT_LT(error.mean, 0.01);
  EXPECT_LT(error.max, 0.025);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_FALSE(solver.stats().doubledCover);
}

TEST(HeatSolver, FaceInteriorSourceOnAPlane) {
  const Surface s = planarGrid(32, 1.0);
  const HeatSolver solver = buildSolver(s);
  const std::uint32_t face = 2 * (16 * 32 + 16);
  const SurfacePoint p{face, {0.2, 0.5, 0.3}};
  const std::vector<SurfacePoint> source{p};
  const std::vector<double> d = solver.distances(source);
  const FieldError error = relativeError(d, euclideanFrom(s, {p.position(s)}));
  EXPECT_LT(error.mean, 0.015);
  EXPECT_LT(error.max, 0.05);
  expectFiniteNonNegative(d);
}

TEST(HeatSolver, FewSourcesGiveTheMinimumOfTheirOwnFields) {
  const Surface s = geodesicSphere(2, 1.0);
  const HeatSolver solver = buildSolver(s);
  const std::vector<SurfacePoint> both{vertexPoint(s, 5), SurfacePoint{30, {0.2, 0.3, 0.5}}};
  const std::vector<double> d = solver.distances(both);
  const std::vector<double> a = solver.distances(std::span(both).first(1));
  const std::vector<double> b = solver.distances(std::span(both).last(1));
  // The straight-line bounds of the combined field use both sources (the lower one is the nearer
  // source in a straight line, weaker than each field's own), so it may lie a little below.
  for (std::size_t v = 0; v < d.size(); ++v) {
    EXPECT_LE(d[v], std::min(a[v], b[v]) + 1e-15);
    EXPECT_NEAR(d[v], std::min(a[v], b[v]), 0.05);
  }
}

// Separate fields go through the factors in batches of columns, the batches side by side: seven
// sources (a batch of four and one of three) give the same bytes on one thread and on two, and no
// vertex lies above the nearest source's own field.
TEST(HeatSolver, SeparateFieldsInBatchesDoNotDependOnTheThreadCount) {
  const Surface s = geodesicSphere(2, 1.0);
  HeatOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const HeatSolver serial = buildSolver(s, one), parallel = buildSolver(s, two);
  std::vector<SurfacePoint> sources;
  for (std::uint32_t v : {3u, 11u, 40u, 77u, 120u, 151u}) sources.push_back(vertexPoint(s, v));
  sources.push_back(SurfacePoint{30, {0.2, 0.3, 0.5}});
  const std::vector<double> d = serial.distances(sources);
  EXPECT_EQ(d, parallel.distances(sources));
  std::vector<double> nearest(d.size(), kUnreachable);
  for (const SurfacePoint& source : sources) {
    const std::vector<double> own = serial.distances(std::span(&source, 1));
    for (std::size_t v = 0; v < d.size(); ++v) nearest[v] = std::min(nearest[v], own[v]);
  }
  for (std::size_t v = 0; v < d.size(); ++v) {
    EXPECT_LE(d[v], nearest[v] + 1e-12) << v;
    EXPECT_NEAR(d[v], nearest[v], 0.05) << v;
  }
}

// With maxSeparateSources = 0 the sources share one field and are held at 0 by Dirichlet conditions.
TEST(HeatSolver, EverySourceSitsAtZeroAndNothingFoldsBetweenThem) {
  const Surface s = planarGrid(64, 1.0);
  HeatOptions options;
  options.maxSeparateSources = 0;
  const HeatSolver solver = buildSolver(s, options);
  const auto at = [](std::uint32_t i, std::uint32_t j) { return j * 65 + i; };
  const std::uint32_t a = at(16, 16), b = at(40, 48), c = at(56, 8);
  const std::vector<SurfacePoint> sources{vertexPoint(s, a), vertexPoint(s, b), vertexPoint(s, c),
                                          SurfacePoint{100, {0.3, 0.3, 0.4}}};
  const std::vector<double> d = solver.distances(sources);
  std::vector<Vec3d> points;
  for (const SurfacePoint& p : sources) points.push_back(p.position(s));
  const std::vector<double> exact = euclideanFrom(s, points);
  const FieldError error = relativeError(d, exact);
  EXPECT_LT(error.mean, 0.015);
  EXPECT_LT(error.max, 0.05);
  for (std::uint32_t v : {a, b, c}) EXPECT_EQ(d[v], 0.0);
  // The face-interior source is at 0 too: its corners are no farther than their true distance allows.
  for (std::uint32_t v : s.triangles[100]) EXPECT_NEAR(d[v], exact[v], 0.01);
  // Half-way between two sources the distance is half their separation, not pulled towards 0.
  const std::uint32_t middle = at(28, 32);
  EXPECT_NEAR(exact[middle], 0.3125, 1e-12);
  EXPECT_NEAR(d[middle], exact[middle], 0.01);
}

TEST(HeatSolver, ManySourcesBeyondThePinLimitStillGiveAZeroedField) {
  const Surface s = planarGrid(16, 1.0);
  HeatOptions options;
  options.maxSeparateSources = 0;
  options.maxPinnedSources = 2;
  const HeatSolver solver = buildSolver(s, options);
  const std::vector<SurfacePoint> sources{vertexPoint(s, 20), vertexPoint(s, 150), vertexPoint(s, 260)};
  const std::vector<double> d = solver.distances(sources);
  expectFiniteNonNegative(d);
  for (std::uint32_t v : {20u, 150u, 260u}) EXPECT_EQ(d[v], 0.0);
  std::vector<Vec3d> points;
  for (const SurfacePoint& p : sources) points.push_back(p.position(s));
  EXPECT_LT(relativeError(d, euclideanFrom(s, points)).mean, 0.05);
}

TEST(HeatSolver, OtherComponentsAndIsolatedVerticesAreUnreachable) {
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {9, 9, 9}},
                                {{0, 1, 2}, {3, 4, 5}});
  const HeatSolver solver = buildSolver(s);
  const std::vector<SurfacePoint> source{vertexPoint(s, 0)};
  const std::vector<double> d = solver.distances(source);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_TRUE(std::isfinite(d[1]) && d[1] > 0.5);
  EXPECT_TRUE(std::isfinite(d[2]) && d[2] > 0.5);
  for (std::size_t v : {3, 4, 5, 6}) EXPECT_EQ(d[v], kUnreachable);
  EXPECT_EQ(solver.distances({}), std::vector<double>(7, kUnreachable));
}

TEST(HeatSolver, NonManifoldPagesAreReachedSymmetrically) {
  // Three pages on a spine; the two pages away from the source are mirror images of each other.
  const double c = std::cos(2.0944), sn = std::sin(2.0944);
  const Surface s = makeSurface({{0, 0, 0}, {0, 0, 1}, {1, 0, 0.5}, {c, sn, 0.5}, {c, -sn, 0.5}},
                                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const HeatSolver solver = buildSolver(s);
  EXPECT_EQ(solver.stats().tuftedEdges, 1u);
  const std::vector<SurfacePoint> source{vertexPoint(s, 2)};
  const std::vector<double> d = solver.distances(source);
  expectFiniteNonNegative(d);
  EXPECT_NEAR(d[3], d[4], 1e-9);
  // Unfolded, two pages make a rhombus: tip to tip is 2 through the spine.
  EXPECT_NEAR(d[3], 2.0, 0.5);
}

TEST(HeatSolver, DegenerateFacesGiveFiniteDistances) {
  // A strip with a zero-area face (collinear corners), a needle and a repeated position.
  const Surface s = makeSurface({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1e-12, 0},
                                 {3, 0.5, 0}},
                                {{0, 1, 3}, {1, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 6, 5}, {0, 2, 1}});
  const HeatSolver solver = buildSolver(s);
  EXPECT_GT(solver.stats().mollifyEpsilon, 0.0);
  const std::vector<SurfacePoint> source{vertexPoint(s, 0)};
  const std::vector<double> d = solver.distances(source);
  expectFiniteNonNegative(d);
  for (double x : d) EXPECT_LT(x, 10.0);
}

TEST(HeatSolver, ConcurrentFieldsMatchSerialOnes) {
  const Surface s = geodesicSphere(2, 1.0);
  const HeatSolver solver = buildSolver(s);
  const std::vector<SurfacePoint> first{vertexPoint(s, 3)}, second{vertexPoint(s, 7), vertexPoint(s, 40)};
  const std::vector<double> a = solver.distances(first), b = solver.distances(second);
  std::vector<double> a2, b2;
  std::thread t1([&] { a2 = solver.distances(first); });
  std::thread t2([&] { b2 = solver.distances(second); });
  t1.join();
  t2.join();
  EXPECT_EQ(a, a2);
  EXPECT_EQ(b, b2);
}

}  // namespace
}  // namespace bake::geodesic
