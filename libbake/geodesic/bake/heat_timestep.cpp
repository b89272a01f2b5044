// Time step of the heat method, chosen from the mesh so that heat never underflows.
//
// One backward Euler step (M + tL) u = delta does not give a Gaussian: its kernel is the resolvent of
// the Laplacian, which decays like exp(-d / sqrt(t)) with the distance d from the source (for the
// Gaussian exp(-d^2 / 4t) it would be worse still). With the usual t = h^2 a field spanning d / h =
// 1000 edges needs exp(-1000), below the smallest double (about exp(-745)); and long before that the
// heat is lost in the rounding of the solve, the normalised gradient turns to noise and distances go
// wrong by tens of percent (a corner source on a 2M-triangle planar grid: 5.6 % mean, 40 % max error).
// So t is bounded from below by (extent / K)^2, where the extent estimates the longest geodesic in
// the mesh: heat then falls by at most exp(-K) across a field. The double sweep can underestimate the
// extent by up to half, so a field may span 2K decay lengths at worst; K = 350 keeps even that,
// exp(-700) ~ 1e-304, above the smallest normal double, while the usual case, exp(-350) ~ 1e-152,
// leaves decades for the rounding of the solve. The extra smoothing costs little: on the Stanford
// bunny subdivided to 1.1M triangles (t = 4.5 h^2) the error is 0.27 % mean, 1.5 % max against 0.26 %
// and 1.4 % with t = h^2, and the grid above drops to 0.06 % mean, 0.56 % max. Small meshes (extent
// < K h) keep t = h^2 and the accuracy Crane et al. measured with it.
#include "geodesic/bake/heat_timestep.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace bake::geodesic {
namespace {

// Dijkstra along edges from every seed at once; returns the distances (infinity where unreached).
std::vector<double> edgeDistances(const Surface& surface, const std::vector<std::uint32_t>& seeds) {
  std::vector<double> distance(surface.vertexCount(), kUnreachable);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (std::uint32_t s : seeds) {
    distance[s] = 0.0;
    queue.emplace(0.0, s);
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    for (std::uint32_t e : surface.edgesOfVertex(v)) {
      const std::uint32_t w = surface.edges[e][0] == v ? surface.edges[e][1] : surface.edges[e][0];
      const double candidate = d + surface.edgeLengths[e];
      if (candidate < distance[w]) {
        distance[w] = candidate;
        queue.emplace(candidate, w);
      }
    }
  }
  return distance;
}

// The farthest vertex of each component from the given distances.
std::vector<std::uint32_t> farthestPerComponent(const Surface& surface, const std::vector<double>& distance) {
  std::vector<std::int64_t> best(surface.componentCount, -1);
  for (std::uint32_t v = 0; v < surface.vertexCount(); ++v) {
    std::int64_t& b = best[surface.componentOf[v]];
    if (b < 0 || distance[v] > distance[static_cast<std::uint32_t>(b)]) b = v;
  }
  std::vector<std::uint32_t> result;
  for (std::int64_t b : best)
    if (b >= 0) result.push_back(static_cast<std::uint32_t>(b));
  return result;
}

}  // namespace

double estimateGeodesicExtent(const Surface& surface) {
  if (surface.vertexCount() == 0) return 0.0;
  const std::vector<double> zero(surface.vertexCount(), 0.0);
  const std::vector<std::uint32_t> firsts = farthestPerComponent(surface, zero);
  const std::vector<std::uint32_t> far = farthestPerComponent(surface, edgeDistances(surface, firsts));
  const std::vector<double> sweep = edgeDistances(surface, far);
  double extent = 0.0;
  for (double d : sweep)
    if (d != kUnreachable) extent = std::max(extent, d);
  return extent;
}

double heatTimeStep(double meanEdgeLength, double extent, double factor) {
  const double h2 = meanEdgeLength * meanEdgeLength;
  if (factor > 0.0) return factor * h2;
  const double floor = extent / kMaxDecayLengths;
  return std::max(h2, floor * floor);
}

}  // namespace bake::geodesic
