// geobake's run: read, clean, resolve sources, solve, verify, write; each stage timed in the report.
#include "bake/geodesic/bake.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bake/core/limits.h"
#include "bake/core/session.h"
#include "bake/io/glb.h"
#include "bake/io/mesh.h"
#include "core/path.h"
#include "core/progress.h"
#include "geodesic/bake/bake_stages.h"
#include "geodesic/package/bake_package.h"

namespace bake::geodesic {
namespace {

using nlohmann::json;

Status checkOptions(const Settings& settings) {
  BAKE_RETURN_IF_ERROR(checkWrittenExtension(settings.output, "-o", ".glb", "the package"));
  if (!settings.onlyFields.empty() && settings.sourcesFile.empty())
    return usageError("--fields selects fields of a --sources file; give one");
  if (settings.encoding == Encoding::Unorm16 && settings.normalization == Normalization::None)
    return usageError("--encoding unorm16 needs normalised fields (--normalize per-field or global)");
  for (std::int64_t v : settings.sourceVertices)
    if (v < 0) return usageError("--source-vertex " + std::to_string(v) + ": vertex indices are >= 0");
  if (!(settings.weldTolerance >= 0.0) || !std::isfinite(settings.weldTolerance))
    return usageError("--weld-tolerance must be a finite number >= 0");
  // A factor <= 0 means "choose the time step"; a negative or NaN one was taken for that silently.
  if (!(settings.heat.timeFactor >= 0.0) || !std::isfinite(settings.heat.timeFactor))
    return usageError("--heat-time must be a finite number >= 0 (0: chosen from the mesh)");
  return {};
}

json optionsOf(const Settings& settings) {
  return {{"method", methodName(settings.method)},
          {"combine", settings.combine},
          {"autoSources", settings.autoSources},
          {"normalization", settings.normalization == Normalization::PerField ? "per-field"
                            : settings.normalization == Normalization::Global ? "global"
                                                                                : "none"},
          {"encoding", settings.encoding == Encoding::Float ? "float" : "unorm16"},
          {"verify", settings.verifySamples},
          {"weldTolerance", settings.weldTolerance},
          {"draco", settings.draco},
          {"fields", settings.onlyFields},
          {"threads", settings.common.threads}};
}

void warnAboutCleaning(const SurfaceCleanStats& stats, Diagnostics& diagnostics) {
  if (stats.degenerateFacesRemoved > 0)
    diagnostics.warning("degenerate-faces", std::to_string(stats.degenerateFacesRemoved) +
                                                " faces with a repeated corner (after welding) are left out of the solve");
  if (stats.duplicateFacesRemoved > 0)
    diagnostics.warning("duplicate-faces",
                        std::to_string(stats.duplicateFacesRemoved) + " repeated faces are left out of the solve");
  if (stats.nonManifoldEdges > 0)
    diagnostics.warning("non-manifold-edges", std::to_string(stats.nonManifoldEdges) +
                                                  " non-manifold edges: paths continue into every face of such an edge");
}

json cleaningStatistics(const SurfaceCleanStats& stats) {
  return {{"verticesWelded", stats.verticesWelded},
          {"degenerateFacesRemoved", stats.degenerateFacesRemoved},
          {"duplicateFacesRemoved", stats.duplicateFacesRemoved},
          {"zeroAreaFaces", stats.zeroAreaFaces},
          {"unreferencedVertices", stats.unreferencedVertices},
          {"boundaryEdges", stats.boundaryEdges},
          {"nonManifoldEdges", stats.nonManifoldEdges},
          {"components", stats.components}};
}

Status bake(const Settings& settings, BakeSession& session) {
  Report& report = session.report();
  Diagnostics& diagnostics = session.diagnostics();
  session.addInput(settings.input);
  if (!settings.sourcesFile.empty()) session.addInput(settings.sourcesFile);

  TriangleMesh mesh;
  {
    StageTimer timer(&report, "read");
    MeshReadOptions options;
    options.nearOrigin = true;  // a mesh far from the origin keeps its precision (origin in the node)
    BAKE_ASSIGN_OR_RETURN(mesh, readMesh(settings.input, options));
    BAKE_RETURN_IF_ERROR(validateMesh(mesh, settings.input));
  }
  SurfaceBuild build;
  {
    StageTimer timer(&report, "clean");
    build = buildSurface(mesh, settings.weldTolerance);
  }
  warnAboutCleaning(build.stats, diagnostics);

  std::vector<ResolvedField> fields;
  {
    StageTimer timer(&report, "sources");
    BAKE_ASSIGN_OR_RETURN(fields, resolveFields(settings, mesh, build, diagnostics));
  }
  // Every field holds a double per surface vertex while solving, and a float per vertex in the package.
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::FieldValues, std::uint64_t(fields.size()) * build.surface.vertexCount(),
                                   "field values (" + std::to_string(fields.size()) + " fields x " +
                                       std::to_string(build.surface.vertexCount()) + " vertices)",
                                   {settings.input, ""}));

  SolveStats solveStats;
  std::vector<std::vector<double>> distances;
  BAKE_ASSIGN_OR_RETURN(distances, solveFields(build.surface, fields, settings, solveStats));
  if (settings.method == Method::Heat) report.addStage("factorise", solveStats.setupSeconds);
  report.addStage("solve", solveStats.fieldSeconds);
  if (solveStats.fieldsAtWindowLimit > 0)
    diagnostics.warning("window-limit", std::to_string(solveStats.fieldsAtWindowLimit) + " of " +
                                            std::to_string(fields.size()) +
                                            " exact fields stopped at the window limit: their distances are "
                                            "upper bounds (window and edge paths), not exact");

  std::vector<FieldError> errors;
  if (settings.verifySamples > 0) {
    StageTimer timer(&report, "verify");
    const bool exact = settings.method == Method::Exact;
    // On a terminal: checked vertices (exact fields) or the reference run's front (others), per field.
    TaskProgress progress("--verify (" + std::to_string(fields.size()) + " field" + (fields.size() == 1 ? "" : "s") + ")",
                          fields.size(),
                          exact ? std::min<std::uint64_t>(settings.verifySamples, kExactVerifyVertices)
                                : build.surface.vertexCount(),
                          progressEnabled(settings.common.quiet));
    errors = exact ? verifyExactFields(build.surface, fields, distances, settings.verifySamples, settings.common.threads,
                                       &progress)
                   : verifyFields(build.surface, fields, distances, settings.verifySamples, settings.common.threads,
                                  &progress);
    const std::string reference =
        exact ? "independent exact runs (backwards from sampled vertices, forwards from single face-point sources), "
                "relative to the field's largest distance"
              : "exact polyhedral distance (window propagation), relative to the field's largest distance";
    for (std::size_t f = 0; f < errors.size(); ++f) {
      if (errors[f].samples == 0) {
        diagnostics.info("field " + std::to_string(f) + ": no independent exact reference for a single face-point source");
        continue;
      }
      report.addAccuracy("geodesic distance, field " + std::to_string(f) + " (" + fields[f].name + ")", reference,
                         {{"samples", errors[f].samples},
                          {"requested", errors[f].requested},
                          {"referenceRuns", errors[f].referenceRuns},
                          {"referenceSeconds", errors[f].seconds},
                          {"meanRelative", errors[f].meanRelative},
                          {"maxRelative", errors[f].maxRelative},
                          {"unreachableMismatches", errors[f].unreachableMismatches}});
      if (exact && errors[f].requested > errors[f].samples)
        diagnostics.info("field " + std::to_string(f) + ": --verify " + std::to_string(errors[f].requested) +
                         " checks an exact field at " + std::to_string(errors[f].samples) +
                         " vertices (at most " + std::to_string(kExactVerifyVertices) +
                         ": each is an independent exact run; these took " + std::to_string(int(std::lround(errors[f].seconds * 1000))) + " ms)");
      if (!diagnostics.quiet())
        std::fprintf(stderr, "geobake: field %zu: %s error vs %s at %zu vertices: mean %.3g %%, max %.3g %% of radius (%zu reference runs, %.2f s)\n",
                     f, methodName(settings.method), exact ? "independent exact runs" : "exact", errors[f].samples, 100.0 * errors[f].meanRelative,
                     100.0 * errors[f].maxRelative, errors[f].referenceRuns, errors[f].seconds);
    }
  }

  {
    StageTimer timer(&report, "write");
    const glb::Package package = buildPackage(mesh, build, fields, distances, errors, settings);
    glb::WriteOptions options;
    options.draco.enabled = settings.draco;
    BAKE_ASSIGN_OR_RETURN(const auto bytes, glb::encode(package, options));
    BAKE_RETURN_IF_ERROR(session.stageOutput(settings.output, bytes));
  }

  std::size_t unreachable = 0;
  for (const auto& field : distances)
    for (std::uint32_t v : build.vertexMap) unreachable += field[v] == kUnreachable ? 1 : 0;
  report.setStatistic("vertices", mesh.vertexCount());
  report.setStatistic("triangles", mesh.triangleCount());
  report.setStatistic("surfaceVertices", build.surface.vertexCount());
  report.setStatistic("surfaceTriangles", build.surface.triangleCount());
  report.setStatistic("cleaning", cleaningStatistics(build.stats));
  report.setStatistic("fields", fields.size());
  report.setStatistic("unreachableVertexValues", unreachable);
  report.setStatistic("solver", solveStats.details);
  return {};
}

}  // namespace

Status check(const Settings& settings) { return checkOptions(settings); }

Result<RunFiles> inputs(const Settings& settings) {
  RunFiles run{{settings.input}, {settings.output}};
  if (!settings.sourcesFile.empty()) run.inputs.push_back(settings.sourcesFile);
  return run;
}

Status run(const Settings& settings, Diagnostics& diagnostics) {
  BAKE_RETURN_IF_ERROR(checkOptions(settings));
  BakeSession session("geobake", settings.common, diagnostics);
  session.report().setOptions(optionsOf(settings));
  return session.finish(bake(settings, session));
}

}  // namespace bake::geodesic
