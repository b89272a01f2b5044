// Farthest-point sampling: one fast-marching run per chosen vertex, folding each field into the
// running minimum.
#include "geodesic/input/farthest.h"

#include <algorithm>

#include "bake/geodesic/sources.h"
#include "geodesic/bake/fmm.h"

namespace bake::geodesic {
namespace {

bool hasFace(const Surface& surface, std::uint32_t v) {
  return surface.vertexFaceOffsets[v] != surface.vertexFaceOffsets[v + 1];
}

// The vertex with a face that is farthest by `distance`; -1 when no vertex has a face.
std::int64_t farthestVertex(const Surface& surface, const std::vector<double>& distance) {
  std::int64_t best = -1;
  for (std::uint32_t v = 0; v < surface.vertexCount(); ++v) {
    if (!hasFace(surface, v)) continue;
    if (best < 0 || distance[v] > distance[std::size_t(best)]) best = v;
  }
  return best;
}

void foldMinimum(std::vector<double>& running, const std::vector<double>& field) {
  for (std::size_t v = 0; v < running.size(); ++v) running[v] = std::min(running[v], field[v]);
}

}  // namespace

std::vector<std::uint32_t> farthestPointSamples(const Surface& surface, unsigned count) {
  std::vector<std::uint32_t> chosen;
  if (count == 0) return chosen;
  std::vector<double> running(surface.vertexCount(), kUnreachable);
  // The first sample: farthest from the first vertex with a face (not itself a sample).
  std::int64_t start = -1;
  for (std::uint32_t v = 0; v < surface.vertexCount() && start < 0; ++v)
    if (hasFace(surface, v)) start = v;
  if (start < 0) return chosen;
  const SurfacePoint seed = vertexPoint(surface, std::uint32_t(start));
  std::vector<double> probe = fastMarchingDistances(surface, {&seed, 1});
  // Unreachable vertices are farthest, but the first pick should start in the seed's component.
  for (double& d : probe)
    if (d == kUnreachable) d = -1.0;
  std::int64_t next = farthestVertex(surface, probe);
  while (next >= 0 && chosen.size() < count) {
    chosen.push_back(std::uint32_t(next));
    if (chosen.size() == count) break;  // the field from the last pick would choose nothing more
    const SurfacePoint source = vertexPoint(surface, std::uint32_t(next));
    foldMinimum(running, fastMarchingDistances(surface, {&source, 1}));
    next = farthestVertex(surface, running);
    if (next >= 0 && running[std::size_t(next)] == 0.0) break;  // every vertex is a sample already
  }
  return chosen;
}

}  // namespace bake::geodesic
