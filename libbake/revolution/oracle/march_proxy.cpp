// Proxy bands: stacked cylinders that bound the solid more tightly than the shape box, so the march
// (formats/revolution.md, step 1) starts where the ray first enters one instead of at the box, and
// rays that miss every band are discarded without a fetch (the empty-space skipping of bounding
// volumes; Hart 1996, section 5). A texel square can hold solid only if the distance at its centre
// is at most half its diagonal (the distance is exact at centres and 1-Lipschitz), so each band's
// radius is the outer edge of the farthest such texel among the band's rows, widened by the margin
// plus a quarter texel for the hit epsilon (and by the rows within that reach above and below),
// because the march stops at distance `margin` from the solid, not at the solid itself. The band
// boundaries are chosen by dynamic programming over the rows for the least total band volume
// (O(bands x rows^2) additions, rows taken in groups beyond 1024 of them), so bands are thin where
// the radius changes fast and tall where it does not.
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "bake_formats/revolution.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {
namespace {

constexpr double kHitSlackTexels = 0.25;  // above the hit epsilon (kHitEpsilonTexels)
constexpr int kMaxCuts = 1024;            // band boundary positions the search considers

// Outer edge (object units) of the farthest texel in row j that may contain solid; 0 when none.
double rowExtent(const ShapeField& field, int j) {
  const ShapeGrid& g = field.grid;
  const double halfDiagonal = 0.5 * std::sqrt(2.0) * g.texelSize;
  for (int i = g.width - 1; i >= 0; --i)
    if (field.at(i, j) <= halfDiagonal) return (i + 1) * g.texelSize;
  return 0;
}

// Ray parameters inside the slab lo <= o + t d <= hi (all t when the ray is parallel and inside).
bool clipSlab(double o, double d, double lo, double hi, double& tIn, double& tOut) {
  if (d == 0) return o >= lo && o <= hi;
  double t0 = (lo - o) / d, t1 = (hi - o) / d;
  if (t0 > t1) std::swap(t0, t1);
  tIn = std::max(tIn, t0);
  tOut = std::min(tOut, t1);
  return tIn <= tOut;
}

// Ray parameters inside the infinite cylinder x^2 + z^2 <= radius^2.
bool clipCylinder(const Ray& ray, double radius, double& tIn, double& tOut) {
  const double ox = ray.origin[0], oz = ray.origin[2], dx = ray.direction[0], dz = ray.direction[2];
  const double a = dx * dx + dz * dz;
  const double c = ox * ox + oz * oz - radius * radius;
  if (a == 0) return c <= 0;
  const double halfB = ox * dx + oz * dz;
  const double disc = halfB * halfB - a * c;
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  // Stable roots: q and c / q instead of a difference of close numbers.
  const double q = -(halfB + std::copysign(root, halfB));
  double t0 = q / a, t1 = q != 0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  tIn = std::max(tIn, t0);
  tOut = std::min(tOut, t1);
  return tIn <= tOut;
}

}  // namespace

std::vector<ProxyBand> buildProxyBands(const ShapeField& field, int bandCount, double margin) {
  const ShapeGrid& g = field.grid;
  std::vector<ProxyBand> bands;
  if (g.width <= 0 || g.height <= 0 || field.distance.size() != std::size_t(g.width) * g.height) return bands;
  bandCount = std::clamp(bandCount, 1, std::min(g.height, format::revolution::kMaxProxyBands));
  // The march stops up to margin + hit epsilon (a small fraction of a texel) from the solid, so a row
  // must also cover the solid of the rows within that reach.
  const double reach = std::max(margin, 0.0) + kHitSlackTexels * g.texelSize;
  const int reachRows = int(std::ceil(reach / g.texelSize));
  std::vector<double> extent(g.height), covered(g.height, 0);
  for (int j = 0; j < g.height; ++j) extent[j] = rowExtent(field, j);
  for (int j = 0; j < g.height; ++j)
    for (int k = std::max(0, j - reachRows); k < std::min(g.height, j + reachRows + 1); ++k)
      covered[j] = std::max(covered[j], extent[k]);
  auto radiusOf = [&](double widest) { return widest > 0 ? widest + reach : 0.0; };  // 0: no solid

  // Band boundaries by dynamic programming over the rows: the least total volume sum(R^2 rows),
  // the empty space a ray can cross inside the bands. Tall maps are cut at every `stride` rows only,
  // which keeps the search at most kMaxCuts^2 per band.
  const int stride = (g.height + kMaxCuts - 1) / kMaxCuts;
  const int n = (g.height + stride - 1) / stride;  // cut positions 0..n
  auto rowOfCut = [&](int k) { return std::min(k * stride, g.height); };
  std::vector<double> blockWidest(n, 0);
  for (int j = 0; j < g.height; ++j) blockWidest[j / stride] = std::max(blockWidest[j / stride], covered[j]);
  bandCount = std::min(bandCount, n);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(std::size_t(n + 1), inf), next(std::size_t(n + 1));
  std::vector<std::vector<int>> split(bandCount + 1, std::vector<int>(n + 1, 0));
  cost[0] = 0;
  for (int b = 1; b <= bandCount; ++b) {
    std::fill(next.begin(), next.end(), inf);
    for (int j = b; j <= n; ++j) {
      double widest = 0;
      for (int i = j - 1; i >= b - 1; --i) {  // band = cuts [i, j)
        widest = std::max(widest, blockWidest[i]);
        const double radius = radiusOf(widest);
        const double total = cost[i] + radius * radius * (rowOfCut(j) - rowOfCut(i));
        if (total < next[j]) next[j] = total, split[b][j] = i;
      }
    }
    cost.swap(next);
  }
  std::vector<int> edges{g.height};
  for (int b = bandCount, j = n; b >= 1; --b) edges.push_back(rowOfCut(j = split[b][j]));
  std::reverse(edges.begin(), edges.end());
  for (int b = 0; b < bandCount; ++b) {
    const int j0 = edges[b], j1 = edges[b + 1];
    double widest = 0;
    for (int j = j0; j < j1; ++j) widest = std::max(widest, covered[j]);
    ProxyBand band;
    band.hMin = g.hMin + j0 * g.texelSize;
    band.hMax = g.hMin + j1 * g.texelSize;
    band.rMax = radiusOf(widest);
    bands.push_back(band);
  }
  return bands;
}

std::optional<std::array<double, 2>> enterBands(const Ray& ray, const std::vector<ProxyBand>& bands) {
  double entry = std::numeric_limits<double>::infinity(), exit = -entry;
  for (const ProxyBand& band : bands) {
    if (!(band.rMax > 0)) continue;
    double tIn = 0, tOut = std::numeric_limits<double>::infinity();  // only ahead of the origin
    if (!clipSlab(ray.origin[1], ray.direction[1], band.hMin, band.hMax, tIn, tOut)) continue;
    if (!clipCylinder(ray, band.rMax, tIn, tOut)) continue;
    entry = std::min(entry, tIn);
    exit = std::max(exit, tOut);
  }
  if (!(entry <= exit)) return std::nullopt;
  return std::array<double, 2>{entry, exit};
}

}  // namespace bake::revolution
