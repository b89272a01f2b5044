// Error against run time of the march: the silhouette and hit-point error of the CPU march (identical
// to the shader) against the analytic intersection, per iteration budget. Rays come from `views`
// orthographic views around the axis (azimuths spread by the golden angle, elevations evenly from
// -50 to +50 degrees for six views), through a regular grid over each view's projection of the shape
// box. Every ray is marched once with the largest budget: a budget only cuts the loop short, so the
// march under budget B hits exactly when the full march hit within B fetches, at the same t, and it
// takes min(fetches, B) fetches. Per budget:
//   silhouette mismatch = rays where march and reference disagree on hit/miss, divided by the rays
//                         that hit in either (the union of both silhouettes, so empty space around the
//                         object does not dilute the figure);
//   hit error           = |t_march - t_reference| over rays both hit (object units, mean and max);
//   mean fetches        = over the rays that enter the shape box (the fragments the shader runs).
// Rays are independent; per-ray results are summed in ray order, so the curve is the same for any
// thread count.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bake/core/vec.h"
#include "core/parallel.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {
namespace {

constexpr double kGoldenAngle = 2.39996322972865332;
constexpr double kMaxElevation = 60.0 * 3.14159265358979323846 / 180.0;

struct RayOutcome {
  bool inBox = false;
  bool referenceHit = false, marchHit = false;
  double referenceT = 0, marchT = 0;
  int fetches = 0;
};

using vec::cross;
using vec::dot;
Vec3d normalised(const Vec3d& v) {
  const double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}

// An orthographic camera: rays along `direction`, origins on the plane spanned by right and up.
struct View {
  Vec3d direction, right, up, centre;
  double uMin, uMax, vMin, vMax, back;
};

View makeView(int k, int views, const ShapeGrid& grid) {
  const double azimuth = kGoldenAngle * k + 0.3;
  const double elevation = -kMaxElevation + 2 * kMaxElevation * (k + 0.5) / views;
  View v;
  v.direction = {-std::cos(elevation) * std::cos(azimuth), -std::sin(elevation), -std::cos(elevation) * std::sin(azimuth)};
  v.right = normalised(cross(v.direction, {0, 1, 0}));
  v.up = cross(v.right, v.direction);
  const double radius = grid.width * grid.texelSize;
  const double h0 = grid.hMin, h1 = grid.hMin + grid.height * grid.texelSize;
  v.centre = {0, 0.5 * (h0 + h1), 0};
  v.uMin = v.vMin = std::numeric_limits<double>::infinity();
  v.uMax = v.vMax = -v.uMin;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3d p{(corner & 1 ? radius : -radius), (corner & 2 ? h1 : h0) - v.centre[1], (corner & 4 ? radius : -radius)};
    v.uMin = std::min(v.uMin, dot(p, v.right)), v.uMax = std::max(v.uMax, dot(p, v.right));
    v.vMin = std::min(v.vMin, dot(p, v.up)), v.vMax = std::max(v.vMax, dot(p, v.up));
  }
  v.back = 2 * std::hypot(2 * radius, h1 - h0);  // origins well outside the box
  return v;
}

Ray rayThrough(const View& v, double a, double b) {
  Ray ray;
  for (int c = 0; c < 3; ++c)
    ray.origin[c] = v.centre[c] + a * v.right[c] + b * v.up[c] - v.back * v.direction[c];
  ray.direction = v.direction;
  return ray;
}

bool entersBox(const Ray& ray, const ShapeGrid& grid) { return enterShapeBox(ray, grid).has_value(); }

MarchErrorPoint summarise(const std::vector<RayOutcome>& outcomes, int budget) {
  MarchErrorPoint point;
  point.iterations = budget;
  std::size_t either = 0, differ = 0, both = 0, inBox = 0;
  double errorSum = 0, fetchSum = 0;
  for (const RayOutcome& o : outcomes) {
    if (!o.inBox) continue;
    ++inBox;
    fetchSum += std::min(o.fetches, budget);
    const bool marchHit = o.marchHit && o.fetches <= budget;
    if (marchHit || o.referenceHit) ++either;
    if (marchHit != o.referenceHit) ++differ;
    if (marchHit && o.referenceHit) {
      const double error = std::abs(o.marchT - o.referenceT);
      ++both;
      errorSum += error;
      point.maxHitError = std::max(point.maxHitError, error);
    }
  }
  point.silhouetteMismatch = either ? double(differ) / double(either) : 0.0;
  point.meanHitError = both ? errorSum / double(both) : 0.0;
  point.meanFetches = inBox ? fetchSum / double(inBox) : 0.0;
  return point;
}

}  // namespace

std::vector<MarchErrorPoint> measureMarchError(const Profile& profile, const EncodedShapeMap& encoded,
                                               const ShapeGrid& grid, const std::vector<ProxyBand>& bands,
                                               MarchSettings base, const MarchErrorSettings& settings) {
  std::vector<MarchErrorPoint> curve;
  if (settings.iterationBudgets.empty() || settings.views <= 0 || grid.width <= 0 || grid.height <= 0) return curve;
  const int side = std::max(1, int(std::lround(std::sqrt(double(std::max(settings.raysPerView, 1))))));
  base.maxIterations = *std::max_element(settings.iterationBudgets.begin(), settings.iterationBudgets.end());
  std::vector<View> views;
  for (int k = 0; k < settings.views; ++k) views.push_back(makeView(k, settings.views, grid));

  const std::size_t perView = std::size_t(side) * side;
  std::vector<RayOutcome> outcomes(perView * views.size());
  parallelFor(outcomes.size(), resolveThreadCount(settings.threads), [&](std::size_t index) {
    const View& v = views[index / perView];
    const std::size_t pixel = index % perView;
    const double a = v.uMin + (v.uMax - v.uMin) * ((pixel % side) + 0.5) / side;
    const double b = v.vMin + (v.vMax - v.vMin) * ((pixel / side) + 0.5) / side;
    const Ray ray = rayThrough(v, a, b);
    RayOutcome& out = outcomes[index];
    out.inBox = entersBox(ray, grid);
    if (!out.inBox) return;
    if (const auto t = intersectExact(ray, profile)) out.referenceHit = true, out.referenceT = *t;
    const MarchResult march = marchRay(ray, encoded, grid, bands, base);
    out.marchHit = march.hit;
    out.marchT = march.t;
    out.fetches = march.fetches;
  }, 64);

  std::vector<int> budgets = settings.iterationBudgets;
  std::sort(budgets.begin(), budgets.end());
  budgets.erase(std::unique(budgets.begin(), budgets.end()), budgets.end());
  for (int budget : budgets) curve.push_back(summarise(outcomes, budget));
  return curve;
}

int iterationsForTarget(const std::vector<MarchErrorPoint>& curve, double targetMismatch) {
  int best = -1, largest = 0;
  for (const MarchErrorPoint& point : curve) {
    largest = std::max(largest, point.iterations);
    if (point.silhouetteMismatch <= targetMismatch && (best < 0 || point.iterations < best)) best = point.iterations;
  }
  return best >= 0 ? best : largest;
}

}  // namespace bake::revolution
