// The heat method (Crane, Weischedel and Wardetzky 2013, Algorithm 1) on the robust intrinsic
// Laplacian of Sharp and Crane 2020:
//   build:     tufted cover -> mollify -> intrinsic Delaunay flips -> L, M; factorise M + tL and L
//              (L pinned at one vertex per component, so it is definite).
//   per field: I.   solve (M + tL) u = delta_sources          (heat flow for time t)
//              II.  X = -grad u / |grad u| per face             (direction away from the sources)
//              III. solve L phi = div X                         (the function whose gradient best fits X)
// Step III fixes phi only up to a constant per component. One source: phi is shifted so that it is 0
// at the source. A source inside a face holds phi's linear interpolant there at the interpolant of its
// true distances to the face's corners (straight segments in the face), not at 0: the distance is a
// cone whose tip lies inside the face, and forcing its interpolant to 0 would pull the corners, and
// with them the whole field, down by a fraction of an edge (r below is that value, 0 at a vertex).
// Several sources: shifting by the minimum (as CGAL 5.5 does) lets the solution's error pull distances
// between sources towards 0; instead every source is held at its value by a Dirichlet condition,
// imposed on the pinned factor with Lagrange multipliers: phi = G(b + C lambda) + mu, where G is the
// pinned inverse, the columns of C are the sources' barycentric weights, C^T phi = r and the
// multipliers sum to 0 (so the pinned row's equation holds too). That costs one extra
// back-substitution per source, one more for the correction and a small dense system
// (HeatOptions::maxPinnedSources bounds it). Components without a source are unreachable.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>

#include <Eigen/Dense>

#include "bake/geodesic/heat.h"
#include "core/parallel.h"
#include "geodesic/bake/heat_cholmod.h"
#include "geodesic/bake/heat_intrinsic.h"
#include "geodesic/bake/heat_operators.h"
#include "geodesic/bake/heat_timestep.h"

namespace bake::geodesic {

// Everything a field needs after build(); read-only in distances().
struct HeatSystem {
  std::size_t vertexCount = 0;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Vec3d> positions;
  std::vector<std::uint32_t> componentOf;
  std::uint32_t componentCount = 0;
  std::vector<char> isolated;  // vertices without a face: never reached
  std::vector<char> pinned;    // one vertex per component, held at 0 in the pinned Poisson factor
  HeatOperators ops;
  std::optional<CholeskyFactor> heat;
  std::optional<CholeskyFactor> poisson;
  // Where a field lives from step I to step III. When both factors share one row order (one
  // analysis) and both go through our own substitution, in that order: row k is vertex vertexOfRow[k]
  // and ops.faces name rows, so no solve copies its values in or out. Otherwise (both empty) row k is
  // vertex k.
  std::vector<std::uint32_t> vertexOfRow;
  std::vector<std::uint32_t> rowOfVertex;
  std::size_t maxPinnedSources = 0;
  std::size_t maxSeparateSources = 0;
  // A field's default threads (HeatOptions::threads). Fields call no BLAS: their solves are our own
  // substitution (or CHOLMOD's simplicial solve), so a sequential OpenBLAS does not hold them.
  unsigned threads = 1;
};

struct HeatSolver::State : HeatSystem {
  HeatStats stats;
};

namespace {

// A source as a row of the constraint matrix C: its corners and normalised barycentric weights.
struct SourceRow {
  std::array<std::uint32_t, 3> vertices;
  std::array<double, 3> weights;
  double value;  // what phi's interpolant must be at the source (0 at a vertex)
  std::uint32_t component;
  std::int64_t vertex;  // the vertex it sits on, or -1
};

// The linear interpolant, at a point of a face, of the distances from that point to the face's corners.
double interpolatedCornerDistance(const HeatSystem& state, const SourceRow& row) {
  Vec3d point{0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) point[k] += row.weights[i] * state.positions[row.vertices[i]][k];
  double value = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3d& corner = state.positions[row.vertices[i]];
    value += row.weights[i] * std::hypot(corner[0] - point[0], corner[1] - point[1], corner[2] - point[2]);
  }
  return value;
}

std::vector<SourceRow> sourceRows(const HeatSystem& state, std::span<const SurfacePoint> sources) {
  std::vector<SourceRow> rows;
  std::vector<char> vertexSeen(state.vertexCount, 0);
  for (const SurfacePoint& p : sources) {
    if (p.face >= state.triangles.size()) continue;
    SourceRow row{state.triangles[p.face], {}, 0.0, 0, -1};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      row.weights[i] = std::isfinite(p.barycentric[i]) ? std::max(0.0, p.barycentric[i]) : 0.0;
      sum += row.weights[i];
      if (p.barycentric[i] == 1.0) row.vertex = row.vertices[i];
    }
    if (!(sum > 0.0)) row.weights = {1.0, 0.0, 0.0}, sum = 1.0;
    for (double& w : row.weights) w /= sum;
    if (row.vertex >= 0) {
      if (vertexSeen[row.vertex]) continue;  // a repeated source would make the constraints singular
      vertexSeen[row.vertex] = 1;
      row.weights = {0.0, 0.0, 0.0};
      for (int i = 0; i < 3; ++i) row.weights[i] = row.vertices[i] == row.vertex ? 1.0 : 0.0;
    }
    row.component = state.componentOf[row.vertices[0]];
    row.value = interpolatedCornerDistance(state, row);
    rows.push_back(row);
  }
  return rows;
}

double rowDot(const SourceRow& row, const double* field) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += row.weights[i] * field[row.vertices[i]];
  return s;
}

std::size_t rowOf(const HeatSystem& state, std::size_t vertex) {
  return state.rowOfVertex.empty() ? vertex : state.rowOfVertex[vertex];
}
std::size_t vertexOf(const HeatSystem& state, std::size_t row) {
  return state.vertexOfRow.empty() ? row : state.vertexOfRow[row];
}

// Solves with `factor` in place, for `columns` interleaved fields in rows (see HeatSystem::vertexOfRow).
void solveRows(const HeatSystem& state, const CholeskyFactor& factor, std::vector<double>& values,
               std::size_t columns, unsigned threads) {
  if (!state.vertexOfRow.empty()) {
    factor.substitution()->solveInFactorOrder(values, columns, threads);
    return;
  }
  std::vector<double> solution(values.size());
  factor.solve(values, solution, columns, threads, ColumnLayout::Interleaved);
  values = std::move(solution);
}

// Step I for `columns` sources rows[first, first + columns): heat spread over their face corners by
// barycentric weight, in rows, interleaved.
std::vector<double> heatFlow(const HeatSystem& state, const std::vector<SourceRow>& rows, std::size_t first,
                             std::size_t columns, unsigned threads) {
  std::vector<double> u(state.vertexCount * columns, 0.0);
  for (std::size_t j = 0; j < columns; ++j)
    for (int i = 0; i < 3; ++i) u[rowOf(state, rows[first + j].vertices[i]) * columns + j] += rows[first + j].weights[i];
  solveRows(state, *state.heat, u, columns, threads);
  return u;
}

// Steps II and III with the pinned factor, phi0 = G div X, for `columns` interleaved fields in rows.
std::vector<double> integrateDirections(const HeatSystem& state, const std::vector<double>& u,
                                        std::size_t columns, unsigned threads) {
  std::vector<double> phi(state.vertexCount * columns, 0.0);  // div X, then phi0
  divergenceOfNormalizedGradient(state.ops.faces, u, phi, columns, threads);
  for (std::size_t k = 0; k < state.vertexCount; ++k) {
    const std::size_t v = vertexOf(state, k);
    if (state.pinned[v] || state.isolated[v]) std::fill_n(phi.begin() + k * columns, columns, 0.0);
  }
  solveRows(state, *state.poisson, phi, columns, threads);
  return phi;
}

// Solves [S 1; 1^T 0] [lambda; mu] = [r; 0] for one component's sources (least squares when sources
// coincide). Returns lambda followed by mu.
Eigen::VectorXd multipliers(const Eigen::MatrixXd& s, const Eigen::VectorXd& r) {
  const Eigen::Index k = s.rows();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(k + 1, k + 1);
  system.topLeftCorner(k, k) = s;
  system.topRightCorner(k, 1).setOnes();
  system.bottomLeftCorner(1, k).setOnes();
  Eigen::VectorXd right = Eigen::VectorXd::Zero(k + 1);
  right.head(k) = r;
  return system.completeOrthogonalDecomposition().solve(right);
}

// Holds every source of a component with several sources at its value (see the file comment), in
// place. The Schur complement C^T G C is gathered a few columns at a time so that the workspace stays
// a few fields in size; the correction G C lambda is then one more solve.
void pinSources(const HeatSystem& state, const std::vector<SourceRow>& rows,
                const std::vector<std::size_t>& members, unsigned threads, std::vector<double>& phi) {
  constexpr std::size_t kBatch = 8;
  const std::size_t n = state.vertexCount, k = members.size();
  // Column s of C: the barycentric weights of source s, without the pinned vertex's entry.
  const auto addColumn = [&](std::size_t s, double scale, double* column) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = rows[members[s]].vertices[i];
      if (!state.pinned[v]) column[v] += scale * rows[members[s]].weights[i];
    }
  };
  Eigen::MatrixXd schur(k, k);
  Eigen::VectorXd right(k);
  for (std::size_t first = 0; first < k; first += kBatch) {
    const std::size_t m = std::min(kBatch, k - first);
    std::vector<double> c(n * m, 0.0), gc(n * m, 0.0);
    for (std::size_t j = 0; j < m; ++j) addColumn(first + j, 1.0, c.data() + j * n);
    state.poisson->solve(c, gc, m, threads);
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t j = 0; j < m; ++j) schur(a, first + j) = rowDot(rows[members[a]], gc.data() + j * n);
  }
  for (std::size_t a = 0; a < k; ++a)
    right[a] = rows[members[a]].value - rowDot(rows[members[a]], phi.data());
  const Eigen::VectorXd solution = multipliers(0.5 * (schur + schur.transpose()), right);
  std::vector<double> forces(n, 0.0), correction(n, 0.0);
  for (std::size_t s = 0; s < k; ++s) addColumn(s, solution[s], forces.data());
  state.poisson->solve(forces, correction, 1, threads);
  const std::uint32_t component = rows[members[0]].component;
  for (std::size_t v = 0; v < n; ++v)
    if (state.componentOf[v] == component) phi[v] += correction[v] + solution[k];
}

// Shifts a component so that its sources' mean error is 0 (one source: that source is exact).
void shiftToSources(const HeatSystem& state, const std::vector<SourceRow>& rows,
                    const std::vector<std::size_t>& members, std::span<double> phi) {
  double mean = 0.0;
  for (std::size_t m : members) mean += rowDot(rows[m], phi.data()) - rows[m].value;
  mean /= static_cast<double>(members.size());
  const std::uint32_t component = rows[members[0]].component;
  for (std::size_t v = 0; v < state.vertexCount; ++v)
    if (state.componentOf[v] == component) phi[v] -= mean;
}

std::vector<char> pinOnePerComponent(const Surface& surface, const std::vector<char>& isolated) {
  std::vector<char> pinned(surface.vertexCount(), 0), done(surface.componentCount, 0);
  for (std::uint32_t v = 0; v < surface.vertexCount(); ++v)
    if (!isolated[v] && !done[surface.componentOf[v]]) done[surface.componentOf[v]] = pinned[v] = 1;
  return pinned;
}

bool finiteGeometry(const Surface& surface) {
  for (const Vec3d& p : surface.positions)
    for (double x : p)
      if (!std::isfinite(x)) return false;
  return std::all_of(surface.edgeLengths.begin(), surface.edgeLengths.end(),
                     [](double l) { return std::isfinite(l); });
}

// See HeatSystem::vertexOfRow.
void orderByFactorRows(HeatSystem& state) {
  const SubstitutionPlan* heat = state.heat->substitution();
  const SubstitutionPlan* poisson = state.poisson->substitution();
  if (!heat || !poisson) return;
  const std::size_t n = state.vertexCount;
  const auto rowsOf = [n](const SubstitutionPlan& plan) {
    std::vector<std::uint32_t> vertices(n);
    for (std::size_t k = 0; k < n; ++k)
      vertices[k] = plan.permutation() ? static_cast<std::uint32_t>(plan.permutation()[k]) : static_cast<std::uint32_t>(k);
    return vertices;
  };
  std::vector<std::uint32_t> vertexOfRow = rowsOf(*heat);
  if (vertexOfRow != rowsOf(*poisson)) return;
  state.rowOfVertex.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) state.rowOfVertex[vertexOfRow[k]] = static_cast<std::uint32_t>(k);
  state.vertexOfRow = std::move(vertexOfRow);
  for (HeatFace& face : state.ops.faces)
    for (std::uint32_t& v : face.vertices) v = state.rowOfVertex[v];
}

}  // namespace

Result<HeatSolver> HeatSolver::build(const Surface& surface, const HeatOptions& options) {
  if (!finiteGeometry(surface)) return invalidInput("surface has non-finite vertex positions");
  auto state = std::make_unique<State>();
  state->vertexCount = surface.vertexCount();
  state->triangles = surface.triangles;
  state->positions = surface.positions;
  state->componentOf = surface.componentOf;
  state->componentCount = surface.componentCount;
  state->maxPinnedSources = options.maxPinnedSources;
  state->maxSeparateSources = options.maxSeparateSources;
  state->isolated.assign(surface.vertexCount(), 1);
  for (const auto& t : surface.triangles)
    for (std::uint32_t v : t) state->isolated[v] = 0;
  state->pinned = pinOnePerComponent(surface, state->isolated);
  HeatStats& stats = state->stats;
  if (surface.triangleCount() == 0) return HeatSolver(std::move(state));

  const auto intrinsicStart = std::chrono::steady_clock::now();
  const double h = surface.meanEdgeLength > 0.0 ? surface.meanEdgeLength : 1.0;
  // The intrinsic operators and the extent estimate (two edge-path sweeps, for the time step) only
  // read the surface: they run side by side.
  parallelForBlocks(2, 1, options.threads, [&](std::size_t k, std::size_t) {
    if (k == 1) {
      stats.geodesicExtent = estimateGeodesicExtent(surface);
      return;
    }
    IntrinsicBuildStats intrinsic;
    IntrinsicTriangulation mesh = buildTuftedCover(surface, intrinsic);
    stats.mollifyEpsilon = mollify(mesh, options.mollifyFactor * h);
    stats.edgeFlips = flipToDelaunay(mesh);
    stats.tuftedEdges = intrinsic.nonManifoldEdges;
    stats.doubledCover = intrinsic.doubled;
    state->ops = buildHeatOperators(mesh, surface.vertexCount());
  });
  stats.timeStep = heatTimeStep(h, stats.geodesicExtent, options.timeFactor);
  stats.intrinsicSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - intrinsicStart).count();

  const auto start = std::chrono::steady_clock::now();
  std::vector<char> poissonIdentity(surface.vertexCount());
  for (std::size_t v = 0; v < surface.vertexCount(); ++v)
    poissonIdentity[v] = state->isolated[v] || state->pinned[v];
  const std::vector<double> none(surface.vertexCount(), 0.0);
  // The two matrices assemble at once (each alone, so they never depend on the thread count).
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> heatMatrix, poissonMatrix;
  parallelForBlocks(2, 1, options.threads, [&](std::size_t k, std::size_t) {
    if (k == 0) heatMatrix = assembleUpper(state->ops, stats.timeStep, state->ops.mass, state->isolated);
    else poissonMatrix = assembleUpper(state->ops, 1.0, none, poissonIdentity);
  });
  const std::array<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>*, 2> matrices{&heatMatrix,
                                                                                          &poissonMatrix};
  FactoriseReport factorising;
  BAKE_ASSIGN_OR_RETURN(std::vector<CholeskyFactor> factors,
                        CholeskyFactor::factoriseAll(matrices, options.threads, &factorising));
  stats.factorBackwardError = factorising.worstBackwardError;
  stats.factorsRedoneWithoutBlas = factorising.redoneWithoutBlas;
  stats.blasOneAtATime = factorising.oneAtATime;
  state->threads = options.threads;
  state->heat.emplace(std::move(factors[0]));
  state->poisson.emplace(std::move(factors[1]));
  orderByFactorRows(*state);
  stats.factorSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return HeatSolver(std::move(state));
}

namespace {

using Components = std::map<std::uint32_t, std::vector<std::size_t>>;

Components groupByComponent(const std::vector<SourceRow>& rows) {
  Components byComponent;
  for (std::size_t r = 0; r < rows.size(); ++r) byComponent[rows[r].component].push_back(r);
  return byComponent;
}

// One heat-method field from all the rows together, each source held at its value (or, beyond the
// pin limit, the mean over the sources). Valid on the components that hold a source.
std::vector<double> combinedField(const HeatSystem& state, const std::vector<SourceRow>& rows, unsigned threads) {
  // One column: the sum of every source's heat.
  std::vector<double> delta(state.vertexCount, 0.0);
  for (const SourceRow& row : rows)
    for (int i = 0; i < 3; ++i) delta[rowOf(state, row.vertices[i])] += row.weights[i];
  solveRows(state, *state.heat, delta, 1, threads);
  const std::vector<double> byRow = integrateDirections(state, delta, 1, threads);
  std::vector<double> phi(state.vertexCount);
  for (std::size_t k = 0; k < state.vertexCount; ++k) phi[vertexOf(state, k)] = byRow[k];
  const Components byComponent = groupByComponent(rows);
  std::size_t pinnedTotal = 0;
  for (const auto& [component, members] : byComponent)
    if (members.size() > 1) pinnedTotal += members.size();
  for (const auto& [component, members] : byComponent) {
    if (members.size() > 1 && pinnedTotal <= state.maxPinnedSources)
      pinSources(state, rows, members, threads, phi);
    else
      shiftToSources(state, rows, members, phi);
  }
  return phi;
}

// body(begin, end) over blocks of [0, count), on up to `threads` threads where there are enough
// vertices to pay for starting one. For loops whose every vertex is computed alone (so the result is
// the same on any number of threads).
void forEachVertexBlock(std::size_t count, unsigned threads,
                        const std::function<void(std::size_t, std::size_t)>& body) {
  constexpr std::size_t kBlock = 16384;
  if (count < 2 * kBlock) {
    body(0, count);
    return;
  }
  parallelForBlocks(count, kBlock, threads, body);
}

// Steps I to III for the sources rows[first, first + m) through each factor together, m columns in
// one solve (the factor is read once per batch instead of once per source), each field shifted to
// its source; their minimum into phi. The fields are interleaved (a row's m values side by side), so
// that step II reads and writes one short row per corner for all of them; every field's values are
// those it would have alone.
void singleFieldsBatch(const HeatSystem& state, const std::vector<SourceRow>& rows, std::size_t first,
                       std::size_t m, unsigned solveThreads, std::vector<double>& phi) {
  const std::size_t n = state.vertexCount;
  const std::vector<double> field =
      integrateDirections(state, heatFlow(state, rows, first, m, solveThreads), m, solveThreads);
  // Each field shifted so that its source's error is 0 (as shiftToSources does for one field alone).
  std::vector<double> shift(m);
  std::vector<std::uint32_t> component(m);
  for (std::size_t j = 0; j < m; ++j) {
    const SourceRow& row = rows[first + j];
    double value = 0.0;
    for (int i = 0; i < 3; ++i) value += row.weights[i] * field[rowOf(state, row.vertices[i]) * m + j];
    shift[j] = value - row.value;
    component[j] = row.component;
  }
  forEachVertexBlock(n, solveThreads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t v = vertexOf(state, k);
      for (std::size_t j = 0; j < m; ++j)
        if (state.componentOf[v] == component[j]) phi[v] = std::min(phi[v], field[k * m + j] - shift[j]);
    }
  });
}

// The minimum of one field per source: each is the single-source heat method, which is more accurate
// than one field from the summed heat of all sources (where the sources' kernels meet, the normalised
// gradient turns sharply and the Poisson step smooths the ridge: on the teapot, 2.9 % mean error for
// two sources against 1.5 % for the minimum of their fields). Two solves per source.
std::vector<double> minimumOfSingleFields(const HeatSystem& state, const std::vector<SourceRow>& rows,
                                          unsigned threads) {
  // Batches of up to as many columns as a substitution takes, run side by side. A field's values do
  // not depend on the batch it is in (see singleFieldsBatch), nor then on the thread count.
  constexpr std::size_t kBatch = SubstitutionPlan::kMaxColumns;
  const std::size_t batches = (rows.size() + kBatch - 1) / kBatch;
  std::vector<std::vector<double>> partial(batches);
  // One batch alone has the threads to itself for its substitutions.
  const unsigned solveThreads = batches == 1 ? threads : 1u;
  parallelForBlocks(batches, 1, threads, [&](std::size_t b, std::size_t) {
    partial[b].assign(state.vertexCount, kUnreachable);
    singleFieldsBatch(state, rows, b * kBatch, std::min(kBatch, rows.size() - b * kBatch), solveThreads,
                      partial[b]);
  });
  std::vector<double> phi = std::move(partial[0]);
  for (std::size_t b = 1; b < batches; ++b)
    for (std::size_t v = 0; v < state.vertexCount; ++v) phi[v] = std::min(phi[v], partial[b][v]);
  return phi;
}

// Bounds that every surface path obeys, applied to the approximate field: no vertex is nearer to a
// source of its component than in a straight line (the heat method's smoothing rounds the distance's
// tip and ridges, so it undershoots there), and the corners of a source's faces are no farther than
// the straight segment inside the face. Both only move values towards the true distance. Costs
// O(vertices x sources), so it is skipped beyond kMaxBoundedSources.
constexpr std::size_t kMaxBoundedSources = 64;

double straightDistance(const Vec3d& a, const Vec3d& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  const double squared = dx * dx + dy * dy + dz * dz;
  // hypot only where the squares could overflow or lose digits to underflow (it costs several times more).
  if (squared < std::numeric_limits<double>::max() && squared > 1e-280) return std::sqrt(squared);
  return std::hypot(dx, dy, dz);
}

void applyPathBounds(const HeatSystem& state, const std::vector<SourceRow>& rows, unsigned threads,
                     std::vector<double>& result) {
  if (rows.size() > kMaxBoundedSources) return;
  std::vector<Vec3d> points;
  for (const SourceRow& row : rows) {
    Vec3d p{0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) p[k] += row.weights[i] * state.positions[row.vertices[i]][k];
    points.push_back(p);
  }
  forEachVertexBlock(state.vertexCount, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      if (!std::isfinite(result[v])) continue;
      double lower = kUnreachable;
      for (std::size_t r = 0; r < rows.size(); ++r)
        if (rows[r].component == state.componentOf[v])
          lower = std::min(lower, straightDistance(state.positions[v], points[r]));
      if (lower != kUnreachable) result[v] = std::max(result[v], lower);
    }
  });
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::uint32_t v : rows[r].vertices)
      result[v] = std::min(result[v], straightDistance(state.positions[v], points[r]));
}

}  // namespace

std::vector<double> HeatSolver::distances(std::span<const SurfacePoint> sources, unsigned threads) const {
  const State& state = *state_;
  if (threads == 0) threads = state.threads;
  std::vector<double> result(state.vertexCount, kUnreachable);
  const std::vector<SourceRow> rows = sourceRows(state, sources);
  if (rows.empty() || !state.heat) return result;

  const std::vector<double> phi = rows.size() > 1 && rows.size() <= state.maxSeparateSources
                                      ? minimumOfSingleFields(state, rows, threads)
                                      : combinedField(state, rows, threads);
  const Components byComponent = groupByComponent(rows);
  std::vector<char> reached(state.componentCount, 0);
  for (const auto& [component, members] : byComponent) reached[component] = 1;
  for (std::size_t v = 0; v < state.vertexCount; ++v)
    if (reached[state.componentOf[v]] && !state.isolated[v])
      result[v] = std::isfinite(phi[v]) ? std::max(0.0, phi[v]) : 0.0;
  applyPathBounds(state, rows, threads, result);
  for (const SourceRow& row : rows)
    if (row.vertex >= 0) result[static_cast<std::size_t>(row.vertex)] = 0.0;
  return result;
}

const HeatStats& HeatSolver::stats() const { return state_->stats; }

HeatSolver::HeatSolver(std::unique_ptr<State> state) : state_(std::move(state)) {}
HeatSolver::HeatSolver(HeatSolver&&) noexcept = default;
HeatSolver& HeatSolver::operator=(HeatSolver&&) noexcept = default;
HeatSolver::~HeatSolver() = default;

}  // namespace bake::geodesic
