// The groove grid (seed 000 §4.1, §4.2): a uniform grid over the domain whose cells list every
// primitive whose region can touch them, as a CSR "compact grid", plus the special-case records.
//
// Cell size (§4.1: "similar to the average width of the grooves"): the mean of 2 wmax over the
// grooves (perturbation included), rounded so the domain holds a whole number of cells per axis,
// then grown until the grid has at most maxCells cells. References: each primitive's region polygon
// (grid_region.cpp) is rasterised into the cells it meets, in parallel over fixed blocks of
// primitives; a count pass, a prefix sum (cellStart) and a fill pass in primitive order then give
// every cell its references in ascending order, whatever the thread count. Records
// (grid_records.cpp) are searched through a 4x coarser grid of the same polygons, and get the same
// CSR over the cells their boxes meet.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "bake/core/limits.h"
#include "bake/core/vector_text.h"
#include "core/parallel.h"
#include "grooves/bake/grid_stages.h"

namespace bake::grooves {
namespace {

using grid_detail::Lattice;
using grid_detail::Polygon;

constexpr std::size_t kPrimitiveBlock = 512;

double meanGrooveWidth(const GrooveScene& scene) {
  if (scene.grooves.empty()) return std::max(scene.domain[0], scene.domain[1]);
  double sum = 0;
  for (const Groove& g : scene.grooves) sum += 2 * g.wmax;
  return sum / double(scene.grooves.size());
}

std::uint64_t cellsAlong(double extent, double size) {
  const double count = std::round(extent / size);
  return count < 1 ? 1 : count > 4e9 ? std::uint64_t(4e9) : std::uint64_t(count);
}

Status chooseCells(const GrooveScene& scene, const GridSettings& settings, Lattice& lattice) {
  const Location where{"", "grid"};
  if (!(settings.cellSize >= 0) || !std::isfinite(settings.cellSize))
    return invalidInput("cell size " + numberText(settings.cellSize) + " must be finite and >= 0", where);
  if (settings.maxCells < 1) return invalidInput("the largest cell count must be at least 1", where);
  const double U = scene.domain[0], V = scene.domain[1];
  double size = settings.cellSize > 0 ? settings.cellSize : meanGrooveWidth(scene);
  auto count = [&] { return double(cellsAlong(U, size)) * double(cellsAlong(V, size)); };
  if (settings.cellSize > 0 && count() > double(settings.maxCells))
    return invalidInput("cell size " + numberText(settings.cellSize) + " gives " + numberText(count()) +
                            " cells, more than the largest count " + std::to_string(settings.maxCells),
                        where);
  // Grow by at least 1% a step, by the square root of the excess when it is large.
  while (count() > double(settings.maxCells)) size *= std::max(1.01, std::sqrt(count() / double(settings.maxCells)));
  lattice.cells[0] = static_cast<std::uint32_t>(cellsAlong(U, size));
  lattice.cells[1] = static_cast<std::uint32_t>(cellsAlong(V, size));
  lattice.origin = {0, 0};
  lattice.domain = {U, V};
  lattice.cellSize = {U / lattice.cells[0], V / lattice.cells[1]};
  lattice.wrap = scene.wrapRepeat;
  return {};
}

// The record search finds its candidate pairs through a grid of cells about four times larger: each
// primitive then meets a handful of cells, and the whole coarse CSR stays in cache, where the fine
// one (megabytes of mostly empty cells) would be read from memory for every primitive.
constexpr std::uint32_t kCoarsening = 4;

Lattice coarseLattice(const Lattice& fine) {
  Lattice coarse = fine;
  for (int axis = 0; axis < 2; ++axis)
    coarse.cells[axis] = std::max<std::uint32_t>(1, (fine.cells[axis] + kCoarsening / 2) / kCoarsening);
  coarse.cellSize = {fine.domain.u / coarse.cells[0], fine.domain.v / coarse.cells[1]};
  return coarse;
}

Lattice latticeOf(const GrooveGrid& grid) {
  Lattice lattice;
  lattice.origin = grid.origin;
  lattice.cellSize = grid.cellSize;
  lattice.cells[0] = grid.cells[0];
  lattice.cells[1] = grid.cells[1];
  lattice.domain = {grid.cellSize.u * grid.cells[0], grid.cellSize.v * grid.cells[1]};
  lattice.wrap = grid.wrapRepeat;
  return lattice;
}

// Items' cell lists, in item order: cellsOf(item, out) appends the item's cells.
template <class CellsOf>
void cellListsInOrder(std::size_t count, unsigned threads, CellsOf cellsOf, std::vector<std::uint32_t>& itemStart,
                      std::vector<std::uint32_t>& itemCells) {
  const std::size_t blocks = (count + kPrimitiveBlock - 1) / kPrimitiveBlock;
  std::vector<std::vector<std::uint32_t>> blockCells(blocks), blockCounts(blocks);
  parallelForBlocks(blocks, 1, threads, [&](std::size_t b, std::size_t) {
    const std::size_t begin = b * kPrimitiveBlock, end = std::min(count, begin + kPrimitiveBlock);
    for (std::size_t item = begin; item < end; ++item) {
      const std::size_t before = blockCells[b].size();
      cellsOf(item, blockCells[b]);
      blockCounts[b].push_back(static_cast<std::uint32_t>(blockCells[b].size() - before));
    }
  });
  itemStart.assign(count + 1, 0);
  std::size_t item = 0, total = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    for (const std::uint32_t n : blockCounts[b]) {
      total += n;
      itemStart[++item] = static_cast<std::uint32_t>(std::min<std::size_t>(total, UINT32_MAX));
    }
  }
  itemCells.clear();
  itemCells.reserve(total);
  for (auto& cells : blockCells) itemCells.insert(itemCells.end(), cells.begin(), cells.end());
}

// Turns per-item cell lists into the per-cell CSR: count, prefix sum, fill in item order. The cells
// are split into fixed ranges, each counted and filled by one task that scans every item's list and
// keeps its own cells; a cell's references are still written in item order, so the result is the
// same for any split and thread count.
Status buildCsr(std::uint64_t cellCount, const std::vector<std::uint32_t>& itemStart,
                const std::vector<std::uint32_t>& itemCells, const char* what, unsigned threads,
                std::vector<std::uint32_t>& cellStart, std::vector<std::uint32_t>& refs) {
  if (itemCells.size() >= UINT32_MAX)
    return unsupported(std::string("grid: more than 2^32 ") + what + " references; use a larger cell size");
  const std::uint64_t ranges = std::max(1u, threads), span = (cellCount + ranges - 1) / ranges;
  cellStart.assign(cellCount + 1, 0);
  parallelForBlocks(ranges, 1, threads, [&](std::size_t r, std::size_t) {
    const std::uint64_t lo = r * span, hi = std::min(cellCount, lo + span);
    for (const std::uint32_t cell : itemCells)
      if (cell >= lo && cell < hi) ++cellStart[cell + 1];
  });
  for (std::uint64_t c = 0; c < cellCount; ++c) cellStart[c + 1] += cellStart[c];
  std::vector<std::uint32_t> cursor(cellStart.begin(), cellStart.end() - 1);
  refs.assign(itemCells.size(), 0);
  const std::size_t items = itemStart.size() - 1;
  parallelForBlocks(ranges, 1, threads, [&](std::size_t r, std::size_t) {
    const std::uint64_t lo = r * span, hi = std::min(cellCount, lo + span);
    for (std::size_t item = 0; item < items; ++item)
      for (std::uint32_t k = itemStart[item]; k < itemStart[item + 1]; ++k) {
        const std::uint32_t cell = itemCells[k];
        if (cell >= lo && cell < hi) refs[cursor[cell]++] = static_cast<std::uint32_t>(item);
      }
  });
  return {};
}

// The references of the cells meeting any of the boxes, each once, ascending. A reference listed by
// several cells (a groove crossing them, or a cell listed by two boxes) is kept once by per-thread
// stamps, so only the distinct references are sorted: a sort of every listed reference costs more
// than the stamps even for a few dozen.
void gatherRefs(const GrooveGrid& grid, const std::vector<std::uint32_t>& start, const std::vector<std::uint32_t>& refs,
                const GridBox* boxes, int boxCount, std::vector<std::uint32_t>& out) {
  out.clear();
  if (grid.cellCount() == 0) return;
  thread_local std::vector<std::uint32_t> cells;  // per-thread, reused: a lookup allocates nothing
  cells.clear();
  const grid_detail::Lattice lattice = latticeOf(grid);
  for (int b = 0; b < boxCount; ++b) {
    const GridBox& box = boxes[b];
    if (!(box.lower.u <= box.upper.u) || !(box.lower.v <= box.upper.v)) continue;
    grid_detail::cellsOfBox(lattice, box.lower, box.upper, cells);
  }
  if (cells.size() == 1) {  // one cell lists each reference once, in order
    out.assign(refs.begin() + start[cells[0]], refs.begin() + start[cells[0] + 1]);
    return;
  }
  thread_local std::vector<std::uint32_t> stamp;  // the gather that last saw each reference
  thread_local std::uint32_t gather = 0;
  if (++gather == 0) {  // wrapped: forget every stamp
    std::fill(stamp.begin(), stamp.end(), 0);
    gather = 1;
  }
  for (const std::uint32_t cell : cells)
    for (std::uint32_t k = start[cell]; k < start[cell + 1]; ++k) {
      const std::uint32_t r = refs[k];
      if (r >= stamp.size()) stamp.resize(std::size_t(r) + 1, 0);
      if (stamp[r] == gather) continue;
      stamp[r] = gather;
      out.push_back(r);
    }
  // Distinct already; in index order by a scan of the stamps when they are dense enough that the
  // scan is cheaper than a sort (a footprint over many grooves).
  if (out.size() * 16 >= stamp.size()) {
    out.clear();
    for (std::uint32_t r = 0; r < stamp.size(); ++r)
      if (stamp[r] == gather) out.push_back(r);
  } else {
    std::sort(out.begin(), out.end());
  }
}

}  // namespace

void GrooveGrid::primitivesInBox(Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& out) const {
  const GridBox box{lower, upper};
  gatherRefs(*this, cellStart, primitiveRefs, &box, 1, out);
}

void GrooveGrid::primitivesInBoxes(const GridBox* boxes, int count, std::vector<std::uint32_t>& out) const {
  gatherRefs(*this, cellStart, primitiveRefs, boxes, count, out);
}

CellSpan GrooveGrid::cellSpan(Vec2 lower, Vec2 upper) const {
  const grid_detail::Lattice lattice = latticeOf(*this);
  return {{lattice.cellOf(lower.u, 0), lattice.cellOf(lower.v, 1)}, {lattice.cellOf(upper.u, 0), lattice.cellOf(upper.v, 1)}};
}

void GrooveGrid::recordsInBox(Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& out) const {
  const GridBox box{lower, upper};
  gatherRefs(*this, recordStart, recordRefs, &box, 1, out);
}

GridStats gridStats(const GrooveGrid& grid) {
  GridStats stats;
  const std::uint64_t cells = grid.cellCount();
  if (cells > 0) stats.meanRefsPerCell = double(grid.primitiveRefs.size()) / double(cells);
  for (std::uint64_t c = 0; c < cells && c + 1 < grid.cellStart.size(); ++c) {
    const std::uint32_t n = grid.cellStart[c + 1] - grid.cellStart[c];
    stats.maxRefsPerCell = std::max(stats.maxRefsPerCell, n);
    if (n == 0) ++stats.emptyCells;
  }
  for (const SpecialRecord& record : grid.records) {
    if (record.kind == SpecialRecord::Kind::Intersection) ++stats.intersections;
    if (record.kind == SpecialRecord::Kind::End) ++stats.ends;
    if (record.kind == SpecialRecord::Kind::Corner) ++stats.corners;
  }
  return stats;
}

Result<GrooveGrid> buildGrooveGrid(const GrooveScene& scene, const GridSettings& settings) {
  grid_detail::GridStageTimes times;
  return grid_detail::buildGrooveGridTimed(scene, settings, times);
}

Result<GrooveGrid> grid_detail::buildGrooveGridTimed(const GrooveScene& scene, const GridSettings& settings,
                                                      GridStageTimes& times) {
  const auto start = std::chrono::steady_clock::now();
  auto secondsSince = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  Lattice lattice;
  BAKE_RETURN_IF_ERROR(chooseCells(scene, settings, lattice));
  if (scene.primitives.size() >= UINT32_MAX) return unsupported("grid: more than 2^32 primitives");
  const unsigned threads = resolveThreadCount(settings.threads < 0 ? 0u : unsigned(settings.threads));
  const double cap = grid_detail::reachCap(scene);
  const std::size_t count = scene.primitives.size();

  std::vector<Polygon> regions(count);
  std::vector<grid_detail::FloatBox> boxes(count);
  std::vector<PrimitiveJoints> joints(count);
  parallelFor(count, threads, [&](std::size_t i) {
    joints[i] = jointsOf(scene, i);
    regions[i] = grid_detail::regionPolygon(scene, i, cap, joints[i]);
    boxes[i] = grid_detail::FloatBox::of(regions[i]);
  });

  std::vector<std::uint32_t> primitiveCellStart, primitiveCells;
  cellListsInOrder(
      count, threads,
      [&](std::size_t i, std::vector<std::uint32_t>& out) { grid_detail::cellsOfPolygon(lattice, regions[i], out); },
      primitiveCellStart, primitiveCells);

  GrooveGrid grid;
  grid.origin = lattice.origin;
  grid.cellSize = lattice.cellSize;
  grid.cells[0] = lattice.cells[0];
  grid.cells[1] = lattice.cells[1];
  grid.wrapRepeat = lattice.wrap;
  grid.joints = std::move(joints);
  BAKE_RETURN_IF_ERROR(
      buildCsr(grid.cellCount(), primitiveCellStart, primitiveCells, "primitive", threads, grid.cellStart, grid.primitiveRefs));

  times.cells = secondsSince(start);
  const auto recordsStart = std::chrono::steady_clock::now();
  const Lattice coarse = coarseLattice(lattice);
  std::vector<std::uint32_t> coarseItemStart, coarseItemCells, coarseCellStart, coarseRefs;
  cellListsInOrder(
      count, threads,
      [&](std::size_t i, std::vector<std::uint32_t>& out) { grid_detail::cellsOfPolygon(coarse, regions[i], out); },
      coarseItemStart, coarseItemCells);
  BAKE_RETURN_IF_ERROR(buildCsr(std::uint64_t(coarse.cells[0]) * coarse.cells[1], coarseItemStart, coarseItemCells,
                                "primitive", threads, coarseCellStart, coarseRefs));
  // Before the records: every pair of primitives sharing a coarse cell is tried for a crossing, so the
  // pairs are the work of that stage (a million tiny segments in one cell would be 10^12 tries).
  std::uint64_t pairs = 0;
  for (std::size_t c = 0; c + 1 < coarseCellStart.size(); ++c) {
    const std::uint64_t n = coarseCellStart[c + 1] - coarseCellStart[c];
    pairs += n * (n - 1) / 2;
  }
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::Crossings, pairs,
                                   "pairs of primitives sharing a grid cell (each is tried for a crossing)", {}));
  grid_detail::RecordInputs inputs;
  inputs.scene = &scene;
  inputs.lattice = &coarse;
  inputs.regions = &regions;
  inputs.boxes = &boxes;
  inputs.cellStart = &coarseCellStart;
  inputs.primitiveRefs = &coarseRefs;
  inputs.primitiveCellStart = &coarseItemStart;
  inputs.primitiveCells = &coarseItemCells;
  inputs.cap = cap;
  inputs.threads = threads;
  grid.records = grid_detail::findRecords(inputs);
  if (grid.records.size() >= UINT32_MAX) return unsupported("grid: more than 2^32 special-case records");

  std::vector<std::uint32_t> recordCellStart, recordCells;
  cellListsInOrder(
      grid.records.size(), threads,
      [&](std::size_t r, std::vector<std::uint32_t>& out) {
        grid_detail::cellsOfBox(lattice, grid.records[r].lower, grid.records[r].upper, out);
      },
      recordCellStart, recordCells);
  BAKE_RETURN_IF_ERROR(buildCsr(grid.cellCount(), recordCellStart, recordCells, "record", threads, grid.recordStart, grid.recordRefs));
  grid.far = buildFarLevel(scene, grid.cells);
  times.records = secondsSince(recordsStart);
  return grid;
}

std::size_t dropSpecialCases(GrooveGrid& grid) {
  const std::size_t count = grid.records.size();
  grid.records.clear();
  grid.recordRefs.clear();
  std::fill(grid.recordStart.begin(), grid.recordStart.end(), 0u);
  return count;
}

}  // namespace bake::grooves
