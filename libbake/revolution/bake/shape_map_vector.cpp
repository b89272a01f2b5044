// Shape map from a vector profile (shape_map.h): exact signed distance at every texel centre, and
// coverage as the exact area of the solid in each texel.
// Distance: the map is cut into tiles; for a tile with centre C and half-diagonal k, every texel's
// nearest piece is among those with dist(C, piece) <= min_piece dist(C, piece) + 2k (triangle
// inequality), so each texel is measured against a short candidate list, exactly. The sign comes
// from a scanline per row: the parity crossings of all pieces (profile_geometry.h) sorted once.
// Coverage: signed-area rasterisation of the flattened contours (the accumulation scheme of font
// rasterisers such as font-rs): each edge deposits, per cell it crosses, the change of the area to
// its right; a prefix sum along the row gives the winding-number integral over each texel, which
// is the area fraction because validation oriented the contours by nesting.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bake/revolution/shape_map.h"
#include "core/parallel.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {
namespace {

constexpr int kTile = 8;

struct Piece {
  const Segment* segment;
};

double distanceTo(const Segment& s, Point2 p) { return distanceToPiece(s, p).distance; }

// Integral of clamp(v, 0, 1) from 0 to s.
double rampIntegral(double s) {
  if (s <= 0) return 0;
  if (s <= 1) return 0.5 * s * s;
  return s - 0.5;
}

// One edge (grid units: x = r / texel, y = rows from hMin) into the per-row accumulators.
void depositEdge(double x0, double y0, double x1, double y1, int width, int height, std::vector<float>& acc) {
  if (y0 == y1) return;
  const double dir = y1 > y0 ? 1.0 : -1.0;
  if (y1 < y0) {
    std::swap(x0, x1);
    std::swap(y0, y1);
  }
  const double slope = (x1 - x0) / (y1 - y0);
  const int rowFirst = std::max(0, int(std::floor(y0)));
  const int rowLast = std::min(height - 1, int(std::ceil(y1)) - 1);
  for (int row = rowFirst; row <= rowLast; ++row) {
    const double ya = std::max(y0, double(row)), yb = std::min(y1, double(row + 1));
    if (yb <= ya) continue;
    const double xa = x0 + (ya - y0) * slope, xb = x0 + (yb - y0) * slope;
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    const double d = (yb - ya) * dir;
    // g(c): mean over the piece of the part of cell c right of it; 0 left of the piece, 1 right.
    auto g = [&](int c) {
      if (hi - lo < 1e-12) return std::clamp(c + 1 - lo, 0.0, 1.0);
      return (rampIntegral(c + 1 - lo) - rampIntegral(c + 1 - hi)) / (hi - lo);
    };
    float* line = acc.data() + std::size_t(row) * width;
    double previous = 0;
    const int cFirst = std::max(0, int(std::floor(lo)));
    const int cLast = int(std::ceil(hi));
    if (cFirst > 0 && cFirst - 1 < width) previous = g(cFirst - 1);
    for (int c = cFirst; c <= cLast && c < width; ++c) {
      const double value = g(c);
      line[c] += float(d * (value - previous));
      previous = value;
    }
  }
}

void rasteriseCoverage(const Profile& profile, const ShapeGrid& grid, std::vector<float>& coverage) {
  coverage.assign(std::size_t(grid.width) * grid.height, 0.0f);
  const double tolerance = 1e-4 * grid.texelSize;
  std::vector<Point2> points;
  for (const Contour& contour : profile.contours) {
    if (contour.segments.empty()) continue;
    points.clear();
    points.push_back(contour.segments.front().a);
    for (const Segment& s : contour.segments) flattenSegment(s, tolerance, points);
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const double x0 = points[k].r / grid.texelSize, y0 = (points[k].h - grid.hMin) / grid.texelSize;
      const double x1 = points[k + 1].r / grid.texelSize, y1 = (points[k + 1].h - grid.hMin) / grid.texelSize;
      depositEdge(x0, y0, x1, y1, grid.width, grid.height, coverage);
    }
  }
  for (int j = 0; j < grid.height; ++j) {
    float* line = coverage.data() + std::size_t(j) * grid.width;
    double sum = 0;
    for (int i = 0; i < grid.width; ++i) {
      sum += line[i];
      line[i] = float(std::min(1.0, std::abs(sum)));
    }
  }
}

void tileDistances(const std::vector<Piece>& pieces, const Profile& profile, const ShapeGrid& grid, int tileRow,
                   ShapeField& field) {
  const int j0 = tileRow * kTile, j1 = std::min(grid.height, j0 + kTile);
  // Inside/outside per texel from the sorted parity crossings of each row.
  std::vector<std::vector<double>> crossings(j1 - j0);
  for (int j = j0; j < j1; ++j) {
    auto& row = crossings[j - j0];
    for (const Contour& contour : profile.contours)
      for (const Segment& s : contour.segments) parityCrossings(s, grid.centreH(j), row);
    std::sort(row.begin(), row.end());
  }
  std::vector<std::size_t> firstRight(j1 - j0, 0);
  const double halfDiagonal = kTile * grid.texelSize * std::sqrt(0.5);
  std::vector<double> toCentre(pieces.size());
  std::vector<const Segment*> candidates;
  for (int i0 = 0; i0 < grid.width; i0 += kTile) {
    const int i1 = std::min(grid.width, i0 + kTile);
    const Point2 centre{i0 * grid.texelSize + 0.5 * kTile * grid.texelSize,
                        grid.hMin + (j0 + 0.5 * kTile) * grid.texelSize};
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      toCentre[k] = distanceTo(*pieces[k].segment, centre);
      nearest = std::min(nearest, toCentre[k]);
    }
    candidates.clear();
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (toCentre[k] <= nearest + 2 * halfDiagonal + 1e-12 * (1 + nearest)) candidates.push_back(pieces[k].segment);
    for (int j = j0; j < j1; ++j) {
      const auto& row = crossings[j - j0];
      std::size_t& right = firstRight[j - j0];
      for (int i = i0; i < i1; ++i) {
        const Point2 p{grid.centreR(i), grid.centreH(j)};
        while (right < row.size() && row[right] <= p.r) ++right;
        const bool inside = ((row.size() - right) & 1) != 0;
        double best = std::numeric_limits<double>::infinity();
        Point2 away;
        for (const Segment* s : candidates) {
          const PieceDistance d = distanceToPiece(*s, p);
          if (d.distance < best) {
            best = d.distance;
            away = d.away;
          }
        }
        const std::size_t at = std::size_t(j) * grid.width + i;
        const double dist = best;
        if (dist > 0) {
          const double sign = inside ? -1.0 : 1.0;
          field.distance[at] = float(sign * dist);
          field.gradR[at] = float(sign * away.r);
          field.gradH[at] = float(sign * away.h);
        } else {
          const DistanceSample sample = signedDistance(profile, p);  // on the surface: the normal
          field.distance[at] = 0.0f;
          field.gradR[at] = float(sample.gradR);
          field.gradH[at] = float(sample.gradH);
        }
      }
    }
  }
}

}  // namespace

ShapeGrid gridForBounds(const Bounds2& bounds, int resolution, int paddingTexels) {
  ShapeGrid grid;
  const double rExtent = std::max(bounds.rMax, 0.0);
  const double hExtent = std::max(bounds.hMax - bounds.hMin, 0.0);
  const int usable = std::max(1, resolution - 2 * paddingTexels);
  double texel = std::max(rExtent / std::max(1, resolution - paddingTexels), hExtent / usable);
  if (!(texel > 0)) texel = std::max({std::abs(bounds.rMax), std::abs(bounds.hMin), std::abs(bounds.hMax), 1.0}) / usable;
  grid.texelSize = texel;
  grid.width = std::clamp(int(std::ceil(rExtent / texel - 1e-9)) + paddingTexels, 1, std::max(1, resolution));
  grid.height = std::clamp(int(std::ceil(hExtent / texel - 1e-9)) + 2 * paddingTexels, 1, std::max(1, resolution));
  // Centre the h range in the rows.
  grid.hMin = 0.5 * (bounds.hMin + bounds.hMax) - 0.5 * grid.height * texel;
  return grid;
}

ShapeField distanceFromProfile(const Profile& profile, const ShapeGrid& grid) {
  ShapeField field;
  field.grid = grid;
  const std::size_t count = std::size_t(grid.width) * grid.height;
  field.distance.assign(count, 0.0f);
  field.gradR.assign(count, 0.0f);
  field.gradH.assign(count, 0.0f);
  std::vector<Piece> pieces;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments)
      if (!s.onAxis) pieces.push_back({&s});
  if (pieces.empty() || count == 0) {
    field.distance.assign(count, std::numeric_limits<float>::max());
    field.coverage.assign(count, 0.0f);
    return field;
  }
  const int tileRows = (grid.height + kTile - 1) / kTile;
  parallelFor(std::size_t(tileRows), 0, [&](std::size_t t) { tileDistances(pieces, profile, grid, int(t), field); }, 1);
  rasteriseCoverage(profile, grid, field.coverage);
  // Away from the surface the texel is wholly in or out: make that exact.
  const float farAway = float(grid.texelSize * std::sqrt(0.5) * (1 + 1e-6));
  for (std::size_t k = 0; k < count; ++k)
    if (std::abs(field.distance[k]) >= farAway) field.coverage[k] = field.distance[k] < 0 ? 1.0f : 0.0f;
  return field;
}

}  // namespace bake::revolution
