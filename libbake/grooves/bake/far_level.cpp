// Building the far level (far_level.h). Every primitive's centre line is cut into straight pieces
// (arcs into chords of at most 1/64 turn), wrapped into the domain when the scene repeats (clipped to
// it when not), and cut again at the far grid's lines; each piece adds its length times 2 wmax to its
// cell in its class. Prefix sums over both axes make the summed-area table.
#include "bake/core/vec.h"
#include "grooves/bake/far_level.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace bake::grooves {
namespace {

struct Piece {
  Vec2 a, b;
};

// The straight pieces of a primitive's centre line.
std::vector<Piece> centrePieces(const Primitive& p) {
  if (p.kind == Primitive::Kind::Segment) return {{p.a, p.b}};
  const int chords = std::max(1, int(std::ceil(std::abs(p.sweep) / (2 * kPi / 64))));
  std::vector<Piece> pieces;
  for (int k = 0; k < chords; ++k) pieces.push_back({p.pointAt(double(k) / chords), p.pointAt(double(k + 1) / chords)});
  return pieces;
}

using planar::lerp;

// The parameters in (0, 1) where the piece crosses the lines u = k * step (axis 0) or v = k * step.
void crossings(const Piece& piece, int axis, double step, std::vector<double>& out) {
  const double from = axis == 0 ? piece.a.u : piece.a.v, to = axis == 0 ? piece.b.u : piece.b.v;
  if (from == to || !(step > 0)) return;
  const double lo = std::min(from, to), hi = std::max(from, to);
  for (double k = std::floor(lo / step) + 1; k * step < hi; ++k) out.push_back((k * step - from) / (to - from));
}

// The piece cut at the lines u = k * U, v = k * V and each part moved into the domain (repeat), or
// clipped to the domain (no wrap).
void intoDomain(const Piece& piece, const GrooveScene& scene, std::vector<Piece>& out) {
  std::vector<double> cuts{0.0, 1.0};
  crossings(piece, 0, scene.domain[0], cuts);
  crossings(piece, 1, scene.domain[1], cuts);
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    Vec2 a = lerp(piece.a, piece.b, cuts[k]), b = lerp(piece.a, piece.b, cuts[k + 1]);
    const Vec2 middle = lerp(a, b, 0.5);
    const double copyU = std::floor(middle.u / scene.domain[0]), copyV = std::floor(middle.v / scene.domain[1]);
    if (scene.wrapRepeat) {
      a = {a.u - copyU * scene.domain[0], a.v - copyV * scene.domain[1]};
      b = {b.u - copyU * scene.domain[0], b.v - copyV * scene.domain[1]};
    } else if (copyU != 0 || copyV != 0) {
      continue;
    }
    out.push_back({a, b});
  }
}

double length(const Piece& p) { return std::hypot(p.b.u - p.a.u, p.b.v - p.a.v); }

// The class key of a piece: profile, material, direction bin (over a half turn for symmetric
// profiles, a whole turn otherwise).
using ClassKey = std::tuple<std::size_t, std::size_t, int>;

ClassKey keyOf(const GrooveScene& scene, const Primitive& p, const Piece& piece, int bins) {
  const Groove& g = scene.grooves[p.groove];
  const bool symmetric = scene.profiles[g.profile].symmetric;
  double angle = std::atan2(piece.b.v - piece.a.v, piece.b.u - piece.a.u);  // (-pi, pi]
  const double period = symmetric ? kPi : 2 * kPi;
  angle = std::fmod(angle + 2 * kPi, period);
  const int bin = std::min(bins - 1, int(angle / period * bins));
  return {g.profile, g.material, bin};
}

struct ClassSum {
  std::size_t index = 0;
  double area = 0;
  double doubled[2] = {0, 0};  // length-weighted (cos 2a, sin 2a): the mean axis of a symmetric class
  double single[2] = {0, 0};   // length-weighted tangent: the mean direction of an oriented class
  std::uint32_t representative = 0;
  bool representativeIsSegment = false;
};

}  // namespace

double FarLevel::bandArea(std::size_t c, Vec2 lower, Vec2 upper, bool wrapRepeat) const {
  if (empty() || !(upper.u > lower.u) || !(upper.v > lower.v)) return 0.0;
  const double* nodes = table.data() + c * nodesPerClass();
  const std::uint32_t columns = cells[0], rows = cells[1];
  // The table at a point in cell units inside [0, columns] x [0, rows], bilinear within the cell.
  auto inside = [&](double x, double y) {
    const std::uint32_t i = std::min(columns - 1, std::uint32_t(std::max(0.0, std::floor(x))));
    const std::uint32_t j = std::min(rows - 1, std::uint32_t(std::max(0.0, std::floor(y))));
    const double s = x - i, t = y - j;
    auto at = [&](std::uint32_t ii, std::uint32_t jj) { return nodes[std::size_t(jj) * (columns + 1) + ii]; };
    return (1 - s) * (1 - t) * at(i, j) + s * (1 - t) * at(i + 1, j) + (1 - s) * t * at(i, j + 1) + s * t * at(i + 1, j + 1);
  };
  // Below and left of a domain point; a repeating pattern adds whole periods.
  auto summed = [&](double u, double v) {
    double x = u / cellSize.u, y = v / cellSize.v;
    if (!wrapRepeat) return inside(std::clamp(x, 0.0, double(columns)), std::clamp(y, 0.0, double(rows)));
    const double qx = std::floor(x / columns), qy = std::floor(y / rows);
    x -= qx * columns;
    y -= qy * rows;
    return qx * qy * inside(columns, rows) + qx * inside(columns, y) + qy * inside(x, rows) + inside(x, y);
  };
  return summed(upper.u, upper.v) - summed(lower.u, upper.v) - summed(upper.u, lower.v) + summed(lower.u, lower.v);
}

FarLevel buildFarLevel(const GrooveScene& scene, const std::uint32_t maxCells[2]) {
  FarLevel far;
  far.cells[0] = far.cells[1] = 1;  // a scene without grooves: one cell, no class
  far.cellSize = {scene.domain[0], scene.domain[1]};
  if (scene.primitives.empty()) return far;
  // Straight pieces in the domain, with their primitive.
  std::vector<std::pair<std::uint32_t, Piece>> pieces;
  for (std::uint32_t p = 0; p < scene.primitives.size(); ++p) {
    std::vector<Piece> inDomain;
    for (const Piece& piece : centrePieces(scene.primitives[p])) intoDomain(piece, scene, inDomain);
    for (const Piece& piece : inDomain)
      if (length(piece) > 0) pieces.push_back({p, piece});
  }
  // Classes: the finest direction bins that keep at most kMaxFarClasses (then the first ones).
  std::map<ClassKey, ClassSum> sums;
  int bins = kFarDirectionBins;
  for (;; bins /= 2) {
    sums.clear();
    for (const auto& [p, piece] : pieces) sums[keyOf(scene, scene.primitives[p], piece, bins)];
    if (sums.size() <= kMaxFarClasses || bins == 1) break;
  }
  std::size_t next = 0;
  for (auto& [key, sum] : sums) sum.index = next++;
  const std::size_t classCount = std::min(sums.size(), kMaxFarClasses);

  // The grid: the groove grid's cells, halved until the table fits.
  std::uint32_t columns = std::max<std::uint32_t>(1, maxCells[0]), rows = std::max<std::uint32_t>(1, maxCells[1]);
  while (std::uint64_t(columns + 1) * (rows + 1) * classCount > kMaxFarTableEntries && (columns > 1 || rows > 1)) {
    columns = std::max<std::uint32_t>(1, columns / 2);
    rows = std::max<std::uint32_t>(1, rows / 2);
  }
  far.cells[0] = columns;
  far.cells[1] = rows;
  far.cellSize = {scene.domain[0] / columns, scene.domain[1] / rows};
  std::vector<double> area(classCount * columns * rows, 0.0);

  for (const auto& [p, piece] : pieces) {
    const Primitive& primitive = scene.primitives[p];
    ClassSum& sum = sums[keyOf(scene, primitive, piece, bins)];
    if (sum.index >= classCount) continue;
    const double width = 2 * scene.profiles[scene.grooves[primitive.groove].profile].wmax;
    const double l = length(piece), angle = std::atan2(piece.b.v - piece.a.v, piece.b.u - piece.a.u);
    sum.doubled[0] += l * std::cos(2 * angle);
    sum.doubled[1] += l * std::sin(2 * angle);
    sum.single[0] += l * std::cos(angle);
    sum.single[1] += l * std::sin(angle);
    const bool segment = primitive.kind == Primitive::Kind::Segment;
    if (sum.area == 0 || (segment && !sum.representativeIsSegment)) {
      sum.representative = p;
      sum.representativeIsSegment = segment;
    }
    sum.area += l * width;
    std::vector<double> cuts{0.0, 1.0};
    crossings(piece, 0, far.cellSize.u, cuts);
    crossings(piece, 1, far.cellSize.v, cuts);
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const Vec2 middle = lerp(piece.a, piece.b, 0.5 * (cuts[k] + cuts[k + 1]));
      const auto i = std::uint32_t(std::clamp(std::floor(middle.u / far.cellSize.u), 0.0, double(columns - 1)));
      const auto j = std::uint32_t(std::clamp(std::floor(middle.v / far.cellSize.v), 0.0, double(rows - 1)));
      area[(sum.index * rows + j) * columns + i] += (cuts[k + 1] - cuts[k]) * l * width;
    }
  }

  far.classes.resize(classCount);
  for (const auto& [key, sum] : sums) {
    if (sum.index >= classCount) continue;
    FarClass& c = far.classes[sum.index];
    c.profile = std::uint32_t(std::get<0>(key));
    c.material = std::uint32_t(std::get<1>(key));
    c.representative = sum.representative;
    c.halfWidth = scene.profiles[c.profile].wmax;
    const bool symmetric = scene.profiles[c.profile].symmetric;
    const double angle = symmetric ? 0.5 * std::atan2(sum.doubled[1], sum.doubled[0]) : std::atan2(sum.single[1], sum.single[0]);
    c.direction = {std::cos(angle), std::sin(angle)};
  }
  // Summed-area tables: node (i, j) holds the cells (< i, < j).
  far.table.assign(classCount * far.nodesPerClass(), 0.0);
  for (std::size_t c = 0; c < classCount; ++c) {
    double* nodes = far.table.data() + c * far.nodesPerClass();
    for (std::uint32_t j = 0; j < rows; ++j) {
      double row = 0;
      for (std::uint32_t i = 0; i < columns; ++i) {
        row += area[(c * rows + j) * columns + i];
        nodes[std::size_t(j + 1) * (columns + 1) + i + 1] = nodes[std::size_t(j) * (columns + 1) + i + 1] + row;
      }
    }
  }
  return far;
}

}  // namespace bake::grooves
