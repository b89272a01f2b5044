// A mesh of revolution as a profile. The axis comes from the normals: on a surface of revolution every
// normal line meets the axis, i.e. the normal lines (n, p x n) lie in the linear line complex whose
// Pluecker coordinates (a_bar, a) are those of the axis: n . a_bar + (p x n) . a = 0 (Pottmann &
// Randrup 1998). Minimising the area-weighted sum of squares with |a| = 1 eliminates a_bar (a linear
// solve) and leaves the smallest eigenvector of a 3x3 Schur complement. The profile is the cut of the
// mesh by one half-plane bounded by the axis; cut points are keyed by the mesh edge they lie on, so
// chaining them into contours is exact. Every vertex is then measured against that profile: the
// deviation says how far the mesh is from a true surface of revolution.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include <Eigen/Dense>

#include "revolution/input/profile_chain.h"
#include "revolution/input/profile_extract.h"

namespace bake::revolution {
namespace {

using V3 = Eigen::Vector3d;

V3 toV3(const Vec3f& p) { return {p[0], p[1], p[2]}; }

// Each face as (centroid, unit normal, area); degenerate faces are skipped.
struct FaceSample {
  V3 centroid, normal;
  double area;
};

std::vector<FaceSample> faceSamples(const TriangleMesh& mesh) {
  std::vector<FaceSample> faces;
  faces.reserve(mesh.triangleCount());
  for (const Triangle& t : mesh.triangles) {
    const V3 a = toV3(mesh.positions[t[0]]), b = toV3(mesh.positions[t[1]]), c = toV3(mesh.positions[t[2]]);
    const V3 cross = (b - a).cross(c - a);
    const double twiceArea = cross.norm();
    if (!(twiceArea > 0)) continue;
    faces.push_back({(a + b + c) / 3.0, cross / twiceArea, 0.5 * twiceArea});
  }
  return faces;
}

// Within the eigenvectors whose eigenvalues are near the smallest (a sphere has all three, a plane's
// normals do not fix the axis either), the direction closest to the mesh's +y: an ambiguous fit then
// keeps the author's up axis instead of an arbitrary one.
V3 pickDirection(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& solver) {
  const Eigen::Vector3d values = solver.eigenvalues();
  const double scale = std::max(values(2), 1e-300);
  V3 direction = solver.eigenvectors().col(0);
  int nearZero = 1;
  for (int k = 1; k < 3; ++k)
    if (values(k) - values(0) <= 1e-6 * scale) nearZero = k + 1;
  if (nearZero > 1) {
    const V3 up(0, 1, 0);
    V3 projected = V3::Zero();
    for (int k = 0; k < nearZero; ++k) projected += solver.eigenvectors().col(k).dot(up) * solver.eigenvectors().col(k);
    if (projected.norm() > 1e-9) direction = projected.normalized();
  }
  // A sign convention, so the same mesh always gives the same axis: largest component positive.
  int largest = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(direction(k)) > std::abs(direction(largest))) largest = k;
  return direction(largest) < 0 ? V3(-direction) : direction;
}

}  // namespace

Result<AxisFit> fitRevolutionAxis(const TriangleMesh& mesh, const std::string& name) {
  const std::vector<FaceSample> faces = faceSamples(mesh);
  if (faces.size() < 3) return invalidInput("a mesh of revolution needs at least 3 faces with area", {name, ""});
  // Centre the coordinates first: the moments p x n are then of the object's own size.
  V3 centroid = V3::Zero();
  double totalArea = 0;
  for (const FaceSample& f : faces) {
    centroid += f.area * f.centroid;
    totalArea += f.area;
  }
  centroid /= totalArea;

  Eigen::Matrix3d A = Eigen::Matrix3d::Zero(), B = Eigen::Matrix3d::Zero(), C = Eigen::Matrix3d::Zero();
  for (const FaceSample& f : faces) {
    const V3 moment = (f.centroid - centroid).cross(f.normal);
    A += f.area * f.normal * f.normal.transpose();
    B += f.area * f.normal * moment.transpose();
    C += f.area * moment * moment.transpose();
  }
  // a_bar = -A^+ B a: the pseudo-inverse, because a cylinder's normals span only a plane.
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix3d> Ainv(A);
  const Eigen::Matrix3d pinvA = Ainv.pseudoInverse();
  Eigen::Matrix3d schur = C - B.transpose() * pinvA * B;
  schur = 0.5 * (schur + schur.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(schur);
  const V3 a = pickDirection(solver);
  const V3 aBar = -pinvA * B * a;

  AxisFit fit;
  fit.pitch = a.dot(aBar);
  // The axis line (a, a_bar) passes through a x a_bar (relative to the centroid); take the point on
  // it nearest the centroid.
  V3 point = a.cross(aBar);
  point -= point.dot(a) * a;
  point += centroid;
  if (!point.allFinite() || !a.allFinite()) return invalidInput("could not fit an axis of revolution", {name, ""});
  fit.point = {point(0), point(1), point(2)};
  fit.direction = {a(0), a(1), a(2)};
  return fit;
}

namespace {

// The frame of the cutting half-plane: h along the axis, r along `outward`, the plane's normal.
struct HalfPlane {
  V3 origin, axis, outward, normal;
  Point2 toProfile(const V3& p) const {
    const V3 d = p - origin;
    return {d.dot(outward), d.dot(axis)};
  }
};

HalfPlane halfPlaneOf(const AxisFit& fit) {
  HalfPlane plane;
  plane.origin = {fit.point[0], fit.point[1], fit.point[2]};
  plane.axis = {fit.direction[0], fit.direction[1], fit.direction[2]};
  // Outward: the world axis least aligned with the rotation axis, made perpendicular to it.
  V3 seed = V3::UnitX();
  if (std::abs(plane.axis.dot(seed)) > 0.9) seed = V3::UnitZ();
  plane.outward = (seed - seed.dot(plane.axis) * plane.axis).normalized();
  plane.normal = plane.axis.cross(plane.outward);
  return plane;
}

// The plane's cut of every face, clipped to the half-plane r >= 0. A vertex exactly on the plane
// counts as being on its positive side, so each cut point lies strictly inside a mesh edge.
std::vector<KeyedSegment> cutFaces(const TriangleMesh& mesh, const HalfPlane& plane) {
  std::vector<double> side(mesh.vertexCount());
  for (std::size_t v = 0; v < side.size(); ++v) side[v] = (toV3(mesh.positions[v]) - plane.origin).dot(plane.normal);
  std::vector<KeyedSegment> cuts;
  for (const Triangle& t : mesh.triangles) {
    KeyedSegment cut{};
    int found = 0;
    for (int e = 0; e < 3 && found < 3; ++e) {
      const std::uint32_t i = t[e], j = t[(e + 1) % 3];
      const bool pi = side[i] >= 0, pj = side[j] >= 0;
      if (pi == pj) continue;
      const double s = side[i] / (side[i] - side[j]);
      const V3 p = toV3(mesh.positions[i]) + s * (toV3(mesh.positions[j]) - toV3(mesh.positions[i]));
      if (found < 2) {
        cut.ends[found] = pairKey(i, j);
        cut.points[found] = plane.toProfile(p);
      }
      ++found;
    }
    if (found != 2) continue;
    // Keep the part with r >= 0 (the other half-plane holds the mirror image of the same profile).
    if (!clipToPositiveR(cut, axisKey(cuts.size()))) continue;
    cuts.push_back(cut);
  }
  return cuts;
}

}  // namespace

Result<MeshProfile> profileOfMesh(const TriangleMesh& mesh, const std::string& name) {
  MeshProfile result;
  BAKE_ASSIGN_OR_RETURN(result.axis, fitRevolutionAxis(mesh, name));
  const HalfPlane plane = halfPlaneOf(result.axis);
  result.profile.contours = chainKeyedSegments(cutFaces(mesh, plane));
  result.profile.source = name;
  if (result.profile.contours.empty())
    return invalidInput("the half-plane through the fitted axis does not cut the mesh", {name, ""});
  std::vector<std::string> repairs;
  BAKE_RETURN_IF_ERROR(validateProfile(result.profile, repairs).inFile(name));

  V3 lo = V3::Constant(1e300), hi = V3::Constant(-1e300);
  for (const Vec3f& p : mesh.positions) {
    lo = lo.cwiseMin(toV3(p));
    hi = hi.cwiseMax(toV3(p));
  }
  result.objectSize = (hi - lo).norm();
  // Every vertex against the profile; a deterministic stride keeps huge meshes affordable.
  const std::size_t limit = 20000;
  const std::size_t stride = std::max<std::size_t>(1, mesh.vertexCount() / limit);
  double sumSquares = 0;
  for (std::size_t v = 0; v < mesh.vertexCount(); v += stride) {
    const V3 d = toV3(mesh.positions[v]) - plane.origin;
    const double h = d.dot(plane.axis);
    const double r = (d - h * plane.axis).norm();
    const double deviation = std::abs(signedDistance(result.profile, {r, h}).distance);
    result.maxDeviation = std::max(result.maxDeviation, deviation);
    sumSquares += deviation * deviation;
    ++result.vertices;
  }
  result.rmsDeviation = std::sqrt(sumSquares / double(std::max<std::size_t>(1, result.vertices)));
  return result;
}

}  // namespace bake::revolution
