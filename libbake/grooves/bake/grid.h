// The groove grid (seed 000 §4.1, §4.2): a uniform grid over the domain whose cells list the
// primitives whose band (path ± the groove's wmax, perturbation included) overlaps them, stored as a
// CSR "compact grid" (cell starts by prefix sum, one flat reference list), plus per-cell special-case
// records: where two non-parallel bands overlap (intersections), open ends and corners. The query
// box of a footprint is enlarged by hmax/dmax projected along the view and the light (§4.1).
#pragma once

#include <cstdint>
#include <vector>

#include "bake/core/status.h"
#include "grooves/bake/far_level.h"
#include "grooves/input/scene.h"

namespace bake::grooves {

struct GridSettings {
  double cellSize = 0;               // texture units; 0 = automatic (§4.1: the mean groove width 2 wmax)
  std::uint64_t maxCells = 1u << 22;  // the automatic size grows the cells until the grid fits
  int threads = 0;                    // 0 = hardware
};

// A special case (§4.2, Figure 5) and the box of the base plane it affects: a footprint box that
// meets it is shaded by area sampling (§6).
struct SpecialRecord {
  enum class Kind : std::uint32_t { Intersection = 0, End = 1, Corner = 2 };
  Kind kind = Kind::Intersection;
  Vec2 point;            // the paths' crossing point, the end point, the corner point
  Vec2 lower, upper;     // the box of the affected region (overlap of the bands; the end cap; the mitre)
  std::uint32_t primitive[2] = {0, 0};  // the primitives involved (End: both the same)
};

// Where a primitive's region stops (formats/groove-scene.md, "Region"): the line through `point` with
// unit `normal` pointing into the primitive's side; at an open end the flat cut, at a joint the mitre.
struct JointLine {
  Vec2 point, normal;
  bool openEnd = false;
};
struct PrimitiveJoints {
  JointLine start, end;
};
PrimitiveJoints jointsOf(const GrooveScene& scene, std::size_t primitive);

struct GridBox {
  Vec2 lower, upper;
};

// The unwrapped cell indices of a box's corners: two boxes with the same span meet the same cells,
// so a gather for one serves the other.
struct CellSpan {
  std::int64_t first[2] = {0, 0}, last[2] = {-1, -1};
  bool operator==(const CellSpan&) const = default;
};

struct GrooveGrid {
  Vec2 origin;                       // lower corner of the domain
  Vec2 cellSize;                     // per axis (the domain is an integer number of cells)
  std::uint32_t cells[2] = {0, 0};   // columns (u), rows (v)
  std::vector<std::uint32_t> cellStart;      // cells[0] * cells[1] + 1 prefix sums into primitiveRefs
  std::vector<std::uint32_t> primitiveRefs;  // primitive indices, ascending within a cell
  std::vector<std::uint32_t> recordStart;    // the same for records
  std::vector<std::uint32_t> recordRefs;
  std::vector<SpecialRecord> records;
  bool wrapRepeat = false;
  // Every primitive's joint lines, as the grid was built with them (found once here rather than at
  // every pixel); empty for a grid read back from a package, where they are found when needed.
  std::vector<PrimitiveJoints> joints;
  // For footprints over more primitives than the runtime holds (far_level.h).
  FarLevel far;

  std::uint64_t cellCount() const { return std::uint64_t(cells[0]) * cells[1]; }
  // Primitives / records of the cells that meet the box [lower, upper] (wrapping with the domain when
  // the scene repeats), each once, ascending.
  void primitivesInBox(Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& out) const;
  void recordsInBox(Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& out) const;
  // The primitives of the cells that meet any of the boxes, each once, ascending.
  void primitivesInBoxes(const GridBox* boxes, int count, std::vector<std::uint32_t>& out) const;
  CellSpan cellSpan(Vec2 lower, Vec2 upper) const;
};

struct GridStats {
  double meanRefsPerCell = 0;
  std::uint32_t maxRefsPerCell = 0;
  std::uint64_t emptyCells = 0;
  std::uint64_t intersections = 0, ends = 0, corners = 0;
};
GridStats gridStats(const GrooveGrid& grid);

Result<GrooveGrid> buildGrooveGrid(const GrooveScene& scene, const GridSettings& settings);

// Removes every special-case record (recordStart all zero, no references): the grid of a material
// that line-samples everywhere (formats/scene.md, reads.specialCases). Returns how many there were.
std::size_t dropSpecialCases(GrooveGrid& grid);

}  // namespace bake::grooves
