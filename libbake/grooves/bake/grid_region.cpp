// The region a primitive can touch, as a convex polygon, and the grid cells it meets (seed 000 §4.1:
// each cell lists the paths whose band, path ± wmax, overlaps it).
//
// A segment's region (formats/groove-scene.md, "Region") is the slab |b| <= wmax cut by its two
// joint lines: a convex quadrilateral whose corners are where the slab's edges meet the joint lines.
// At a corner the mitre line reaches wmax tan(turn / 2) along the path beyond the joint point on the
// outer side; for a near-reversal this grows without bound, so the reach is capped (reachCap).
// An arc's region is the annular sector r ± wmax between its joint lines; its polygon is the hull of
// a circumscribed polygon of the outer arc, the inner arc's ends, and, at a mitred joint, an octagon
// around the joint point of radius 2 wmax / cos(turn / 2) (the mitre line's reach inside the annulus:
// at most wmax / cos on the outer side, 2 wmax / cos on the inner side since r >= wmax).
// Cells are found row by row: the polygon's extent inside each row's strip gives the exact run of
// cells it meets, so a long diagonal line lists only the cells along it, not its bounding box.
#include <algorithm>
#include <cmath>
#include <functional>

#include "bake/core/vec.h"
#include "grooves/bake/grid_stages.h"

namespace bake::grooves::grid_detail {
namespace {
// Regions are inflated by this fraction of the half-width so that rounding never drops a cell.
constexpr double kInflate = 1e-7;

double cross3(Vec2 o, Vec2 a, Vec2 b) { return cross(sub(a, o), sub(b, o)); }

// Andrew's monotone chain; counter-clockwise, collinear points dropped.
std::vector<Vec2> convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && cross3(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lowerSize = k + 1; i-- > 0;) {
    while (k >= lowerSize && cross3(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

Polygon makePolygon(std::vector<Vec2> points) {
  Polygon polygon;
  polygon.points = convexHull(std::move(points));
  updateBounds(polygon);
  return polygon;
}

// Where the slab edge a + s t + side w n meets the joint line, as s; `limit` bounds the reach.
double slabMeetsJoint(Vec2 a, Vec2 t, Vec2 n, double side, double w, const JointLine& joint, double fallback,
                      double lower, double upper) {
  const double along = dot(t, joint.normal);
  if (std::abs(along) < 1e-12) return fallback;
  const double s = -(dot(sub(a, joint.point), joint.normal) + side * w * dot(n, joint.normal)) / along;
  return std::clamp(s, lower, upper);
}

Polygon segmentRegion(const Primitive& p, const PrimitiveJoints& joints, double w, double cap) {
  const Vec2 t = p.tangentAt(0), n = leftNormal(t);
  const double slack = kInflate * w;
  std::vector<Vec2> corners;
  for (const double side : {-1.0, 1.0}) {
    const double s0 = slabMeetsJoint(p.a, t, n, side, w, joints.start, -cap, -cap, p.length + cap) - slack;
    const double s1 = slabMeetsJoint(p.a, t, n, side, w, joints.end, p.length + cap, -cap, p.length + cap) + slack;
    corners.push_back(add(p.a, add(scaled(s0, t), scaled(side * w, n))));
    corners.push_back(add(p.a, add(scaled(s1, t), scaled(side * w, n))));
  }
  return makePolygon(std::move(corners));
}

// The cosine of half the turn at a joint: the angle between the joint normal and the tangent.
double halfTurnCosine(const JointLine& joint, Vec2 tangentInto) {
  return std::abs(dot(joint.normal, tangentInto));
}

void addMitreOctagon(std::vector<Vec2>& points, const JointLine& joint, Vec2 tangentInto, double w, double cap) {
  const double c = halfTurnCosine(joint, tangentInto);
  if (joint.openEnd || c > 1 - 1e-12) return;  // a flat cut or a G1 joint: the radial line itself
  const double reach = std::min(2 * w / std::max(c, 1e-12), cap) / std::cos(kPi / 8);
  for (int k = 0; k < 8; ++k) {
    const double angle = kPi / 4 * k;
    points.push_back(add(joint.point, {reach * std::cos(angle), reach * std::sin(angle)}));
  }
}

Polygon arcRegion(const Primitive& p, const PrimitiveJoints& joints, double w, double cap) {
  const double outer = (p.radius + w) * (1 + kInflate);
  const double inner = std::max(0.0, p.radius - w * (1 + kInflate));
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(p.sweep) / (kPi / 8))));
  const double step = p.sweep / pieces;
  const double circumscribed = outer / std::cos(std::abs(step) / 2);
  std::vector<Vec2> points;
  for (int k = 0; k <= pieces; ++k) {
    const double angle = p.startAngle + step * k;
    points.push_back(add(p.centre, {circumscribed * std::cos(angle), circumscribed * std::sin(angle)}));
  }
  for (const double angle : {p.startAngle, p.startAngle + p.sweep})
    points.push_back(add(p.centre, {inner * std::cos(angle), inner * std::sin(angle)}));
  addMitreOctagon(points, joints.start, p.tangentAt(0), w, cap);
  const Vec2 endTangent = p.tangentAt(1);
  addMitreOctagon(points, joints.end, {-endTangent.u, -endTangent.v}, w, cap);
  return makePolygon(std::move(points));
}

// The x extent of a convex polygon inside the strip lower <= y <= upper; false when it misses it.
bool extentInStrip(const Polygon& polygon, double lower, double upper, double& xmin, double& xmax) {
  xmin = INFINITY;
  xmax = -INFINITY;
  const std::size_t count = polygon.points.size();
  for (std::size_t k = 0; k < count; ++k) {
    Vec2 p = polygon.points[k], q = polygon.points[(k + 1) % count];
    if (p.v > q.v) std::swap(p, q);
    if (q.v < lower || p.v > upper) continue;
    const double dv = q.v - p.v;
    auto xAt = [&](double y) { return dv > 0 ? p.u + (q.u - p.u) * (y - p.v) / dv : p.u; };
    const double x0 = p.v >= lower ? p.u : xAt(lower), x1 = q.v <= upper ? q.u : xAt(upper);
    xmin = std::min({xmin, x0, x1});
    xmax = std::max({xmax, x0, x1});
  }
  return xmin <= xmax;
}

void addRun(const Lattice& lattice, std::int64_t row, std::int64_t first, std::int64_t last,
            std::vector<std::uint32_t>& cells) {
  if (lattice.wrap && last - first + 1 >= lattice.cells[0]) {
    first = 0;
    last = std::int64_t(lattice.cells[0]) - 1;
  }
  if (!lattice.wrap) {
    first = std::max<std::int64_t>(first, 0);
    last = std::min<std::int64_t>(last, std::int64_t(lattice.cells[0]) - 1);
  }
  if (first > last) return;
  // The row and the first column wrapped (or checked) once; the run then steps along the row.
  std::uint32_t cell = 0;
  if (!lattice.storedCell(first, row, cell)) return;
  const std::int64_t nx = lattice.cells[0];
  std::int64_t column = cell % nx;
  const std::uint32_t rowStart = cell - std::uint32_t(column);
  for (std::int64_t i = first; i <= last; ++i) {
    cells.push_back(rowStart + std::uint32_t(column));
    if (++column == nx) column = 0;  // only a wrapping run reaches the row's end before `last`
  }
}

// The rows to visit; false when a wrapping region spans the domain several times over (then every
// cell is listed, which is conservative and keeps the work bounded).
bool rowRange(const Lattice& lattice, double lower, double upper, std::int64_t& first, std::int64_t& last) {
  first = lattice.cellOf(lower, 1);
  last = lattice.cellOf(upper, 1);
  if (!lattice.wrap) {
    first = std::max<std::int64_t>(first, 0);
    last = std::min<std::int64_t>(last, std::int64_t(lattice.cells[1]) - 1);
    return true;
  }
  return last - first + 1 <= 3 * std::int64_t(lattice.cells[1]);
}

void addAllCells(const Lattice& lattice, std::vector<std::uint32_t>& cells) {
  const std::uint64_t count = std::uint64_t(lattice.cells[0]) * lattice.cells[1];
  for (std::uint64_t c = 0; c < count; ++c) cells.push_back(static_cast<std::uint32_t>(c));
}

void sortUnique(std::vector<std::uint32_t>& cells, std::size_t from) {
  // Rows come in order and each row's run ascends, so outside a wrapping domain the list is usually
  // sorted and unique already.
  const auto first = cells.begin() + std::ptrdiff_t(from);
  if (std::adjacent_find(first, cells.end(), std::greater_equal<std::uint32_t>()) == cells.end()) return;
  std::sort(cells.begin() + std::ptrdiff_t(from), cells.end());
  cells.erase(std::unique(cells.begin() + std::ptrdiff_t(from), cells.end()), cells.end());
}

}  // namespace

void updateBounds(Polygon& polygon) {
  polygon.lower = {INFINITY, INFINITY};
  polygon.upper = {-INFINITY, -INFINITY};
  for (const Vec2& p : polygon.points) {
    polygon.lower = {std::min(polygon.lower.u, p.u), std::min(polygon.lower.v, p.v)};
    polygon.upper = {std::max(polygon.upper.u, p.u), std::max(polygon.upper.v, p.v)};
  }
}

void intersect(const Polygon& a, const Polygon& b, Vec2 shift, Overlap& out) {
  Vec2 buffer[Overlap::kCapacity];
  Vec2* current = out.points;
  Vec2* next = buffer;
  int count = 0;
  for (const Vec2& p : a.points) current[count++] = p;
  const std::size_t edges = b.points.size();
  for (std::size_t k = 0; k < edges && count > 0; ++k) {
    const Vec2 e0 = add(b.points[k], shift), edge = sub(add(b.points[(k + 1) % edges], shift), e0);
    int kept = 0;
    for (int i = 0; i < count && kept + 2 <= Overlap::kCapacity; ++i) {
      const Vec2 p = current[i], q = current[(i + 1) % count];
      const double sp = cross(edge, sub(p, e0)), sq = cross(edge, sub(q, e0));
      if (sp >= 0) next[kept++] = p;
      if ((sp >= 0) != (sq >= 0)) next[kept++] = add(p, scaled(sp / (sp - sq), sub(q, p)));
    }
    std::swap(current, next);
    count = kept;
  }
  if (current != out.points) std::copy(current, current + count, out.points);
  out.count = count;
  out.lower = {INFINITY, INFINITY};
  out.upper = {-INFINITY, -INFINITY};
  for (int i = 0; i < count; ++i) {
    out.lower = {std::min(out.lower.u, out.points[i].u), std::min(out.lower.v, out.points[i].v)};
    out.upper = {std::max(out.upper.u, out.points[i].u), std::max(out.upper.v, out.points[i].v)};
  }
}

FloatBox FloatBox::of(const Polygon& polygon) {
  auto down = [](double x) { return std::nextafter(float(x), -INFINITY); };
  auto up = [](double x) { return std::nextafter(float(x), INFINITY); };
  if (polygon.empty()) return {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};  // meets nothing
  return {{down(polygon.lower.u), down(polygon.lower.v)}, {up(polygon.upper.u), up(polygon.upper.v)}};
}

double Overlap::area() const {
  // Relative to the first corner: absolute coordinates far from the origin would cancel.
  double twice = 0;
  for (int k = 1; k + 1 < count; ++k) twice += cross(sub(points[k], points[0]), sub(points[k + 1], points[0]));
  return 0.5 * twice;
}

Vec2 Overlap::centre() const {
  Vec2 sum;
  for (int k = 0; k < count; ++k) sum = add(sum, points[k]);
  return count ? scaled(1.0 / count, sum) : sum;
}

bool Overlap::contains(Vec2 x) const {
  for (int k = 0; k < count; ++k)
    if (cross(sub(points[(k + 1) % count], points[k]), sub(x, points[k])) < 0) return false;
  return count >= 3;
}

std::int64_t Lattice::cellOf(double x, int axis) const {
  const double base = axis == 0 ? origin.u : origin.v, size = axis == 0 ? cellSize.u : cellSize.v;
  const double index = std::floor((x - base) / size);
  constexpr double kLimit = 1e15;  // keeps huge or infinite reaches representable
  return static_cast<std::int64_t>(std::clamp(index, -kLimit, kLimit));
}

bool Lattice::storedCell(std::int64_t i, std::int64_t j, std::uint32_t& cell) const {
  const std::int64_t nx = cells[0], ny = cells[1];
  if (wrap) {
    i = ((i % nx) + nx) % nx;
    j = ((j % ny) + ny) % ny;
  } else if (i < 0 || j < 0 || i >= nx || j >= ny) {
    return false;
  }
  cell = static_cast<std::uint32_t>(j * nx + i);
  return true;
}

double reachCap(const GrooveScene& scene) { return std::max(scene.domain[0], scene.domain[1]) + scene.wmax; }

Polygon regionPolygon(const GrooveScene& scene, std::size_t index, double cap) {
  return regionPolygon(scene, index, cap, jointsOf(scene, index));
}

Polygon regionPolygon(const GrooveScene& scene, std::size_t index, double cap, const PrimitiveJoints& joints) {
  const Primitive& p = scene.primitives[index];
  const double w = scene.grooves[p.groove].wmax;
  return p.kind == Primitive::Kind::Segment ? segmentRegion(p, joints, w, cap) : arcRegion(p, joints, w, cap);
}

void cellsOfPolygon(const Lattice& lattice, const Polygon& polygon, std::vector<std::uint32_t>& cells) {
  if (polygon.empty()) return;
  const std::size_t from = cells.size();
  std::int64_t firstRow = 0, lastRow = 0;
  if (!rowRange(lattice, polygon.lower.v, polygon.upper.v, firstRow, lastRow)) return addAllCells(lattice, cells);
  for (std::int64_t row = firstRow; row <= lastRow; ++row) {
    const double y0 = lattice.origin.v + double(row) * lattice.cellSize.v;
    double xmin = 0, xmax = 0;
    if (!extentInStrip(polygon, y0, y0 + lattice.cellSize.v, xmin, xmax)) continue;
    addRun(lattice, row, lattice.cellOf(xmin, 0), lattice.cellOf(xmax, 0), cells);
  }
  sortUnique(cells, from);
}

void cellsOfBox(const Lattice& lattice, Vec2 lower, Vec2 upper, std::vector<std::uint32_t>& cells) {
  const std::size_t from = cells.size();
  std::int64_t firstRow = 0, lastRow = 0;
  if (!rowRange(lattice, lower.v, upper.v, firstRow, lastRow)) return addAllCells(lattice, cells);
  const std::int64_t first = lattice.cellOf(lower.u, 0), last = lattice.cellOf(upper.u, 0);
  for (std::int64_t row = firstRow; row <= lastRow; ++row) addRun(lattice, row, first, last, cells);
  sortUnique(cells, from);
}

}  // namespace bake::grooves::grid_detail
