// The stages of a geobake run (bake.cpp strings them together), one file each:
// bake_sources.cpp resolves what the user asked for into surface points, bake_solve.cpp computes the
// fields, bake_verify.cpp measures them against exact distances, bake_package.cpp normalises, encodes
// and describes them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"
#include "bake/geodesic/bake.h"
#include "bake/geodesic/sources.h"
#include "bake/geodesic/surface.h"
#include "bake/io/mesh.h"

namespace bake {
class TaskProgress;  // core/progress.h
}

namespace bake::geodesic {

struct ResolvedField {
  std::string name;
  std::vector<SourceSpec> specs;
  std::vector<SurfacePoint> points;     // one per spec
  std::vector<double> snapDistances;    // point and node sources: distance moved onto the surface
};

// Reads the sources file (if any), adds the command-line and farthest-point sources, and snaps them.
Result<std::vector<ResolvedField>> resolveFields(const Settings& settings, const TriangleMesh& mesh,
                                                 const SurfaceBuild& build, Diagnostics& diagnostics);

struct SolveStats {
  double setupSeconds = 0.0;  // heat: intrinsic triangulation and factorisation
  double fieldSeconds = 0.0;  // all fields
  std::size_t fieldsAtWindowLimit = 0;  // exact fields that stopped at the window limit (upper bounds)
  nlohmann::json details = nlohmann::json::object();
};

// The largest distance that is not kUnreachable (0 when none is).
double largestReached(const std::vector<double>& distance);

// One distance vector per field, per surface vertex (kUnreachable where no path reaches).
Result<std::vector<std::vector<double>>> solveFields(const Surface& surface,
                                                     const std::vector<ResolvedField>& fields,
                                                     const Settings& settings, SolveStats& stats);

// Error of a field against exact distances at `samples` vertices, relative to the largest exact
// distance of the field (the geodesic radius from its sources).
// An exact field is checked at no more vertices than this: each costs a whole exact run.
constexpr unsigned kExactVerifyVertices = 8;

struct FieldError {
  std::size_t samples = 0;
  double meanRelative = 0.0;
  double maxRelative = 0.0;
  std::size_t unreachableMismatches = 0;  // reachable in one field and not in the other
  std::size_t requested = 0;              // what --verify asked for
  std::size_t referenceRuns = 0;          // exact propagations the reference needed
  double seconds = 0;                     // what the reference cost
};
// `progress` (may be null): one task per field.
std::vector<FieldError> verifyFields(const Surface& surface, const std::vector<ResolvedField>& fields,
                                     const std::vector<std::vector<double>>& distances, unsigned samples,
                                     unsigned threads, TaskProgress* progress = nullptr);
// For fields computed by the exact method itself: independent exact runs (backwards from up to
// kExactVerifyVertices
// sampled vertices, or forwards from each face-point source alone) must give the same distances.
std::vector<FieldError> verifyExactFields(const Surface& surface, const std::vector<ResolvedField>& fields,
                                          const std::vector<std::vector<double>>& distances, unsigned samples,
                                          unsigned threads, TaskProgress* progress = nullptr);

}  // namespace bake::geodesic
