// Error against run time for the paintstroke rasterizer (libbake/stroke). The case is what tambake
// asks for thousands of times: a gently curved stroke about 80 px long, radius 0.5 ... 3 px, on a
// 256 x 256 wrapping tile. Each configuration reports, besides its time, two errors against an oracle
// computed once outside the timed loop: the largest per-pixel coverage error against the area within r
// of the spline (point-sampled 32 x 32 times per pixel) and the relative error of the total ink.
// Ours is swept over the piece length (RasterOptions::maxPieceLength); the peer is the obvious
// alternative, supersampling n x n points per pixel against the same polyline.
//
//   bench-stroke --benchmark_format=csv > stroke.csv
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "bake/stroke/paintstroke.h"

namespace {

using namespace bake::stroke;

constexpr int kTile = 256;

Paintstroke testStroke(double radius) {
  Paintstroke s;
  const double xs[] = {60.3, 100.1, 135.9}, ys[] = {80.7, 95.2, 100.4};
  for (int i = 0; i < 3; ++i) {
    ControlPoint p;
    p.x = xs[i], p.y = ys[i], p.radius = radius;
    s.points.push_back(p);
  }
  return s;
}

using Polyline = std::vector<std::pair<double, double>>;

Polyline densePolyline(const Paintstroke& s) {
  Polyline poly;
  const int n = 800;
  for (int k = 0; k <= n; ++k) {
    const ControlPoint q = evaluate(s, double(s.points.size() - 1) * k / n);
    poly.push_back({q.x, q.y});
  }
  return poly;
}

double segmentDistance(const std::pair<double, double>& a, const std::pair<double, double>& b, double x, double y) {
  const double ax = a.first, ay = a.second, ex = b.first - ax, ey = b.second - ay;
  const double l2 = ex * ex + ey * ey;
  const double t = l2 > 0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / l2, 0.0, 1.0) : 0;
  return std::hypot(x - ax - t * ex, y - ay - t * ey);
}

double distanceTo(const Polyline& poly, double x, double y) {
  double best = 1e300;
  for (std::size_t k = 0; k + 1 < poly.size(); ++k) best = std::min(best, segmentDistance(poly[k], poly[k + 1], x, y));
  return best;
}

// The fraction of pixel (x, y) within r of the polyline, by n x n point samples.
double sampledArea(const Polyline& poly, double r, int x, int y, int n) {
  int inside = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) inside += distanceTo(poly, x + (i + 0.5) / n, y + (j + 0.5) / n) <= r;
  return double(inside) / (n * n);
}

using Image = std::map<std::pair<int, int>, double>;

// Pixels near the stroke: the bounding box of the polyline plus r + 1.
template <class F>
void forNearPixels(const Polyline& poly, double r, F f) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& [x, y] : poly) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  for (int y = int(std::floor(y0 - r - 1)); y <= int(std::ceil(y1 + r + 1)); ++y)
    for (int x = int(std::floor(x0 - r - 1)); x <= int(std::ceil(x1 + r + 1)); ++x) f(x, y);
}

const Image& oracle(double radius) {
  static std::map<double, Image> cache;  // the benchmark runs its cases one after another
  auto it = cache.find(radius);
  if (it != cache.end()) return it->second;
  const Polyline poly = densePolyline(testStroke(radius));
  Image image;
  forNearPixels(poly, radius, [&](int x, int y) {
    if (distanceTo(poly, x + 0.5, y + 0.5) > radius + 0.75) return;
    const double a = sampledArea(poly, radius, x, y, 32);
    if (a > 0) image[{x, y}] = a;
  });
  return cache.emplace(radius, std::move(image)).first->second;
}

void reportError(benchmark::State& state, const Image& got, double radius) {
  const Image& ref = oracle(radius);
  double worst = 0, inkGot = 0, inkRef = 0;
  for (const auto& [key, a] : ref) {
    const auto g = got.find(key);
    worst = std::max(worst, std::abs((g == got.end() ? 0 : g->second) - a));
    inkRef += a;
  }
  for (const auto& [key, a] : got) {
    inkGot += a;
    if (!ref.count(key)) worst = std::max(worst, a);
  }
  state.counters["max_pixel_error"] = worst;
  state.counters["ink_error"] = std::abs(inkGot / inkRef - 1);
  state.counters["pixels"] = double(got.size());
}

// Ours: range(0) = radius in tenths of a pixel, range(1) = maximum piece length in tenths.
void BM_Rasterize(benchmark::State& state) {
  const double radius = state.range(0) / 10.0;
  RasterOptions options;
  options.maxPieceLength = state.range(1) / 10.0;
  const Paintstroke stroke = testStroke(radius);
  InkFootprint footprint;
  for (auto _ : state) {
    footprint = rasterize(stroke, kTile, kTile, true, options);
    benchmark::DoNotOptimize(footprint.pixels.data());
  }
  Image got;
  for (const auto& p : footprint.pixels) got[{p.x, p.y}] = p.alpha;
  reportError(state, got, radius);
}

// Peer: n x n point samples per pixel against the polyline the spline is drawn with (range(1) = n).
void BM_Supersample(benchmark::State& state) {
  const double radius = state.range(0) / 10.0;
  const int n = int(state.range(1));
  const Paintstroke stroke = testStroke(radius);
  Image got;
  for (auto _ : state) {
    got.clear();
    Polyline poly;
    const int pieces = 160;  // 0.5 px pieces
    for (int k = 0; k <= pieces; ++k) {
      const ControlPoint q = evaluate(stroke, 2.0 * k / pieces);
      poly.push_back({q.x, q.y});
    }
    // Per pixel, only the pieces that can reach it are tested.
    Polyline near;  // pairs of points: the pieces near the pixel
    forNearPixels(poly, radius, [&](int x, int y) {
      near.clear();
      for (std::size_t k = 0; k + 1 < poly.size(); ++k) {
        const double reach = radius + 0.75;
        const double cx = x + 0.5, cy = y + 0.5;
        const auto [ax, ay] = poly[k];
        const auto [bx, by] = poly[k + 1];
        if (cx < std::min(ax, bx) - reach || cx > std::max(ax, bx) + reach || cy < std::min(ay, by) - reach ||
            cy > std::max(ay, by) + reach)
          continue;
        near.push_back(poly[k]), near.push_back(poly[k + 1]);
      }
      if (near.empty()) return;
      int inside = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double px = x + (i + 0.5) / n, py = y + (j + 0.5) / n;
          bool in = false;
          for (std::size_t k = 0; k < near.size() && !in; k += 2)
            in = segmentDistance(near[k], near[k + 1], px, py) <= radius;
          inside += in;
        }
      const double a = double(inside) / (n * n);
      if (a > 0) got[{x, y}] = a;
    });
    benchmark::DoNotOptimize(got.size());
  }
  reportError(state, got, radius);
}

BENCHMARK(BM_Rasterize)
    ->ArgsProduct({{5, 10, 15, 30}, {5, 10, 20, 40}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Supersample)->ArgsProduct({{5, 10, 15, 30}, {2, 4, 8}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
