// Solving the fields. Fields are independent, so they run in parallel (one field per task; each
// solver is sequential and deterministic, so the output does not depend on the thread count). The
// heat method pays its factorisation once for all fields.
#include <algorithm>
#include <chrono>
#include <optional>

#include "core/parallel.h"
#include "core/progress.h"
#include "geodesic/bake/bake_stages.h"
#include "geodesic/bake/methods.h"

namespace bake::geodesic {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double largestReached(const std::vector<double>& distance) {
  double largest = 0.0;
  for (double d : distance)
    if (d != kUnreachable) largest = std::max(largest, d);
  return largest;
}

const char* methodName(Method method) {
  switch (method) {
    case Method::Exact: return "exact";
    case Method::Heat: return "heat";
    case Method::FastMarching: return "fmm";
  }
  return "?";
}

Result<std::vector<std::vector<double>>> solveFields(const Surface& surface,
                                                     const std::vector<ResolvedField>& fields,
                                                     const Settings& settings, SolveStats& stats) {
  const auto setupStart = std::chrono::steady_clock::now();
  std::optional<HeatSolver> heat;
  if (settings.method == Method::Heat) {
    HeatOptions options = settings.heat;
    options.threads = settings.common.threads;
    BAKE_ASSIGN_OR_RETURN(HeatSolver solver, HeatSolver::build(surface, options));
    heat.emplace(std::move(solver));
    const HeatStats& h = heat->stats();
    stats.details = {{"edgeFlips", h.edgeFlips},
                     {"timeStep", h.timeStep},
                     {"mollifyEpsilon", h.mollifyEpsilon},
                     {"tuftedEdges", h.tuftedEdges},
                     {"intrinsicSeconds", h.intrinsicSeconds},
                     {"factorSeconds", h.factorSeconds},
                     {"factorBackwardError", h.factorBackwardError},
                     {"factorsRedoneWithoutBlas", h.factorsRedoneWithoutBlas},
                     {"blasOneAtATime", h.blasOneAtATime}};
  }
  stats.setupSeconds = secondsSince(setupStart);

  const auto solveStart = std::chrono::steady_clock::now();
  std::vector<std::vector<double>> distances(fields.size());
  std::vector<ExactStats> exactStats(fields.size());
  // On a terminal, a bar over the vertices each field's front has reached (exact windows can take
  // minutes on large meshes); heat and fast marching take seconds per field.
  TaskProgress progress(std::string("exact distances (") + std::to_string(fields.size()) + " field" +
                            (fields.size() == 1 ? "" : "s") + ")",
                        fields.size(), surface.vertexCount(),
                        settings.method == Method::Exact && progressEnabled(settings.common.quiet));
  parallelFor(
      fields.size(), settings.common.threads,
      [&](std::size_t f) {
        const std::span<const SurfacePoint> sources(fields[f].points);
        switch (settings.method) {
          case Method::Exact: {
            ExactOptions options;
            if (progress.enabled()) options.onReached = [&progress, f](std::size_t reached) { progress.set(f, reached); };
            distances[f] = exactDistances(surface, sources, options, &exactStats[f]);
            progress.set(f, surface.vertexCount());
            break;
          }
          // Several fields already share the threads; one alone has them all.
          case Method::Heat: distances[f] = heat->distances(sources, fields.size() > 1 ? 1u : 0u); break;
          case Method::FastMarching: distances[f] = fastMarchingDistances(surface, sources); break;
        }
      },
      1);
  stats.fieldSeconds = secondsSince(solveStart);
  if (settings.method == Method::Exact) {
    ExactStats total;
    for (const ExactStats& s : exactStats) {
      total.windowsCreated += s.windowsCreated;
      total.windowsPropagated += s.windowsPropagated;
      total.pseudoSources += s.pseudoSources;
      total.windowsPeak = std::max(total.windowsPeak, s.windowsPeak);
      if (s.windowLimitReached) ++stats.fieldsAtWindowLimit;
    }
    stats.details = {{"windowsCreated", total.windowsCreated},
                     {"windowsPropagated", total.windowsPropagated},
                     {"windowsPeak", total.windowsPeak},
                     {"fieldsAtWindowLimit", stats.fieldsAtWindowLimit},
                     {"pseudoSources", total.pseudoSources}};
  }
  for (std::size_t f = 0; f < fields.size(); ++f)
    for (std::size_t v = 0; v < distances[f].size(); ++v)
      if (std::isnan(distances[f][v]) || distances[f][v] < 0.0)
        return internalError("the " + std::string(methodName(settings.method)) + " solver returned " +
                                 std::to_string(distances[f][v]) + " at vertex " + std::to_string(v),
                             {settings.input, "field " + std::to_string(f)});
  return distances;
}

}  // namespace bake::geodesic
