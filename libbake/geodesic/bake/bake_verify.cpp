// --verify K: the error of each field against exact polyhedral distances (exact.h) from the same
// sources, at K vertices drawn with a fixed seed from the vertices the exact field reaches. The error
// is relative to the field's largest exact distance (its geodesic radius), the scale on which the
// normalised field is used (seed 003, 5.2.2).
//
// An exact field cannot be its own reference, so it is checked by independent runs instead: at up to
// kExactVerifyVertices sampled vertices, the distance to each vertex source is recomputed by propagating
// backwards from the sampled vertex (d(s, v) = d(v, s) through a different set of windows), and the
// distance to each face-point source by a forward run from that source alone; the field must equal
// the smallest of them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <random>

#include "core/parallel.h"
#include "core/progress.h"
#include "geodesic/bake/bake_stages.h"
#include "geodesic/bake/exact.h"

namespace bake::geodesic {
namespace {

// Mean and max of differences relative to the field's radius, over the sampled vertices.
struct RelativeErrors {
  double radius = 0.0;
  double sum = 0.0;
  FieldError& error;

  void add(double difference) {
    const double relative = radius > 0.0 ? difference / radius : difference;
    sum += relative;
    error.maxRelative = std::max(error.maxRelative, relative);
  }
  void finish(std::size_t samples) {
    error.samples = samples;
    error.meanRelative = samples == 0 ? 0.0 : sum / double(samples);
  }
};

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
  const double radius = largestReached(exact);
  for (std::size_t v = 0; v < exact.size(); ++v)
    error.unreachableMismatches += (exact[v] == kUnreachable) != (field[v] == kUnreachable) ? 1 : 0;
  const std::vector<std::uint32_t> chosen = sampleVertices(exact, samples);
  RelativeErrors errors{radius, 0.0, error};
  for (std::uint32_t v : chosen) errors.add(field[v] == kUnreachable ? radius : std::abs(field[v] - exact[v]));
  errors.finish(chosen.size());
  return error;
}

// The exact distance at `v` from the field's sources, by independent runs (see the top of the file).
double independentExactDistance(const Surface& surface, const ResolvedField& field, std::uint32_t v, double bound,
                                std::vector<std::vector<double>>& forwardRuns, std::size_t& runs) {
  double best = kUnreachable;
  ExactOptions options;
  options.maxDistance = bound;
  std::vector<double> backward;
  for (std::size_t s = 0; s < field.points.size(); ++s) {
    const std::int64_t sourceVertex = field.points[s].vertex(surface);
    if (sourceVertex >= 0) {
      if (backward.empty()) {
        const SurfacePoint from = vertexPoint(surface, v);
        backward = exactDistances(surface, std::span<const SurfacePoint>(&from, 1), options);
        ++runs;
      }
      best = std::min(best, backward[std::size_t(sourceVertex)]);
    } else {
      if (forwardRuns[s].empty()) {
        forwardRuns[s] = exactDistances(surface, std::span<const SurfacePoint>(&field.points[s], 1));
        ++runs;
      }
      best = std::min(best, forwardRuns[s][v]);
    }
  }
  return best;
}

FieldError checkExactField(const Surface& surface, const ResolvedField& field, const std::vector<double>& distance,
                           unsigned samples, const std::function<void(std::size_t)>& checked) {
  const auto start = std::chrono::steady_clock::now();
  FieldError error;
  error.requested = samples;
  // A lone face-point source has no independent run: a forward run would repeat the computation.
  if (field.points.size() == 1 && field.points[0].vertex(surface) < 0) return error;
  const double radius = largestReached(distance);
  const std::vector<std::uint32_t> chosen = sampleVertices(distance, std::min(samples, kExactVerifyVertices));
  std::vector<std::vector<double>> forwardRuns(field.points.size());
  RelativeErrors errors{radius, 0.0, error};
  std::size_t done = 0;
  for (std::uint32_t v : chosen) {
    // Paths longer than the field's value (plus slack for round-off) cannot be the shortest.
    const double bound = distance[v] * (1.0 + 1e-6) + 1e-12 * (radius + 1.0);
    const double reference = independentExactDistance(surface, field, v, bound, forwardRuns, error.referenceRuns);
    errors.add(reference == kUnreachable ? radius : std::abs(distance[v] - reference));
    checked(++done);
  }
  errors.finish(chosen.size());
  error.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return error;
}

}  // namespace

std::vector<FieldError> verifyExactFields(const Surface& surface, const std::vector<ResolvedField>& fields,
                                          const std::vector<std::vector<double>>& distances, unsigned samples,
                                          unsigned threads, TaskProgress* progress) {
  std::vector<FieldError> errors(fields.size());
  parallelFor(
      fields.size(), threads,
      [&](std::size_t f) {
        errors[f] = checkExactField(surface, fields[f], distances[f], samples, [&, f](std::size_t checked) {
          if (progress) progress->set(f, checked);
        });
        if (progress) progress->set(f, kExactVerifyVertices);
      },
      1);
  return errors;
}

std::vector<FieldError> verifyFields(const Surface& surface, const std::vector<ResolvedField>& fields,
                                     const std::vector<std::vector<double>>& distances, unsigned samples,
                                     unsigned threads, TaskProgress* progress) {
  std::vector<FieldError> errors(fields.size());
  parallelFor(
      fields.size(), threads,
      [&](std::size_t f) {
        const auto start = std::chrono::steady_clock::now();
        ExactOptions options;
        if (progress) options.onReached = [progress, f](std::size_t reached) { progress->set(f, reached); };
        const std::vector<double> exact = exactDistances(surface, std::span<const SurfacePoint>(fields[f].points), options);
        if (progress) progress->set(f, surface.vertexCount());
        errors[f] = compare(distances[f], exact, samples);
        errors[f].requested = samples;
        errors[f].referenceRuns = 1;
        errors[f].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      },
      1);
  return errors;
}

}  // namespace bake::geodesic
