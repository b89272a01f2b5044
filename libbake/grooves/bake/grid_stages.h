// Internal to the grid build (grid.cpp, grid_region.cpp, grid_records.cpp): the convex polygon that
// bounds a primitive's region (seed 000 §4.1: the path ± wmax, cut by the joint lines), the cells such
// a polygon meets, and the special-case records (§4.2).
#pragma once

#include <cstdint>
#include <vector>

#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"

namespace bake::grooves::grid_detail {

using planar::add;
using planar::cross;
using planar::dot;
using planar::leftNormal;
using planar::scaled;
using planar::sub;

// A convex polygon, counter-clockwise, that contains the region of one primitive.
struct Polygon {
  std::vector<Vec2> points;
  Vec2 lower, upper;  // bounding box
  bool empty() const { return points.size() < 3; }
};
void updateBounds(Polygon& polygon);
// The intersection of two convex polygons (the second moved by `shift`), by Sutherland-Hodgman
// clipping in fixed buffers: region polygons have at most 23 corners, so 64 always suffice.
struct Overlap {
  static constexpr int kCapacity = 64;
  Vec2 points[kCapacity];
  int count = 0;
  Vec2 lower, upper;
  double area() const;
  Vec2 centre() const;
  bool contains(Vec2 x) const;
};
void intersect(const Polygon& a, const Polygon& b, Vec2 shift, Overlap& out);

// The geometry of the grid shared by the stages.
struct Lattice {
  Vec2 origin, cellSize, domain;
  std::uint32_t cells[2] = {0, 0};
  bool wrap = false;
  // The unwrapped cell index of a coordinate along an axis.
  std::int64_t cellOf(double x, int axis) const;
  // The stored cell of an unwrapped index pair, or false when outside a non-wrapping grid.
  bool storedCell(std::int64_t i, std::int64_t j, std::uint32_t& cell) const;
};

// How far the mitre at a joint may reach beyond the joint point, bounded for near-reversals.
double reachCap(const GrooveScene& scene);

// The convex polygon holding primitive `index`'s region (grid_region.cpp).
Polygon regionPolygon(const GrooveScene& scene, std::size_t index, double cap);
// The same with the primitive's joints already found.
Polygon regionPolygon(const GrooveScene& scene, std::size_t index, double cap, const PrimitiveJoints& joints);

// Appends the stored cells that `polygon` meets (ascending, each once) to `cells` (grid_region.cpp).
void cellsOfPolygon(const Lattice& lattice, const Polygon& polygon, std::vector<std::uint32_t>& cells);
// Appends the stored cells that the box meets (ascending, each once).
void cellsOfBox(const Lattice& lattice, Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& cells);

// A region's bounding box rounded outwards to fp32: 16 bytes, so the boxes of 10^5 primitives stay in
// cache while the record search tests candidate pairs.
struct FloatBox {
  float lower[2], upper[2];
  static FloatBox of(const Polygon& polygon);
  bool meets(const FloatBox& other) const {
    return lower[0] <= other.upper[0] && other.lower[0] <= upper[0] && lower[1] <= other.upper[1] &&
           other.lower[1] <= upper[1];
  }
};

// The special-case records of the scene, in a fixed order: per primitive, its start end, its start
// corner, its intersections with later primitives, its end end (grid_records.cpp).
struct RecordInputs {
  const GrooveScene* scene = nullptr;
  const Lattice* lattice = nullptr;
  const std::vector<Polygon>* regions = nullptr;
  const std::vector<FloatBox>* boxes = nullptr;  // of the regions
  // A primitive CSR over `lattice` (any grid tiling the domain; the build passes a coarse one) and
  // per primitive the cells of that grid it meets.
  const std::vector<std::uint32_t>* cellStart = nullptr;
  const std::vector<std::uint32_t>* primitiveRefs = nullptr;
  const std::vector<std::uint32_t>* primitiveCellStart = nullptr;
  const std::vector<std::uint32_t>* primitiveCells = nullptr;
  double cap = 0;
  unsigned threads = 1;
};
std::vector<SpecialRecord> findRecords(const RecordInputs& inputs);

// buildGrooveGrid with the wall-clock seconds of its two stages, for the bake's report.
struct GridStageTimes {
  double cells = 0;    // cell size, region polygons, primitive CSR
  double records = 0;  // special-case records and their CSR
};
Result<GrooveGrid> buildGrooveGridTimed(const GrooveScene& scene, const GridSettings& settings, GridStageTimes& times);

}  // namespace bake::grooves::grid_detail
