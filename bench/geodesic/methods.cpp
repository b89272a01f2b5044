// The methods under test, each as one function from (surface, source vertices) to a measurement:
// libbake's exact window propagation, heat method and fast marching, and CGAL's exact
// Surface_mesh_shortest_path and Heat_method_3 (intrinsic Delaunay) as peers. Setup that a method does
// once per mesh (the heat methods' factorisations) is timed apart from the per-field time. Each runs
// inside runIsolated, so a failure is thrown as an exception and becomes a failed row.
#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "bench_geodesic.h"
#include "cgal_geodesic.h"
#include "geodesic/bake/methods.h"

namespace bake::bench {
namespace {

using geodesic::Surface;
using geodesic::SurfacePoint;
using Clock = std::chrono::steady_clock;

std::vector<SurfacePoint> surfacePoints(const Surface& s, const std::vector<std::uint32_t>& vertices) {
  std::vector<SurfacePoint> points;
  for (std::uint32_t v : vertices) points.push_back(geodesic::vertexPoint(s, v));
  return points;
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

template <class T>
T valueOrThrow(Result<T> result) {
  if (!result.isOk()) throw std::runtime_error(result.status().describe());
  return std::move(result).value();
}

Measurement timeField(const MethodSettings& settings, const std::function<std::vector<double>()>& field) {
  Measurement m;
  m.seconds = medianSeconds([&] { m.distances = field(); }, settings.repeat, &m.runs);
  return m;
}

// Builds a solver as often as the repeat rule says and gives the last one, with the median build time:
// a set-up of tens of milliseconds measured once is too noisy to compare with a peer's.
// The previous solver is freed outside the timed part.
template <class Build>
auto timedSetup(const MethodSettings& settings, Build build, double& seconds) {
  std::optional<decltype(build())> solver;
  std::vector<double> times;
  const auto start = Clock::now();
  do {
    solver.reset();
    const auto before = Clock::now();
    solver.emplace(build());
    times.push_back(secondsSince(before));
  } while (settings.repeat.again(static_cast<int>(times.size()), secondsSince(start)));
  seconds = medianOf(std::move(times));
  return std::move(*solver);
}

}  // namespace

std::vector<Method> allMethods(const MethodSettings& settings) {
  std::vector<Method> methods;
  methods.push_back({"exact", [settings](const Surface& s, const std::vector<std::uint32_t>& sources) {
    const auto points = surfacePoints(s, sources);
    return timeField(settings, [&] { return geodesic::exactDistances(s, points); });
  }});
  methods.push_back({"heat", [settings](const Surface& s, const std::vector<std::uint32_t>& sources) {
    const auto points = surfacePoints(s, sources);
    double setup = 0;
    const geodesic::HeatSolver solver =
        timedSetup(settings, [&] { return valueOrThrow(geodesic::HeatSolver::build(s)); }, setup);
    Measurement m = timeField(settings, [&] { return solver.distances(points); });
    m.setupSeconds = setup;
    return m;
  }});
  methods.push_back({"fmm", [settings](const Surface& s, const std::vector<std::uint32_t>& sources) {
    const auto points = surfacePoints(s, sources);
    return timeField(settings, [&] { return geodesic::fastMarchingDistances(s, points); });
  }});
  methods.push_back({"cgal-exact", [settings](const Surface& s, const std::vector<std::uint32_t>& sources) {
    return timeField(settings, [&] { return valueOrThrow(peers::cgalExactDistances(s.positions, s.triangles, sources)); });
  }});
  methods.push_back({"cgal-heat", [settings](const Surface& s, const std::vector<std::uint32_t>& sources) {
    double setup = 0;
    peers::CgalHeatSolver solver =
        timedSetup(settings, [&] { return valueOrThrow(peers::CgalHeatSolver::build(s.positions, s.triangles)); }, setup);
    Measurement m = timeField(settings, [&] { return valueOrThrow(solver.distances(sources)); });
    m.setupSeconds = setup;
    return m;
  }});
  return methods;
}

}  // namespace bake::bench
