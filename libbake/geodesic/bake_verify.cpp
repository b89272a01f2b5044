// --verify K: the error of each field against exact polyhedral distances (exact.h) from the same
// sources, at K vertices drawn with a fixed seed from the vertices the exact field reaches. The error
// is relative to the field's largest exact distance (its geodesic radius), the scale on which the
// normalised field is used (seed 003, 5.2.2).
#include <algorithm>
#include <cmath>
#include <random>

#include "core/parallel.h"
#include "geodesic/bake_stages.h"
#include "geodesic/exact.h"

namespace bake::geodesic {
namespace {

std::vector<std::uint32_t> sampleVertices(const std::vector<double>& exact, unsigned samples) {
  std::vector<std::uint32_t> reachable;
  for (std::uint32_t v = 0; v < exact.size(); ++v)
    if (exact[v] != kUnreachable) reachable.push_back(v);
  if (reachable.size() <= samples) return reachable;
  std::mt19937_64 random(0x9e0bace);
  std::shuffle(reachable.begin(), reachable.end(), random);
  reachable.resize(samples);
  std::sort(reachable.begin(), reachable.end());
  return reachable;
}

FieldError compare(const std::vector<double>& field, const std::vector<double>& exact, unsigned samples) {
  FieldError error;
  double radius = 0.0;
  for (double d : exact)
    if (d != kUnreachable) radius = std::max(radius, d);
  for (std::size_t v = 0; v < exact.size(); ++v)
    error.unreachableMismatches += (exact[v] == kUnreachable) != (field[v] == kUnreachable) ? 1 : 0;
  const std::vector<std::uint32_t> chosen = sampleVertices(exact, samples);
  double sum = 0.0;
  for (std::uint32_t v : chosen) {
    const double difference = field[v] == kUnreachable ? radius : std::abs(field[v] - exact[v]);
    const double relative = radius > 0.0 ? difference / radius : difference;
    sum += relative;
    error.maxRelative = std::max(error.maxRelative, relative);
  }
  error.samples = chosen.size();
  error.meanRelative = chosen.empty() ? 0.0 : sum / double(chosen.size());
  return error;
}

}  // namespace

std::vector<FieldError> verifyFields(const Surface& surface, const std::vector<ResolvedField>& fields,
                                     const std::vector<std::vector<double>>& distances, unsigned samples,
                                     unsigned threads) {
  std::vector<FieldError> errors(fields.size());
  parallelFor(
      fields.size(), threads,
      [&](std::size_t f) {
        const std::vector<double> exact = exactDistances(surface, std::span<const SurfacePoint>(fields[f].points));
        errors[f] = compare(distances[f], exact, samples);
      },
      1);
  return errors;
}

}  // namespace bake::geodesic
