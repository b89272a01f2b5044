// Shape maps from images (shape_map.h).
// Binary images: the exact Euclidean distance transform of both phases (edt_binary.cpp), the surface
// put half a texel between inside and outside centres.
// Anti-aliased images: after Gustavson & Strand ("Anti-aliased Euclidean distance transform",
// Pattern Recognition Letters 2011): an edge texel's coverage a and the local edge direction give
// the offset of the edge from its centre (the area cut from a unit square by a line), hence the
// piece of edge line inside that texel. The nearest edge piece is then propagated between
// neighbours in raster sweeps (as in 8SSEDT), each texel measuring its exact distance to the pieces
// offered; pieces, unlike single edge points, keep texels a few texels out accurate. The edge
// direction is first the coverage gradient (Sobel weights with sqrt 2), then twice refined from the
// gradient of the resulting distance.
// The axis: the solid's mirror image across r = 0 is never nearer than the solid itself, so
// mirroring matters only for the coverage gradient in column 0 (its left neighbour is itself).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bake/revolution/shape_map.h"

namespace bake::revolution {
namespace {

bool insideAt(const CoverageImage& image, std::size_t k) { return image.coverage[k] >= 0.5f; }

// The image with exactly width * height coverages, each finite and in [0, 1] (NaN counts as empty).
CoverageImage sanitised(const CoverageImage& image) {
  CoverageImage clean = image;
  clean.width = std::max(0, image.width);
  clean.height = std::max(0, image.height);
  clean.coverage.resize(std::size_t(clean.width) * clean.height, 0.0f);
  for (float& c : clean.coverage) c = std::isfinite(c) ? std::clamp(c, 0.0f, 1.0f) : 0.0f;
  return clean;
}

ShapeField emptyField(const CoverageImage& image) {
  ShapeField field;
  field.grid = {image.width, image.height, image.texelSize, image.hMin};
  const std::size_t count = std::size_t(image.width) * image.height;
  field.distance.assign(count, 0.0f);
  field.gradR.assign(count, 0.0f);
  field.gradH.assign(count, 0.0f);
  field.coverage = image.coverage;
  field.coverage.resize(count, 0.0f);
  return field;
}

// Unit gradient of the stored distance by central differences (one-sided at the far edges,
// mirrored at the axis).
void gradientFromDistance(ShapeField& field) {
  const int w = field.grid.width, h = field.grid.height;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const int il = i == 0 ? 0 : i - 1, ir = std::min(w - 1, i + 1);
      const int jd = std::max(0, j - 1), ju = std::min(h - 1, j + 1);
      double gr = ir > il ? (field.at(ir, j) - field.at(il, j)) / (ir - il) : 0.0;
      if (i == 0) gr = (field.at(1 < w ? 1 : 0, j) - field.at(0, j)) * 0.5;  // mirror: d(-r) = d(r)
      const double gh = ju > jd ? (field.at(i, ju) - field.at(i, jd)) / (ju - jd) : 0.0;
      const double len = std::hypot(gr, gh);
      const std::size_t k = std::size_t(j) * w + i;
      field.gradR[k] = len > 0 ? float(gr / len) : 1.0f;
      field.gradH[k] = len > 0 ? float(gh / len) : 0.0f;
    }
}

}  // namespace

bool isBinary(const CoverageImage& image) {
  for (float a : image.coverage)
    if (a != 0.0f && a != 1.0f) return false;
  return true;
}

ShapeField distanceFromBinary(const CoverageImage& input) {
  const CoverageImage image = sanitised(input);
  ShapeField field = emptyField(image);
  const std::size_t count = field.distance.size();
  std::vector<std::uint8_t> inside(count);
  for (std::size_t k = 0; k < count; ++k) inside[k] = insideAt(image, k) ? 1 : 0;
  std::vector<std::uint32_t> toInside(count), toOutside(count);
  squaredEdtBinary(inside.data(), FeatureTexels::nonZero, image.width, image.height, toInside.data());
  squaredEdtBinary(inside.data(), FeatureTexels::zero, image.width, image.height, toOutside.data());
  // No texel of the other phase at all: the distance is unbounded; store a large finite value.
  const float far = float(2.0 * (image.width + image.height));
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t squared = inside[k] ? toOutside[k] : toInside[k];
    const float texels = squared == kNoFeature ? far : float(std::sqrt(double(squared)) - 0.5);
    field.distance[k] = float((inside[k] ? -texels : texels) * image.texelSize);
  }
  gradientFromDistance(field);
  return field;
}

namespace {

struct Vec {
  double x = 0, y = 0;
};

// Offset (in texels, along the unit normal n pointing into the solid) from a texel centre to a
// straight edge that covers the fraction a of the texel. With |nx| >= |ny| the covered area is a
// quadratic of the offset while the line cuts a corner (a < ny / (2 nx)) and linear while it crosses
// two opposite sides; inverting gives the offset. Positive: the centre is outside.
double edgeOffset(double a, Vec n) {
  double gx = std::abs(n.x), gy = std::abs(n.y);
  if (gx < gy) std::swap(gx, gy);
  if (gy < 1e-9) return 0.5 - a;
  const double corner = 0.5 * gy / gx;
  if (a < corner) return 0.5 * (gx + gy) - std::sqrt(2.0 * gx * gy * a);
  if (a < 1.0 - corner) return (0.5 - a) * gx;
  return -0.5 * (gx + gy) + std::sqrt(2.0 * gx * gy * (1.0 - a));
}

// The edge inside one edge texel: the line through `point` across `normal`, clipped to the texel.
struct EdgePiece {
  Vec a, b;
};

EdgePiece clipToTexel(int i, int j, Vec point, Vec normal) {
  const Vec t{-normal.y, normal.x};
  double lo = -1e30, hi = 1e30;
  auto clip = [&](double p, double d, double min, double max) {
    if (std::abs(d) < 1e-12) {
      if (p < min || p > max) lo = 1, hi = 0;
      return;
    }
    double u0 = (min - p) / d, u1 = (max - p) / d;
    if (u0 > u1) std::swap(u0, u1);
    lo = std::max(lo, u0);
    hi = std::min(hi, u1);
  };
  clip(point.x, t.x, i, i + 1.0);
  clip(point.y, t.y, j, j + 1.0);
  if (lo > hi) return {point, point};  // the line misses the texel (round-off): keep the point
  return {{point.x + lo * t.x, point.y + lo * t.y}, {point.x + hi * t.x, point.y + hi * t.y}};
}

Vec nearestOnPiece(const EdgePiece& e, double x, double y) {
  const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, len2 = dx * dx + dy * dy;
  const double u = len2 > 0 ? std::clamp(((x - e.a.x) * dx + (y - e.a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return {e.a.x + u * dx, e.a.y + u * dy};
}

struct Propagation {
  int width = 0, height = 0;
  std::vector<EdgePiece> pieces;  // per edge
  std::vector<int> nearest;       // per texel: index of the nearest edge piece known, -1 none
  std::vector<double> dist2;      // squared distance to it
};

void offer(Propagation& p, int i, int j, int ni, int nj) {
  if (ni < 0 || nj < 0 || ni >= p.width || nj >= p.height) return;
  const int edge = p.nearest[std::size_t(nj) * p.width + ni];
  if (edge < 0) return;
  const std::size_t to = std::size_t(j) * p.width + i;
  if (p.nearest[to] == edge) return;
  const Vec q = nearestOnPiece(p.pieces[edge], i + 0.5, j + 0.5);
  const double dx = i + 0.5 - q.x, dy = j + 0.5 - q.y;
  const double d2 = dx * dx + dy * dy;
  if (d2 < p.dist2[to]) {
    p.dist2[to] = d2;
    p.nearest[to] = edge;
  }
}

// Raster sweeps: bottom-up with the row below and left/right, then top-down with the row above.
void propagate(Propagation& p) {
  for (int pass = 0; pass < 2; ++pass) {
    for (int j = 0; j < p.height; ++j) {
      for (int i = 0; i < p.width; ++i) {
        offer(p, i, j, i - 1, j - 1);
        offer(p, i, j, i, j - 1);
        offer(p, i, j, i + 1, j - 1);
        offer(p, i, j, i - 1, j);
      }
      for (int i = p.width - 1; i >= 0; --i) offer(p, i, j, i + 1, j);
    }
    for (int j = p.height - 1; j >= 0; --j) {
      for (int i = p.width - 1; i >= 0; --i) {
        offer(p, i, j, i + 1, j + 1);
        offer(p, i, j, i, j + 1);
        offer(p, i, j, i - 1, j + 1);
        offer(p, i, j, i + 1, j);
      }
      for (int i = 0; i < p.width; ++i) offer(p, i, j, i - 1, j);
    }
  }
}

}  // namespace

ShapeField distanceFromCoverage(const CoverageImage& input) {
  const CoverageImage image = sanitised(input);
  ShapeField field = emptyField(image);
  const int w = image.width, h = image.height;
  if (w == 0 || h == 0) return field;
  auto a = [&](int i, int j) {
    if (i < 0) i = -i - 1;  // mirrored at the axis
    i = std::min(i, w - 1);
    j = std::clamp(j, 0, h - 1);
    return double(std::clamp(image.coverage[std::size_t(j) * w + i], 0.0f, 1.0f));
  };
  // Edge texels: fractional coverage, or a hard edge between a full and an empty texel.
  std::vector<std::size_t> edges;
  std::vector<Vec> normal(std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double c = a(i, j);
      bool edge = c > 0 && c < 1;
      // A full or empty texel is an edge only against a texel of exactly the other value (a hard
      // edge on the texel border); beside a fractional texel the edge lies in that one instead.
      for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        if (!edge && (j + dj >= 0 && j + dj < h && i + di < w)) edge = a(i + di, j + dj) == 1.0 - c;
      if (!edge) continue;
      const double s2 = std::sqrt(2.0);
      const double gx = (a(i + 1, j - 1) + s2 * a(i + 1, j) + a(i + 1, j + 1)) -
                        (a(i - 1, j - 1) + s2 * a(i - 1, j) + a(i - 1, j + 1));
      const double gy = (a(i - 1, j + 1) + s2 * a(i, j + 1) + a(i + 1, j + 1)) -
                        (a(i - 1, j - 1) + s2 * a(i, j - 1) + a(i + 1, j - 1));
      const double len = std::hypot(gx, gy);
      const std::size_t k = std::size_t(j) * w + i;
      normal[k] = len > 0 ? Vec{gx / len, gy / len} : Vec{0, 0};
      // A symmetric sliver (one texel thick) has no central gradient: take the first one-sided
      // difference that is not zero, so its edge lies on a texel side.
      if (len == 0) {
        const Vec sides[4] = {{0, a(i, j + 1) - c}, {0, c - a(i, j - 1)}, {a(i + 1, j) - c, 0}, {c - a(i - 1, j), 0}};
        for (const Vec& g : sides)
          if (g.x != 0 || g.y != 0) {
            normal[k] = {g.x > 0 ? 1.0 : g.x < 0 ? -1.0 : 0.0, g.y > 0 ? 1.0 : g.y < 0 ? -1.0 : 0.0};
            break;
          }
      }
      edges.push_back(k);
    }
  Propagation p;
  p.width = w;
  p.height = h;
  p.pieces.resize(edges.size());
  auto buildPieces = [&] {
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const std::size_t k = edges[e];
      const int i = int(k % w), j = int(k / w);
      const Vec n = normal[k];
      const double offset = edgeOffset(a(i, j), n);
      const Vec foot{i + 0.5 + offset * n.x, j + 0.5 + offset * n.y};
      p.pieces[e] = n.x == 0 && n.y == 0 ? EdgePiece{foot, foot} : clipToTexel(i, j, foot, n);
    }
  };
  // Refine the edge normals twice: the gradient of the distance to the edge pieces (central
  // differences at each edge texel) is smoother than the 3 x 3 coverage gradient. Near an edge the
  // nearest piece lies within two texels, so these rounds look only there.
  std::vector<int> edgeAt(std::size_t(w) * h, -1);
  for (std::size_t e = 0; e < edges.size(); ++e) edgeAt[edges[e]] = int(e);
  auto localDistance = [&](int i, int j) {
    if (i < 0) i = -i - 1;  // the distance is symmetric about the axis
    double best = std::numeric_limits<double>::infinity();
    for (int y = std::max(0, j - 2); y <= std::min(h - 1, j + 2); ++y)
      for (int x = std::max(0, i - 2); x <= std::min(w - 1, i + 2); ++x) {
        const int e = edgeAt[std::size_t(y) * w + x];
        if (e < 0) continue;
        const Vec q = nearestOnPiece(p.pieces[e], i + 0.5, j + 0.5);
        best = std::min(best, std::hypot(i + 0.5 - q.x, j + 0.5 - q.y));
      }
    return a(i, j) >= 0.5 ? -best : best;
  };
  std::vector<Vec> refined(edges.size());
  for (int round = 0; round < 2; ++round) {
    buildPieces();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const int i = int(edges[e] % w), j = int(edges[e] / w);
      const int ir = std::min(w - 1, i + 1), jd = std::max(0, j - 1), ju = std::min(h - 1, j + 1);
      const double gr = (localDistance(ir, j) - localDistance(i - 1, j)) / (ir - i + 1);
      const double gh = ju > jd ? (localDistance(i, ju) - localDistance(i, jd)) / (ju - jd) : 0.0;
      const double len = std::hypot(gr, gh);
      refined[e] = std::isfinite(len) && len > 0 ? Vec{-gr / len, -gh / len} : normal[edges[e]];
    }
    for (std::size_t e = 0; e < edges.size(); ++e) normal[edges[e]] = refined[e];
  }
  buildPieces();
  // Then every texel: the nearest piece, propagated from the edge texels.
  p.nearest.assign(std::size_t(w) * h, -1);
  p.dist2.assign(std::size_t(w) * h, std::numeric_limits<double>::infinity());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::size_t k = edges[e];
    const int i = int(k % w), j = int(k / w);
    const Vec q = nearestOnPiece(p.pieces[e], i + 0.5, j + 0.5);
    p.nearest[k] = int(e);
    p.dist2[k] = (i + 0.5 - q.x) * (i + 0.5 - q.x) + (j + 0.5 - q.y) * (j + 0.5 - q.y);
  }
  propagate(p);
  const double far = 2.0 * (w + h);  // no edge at all: unbounded, stored large and finite
  for (std::size_t k = 0; k < p.dist2.size(); ++k) {
    const bool inside = image.coverage[k] >= 0.5f;
    const double d = std::isfinite(p.dist2[k]) ? std::sqrt(p.dist2[k]) : far;
    field.distance[k] = float((inside ? -d : d) * image.texelSize);
  }
  // Gradient: from the nearest point of the nearest edge piece, pointing out of the solid.
  for (std::size_t k = 0; k < p.dist2.size(); ++k) {
    const int i = int(k % w), j = int(k / w);
    const bool inside = image.coverage[k] >= 0.5f;
    if (p.nearest[k] < 0) continue;
    const Vec q = nearestOnPiece(p.pieces[p.nearest[k]], i + 0.5, j + 0.5);
    const double dx = i + 0.5 - q.x, dy = j + 0.5 - q.y;
    const double len = std::hypot(dx, dy);
    if (len > 1e-9) {
      field.gradR[k] = float((inside ? -dx : dx) / len);
      field.gradH[k] = float((inside ? -dy : dy) / len);
    } else {
      field.gradR[k] = float(-normal[k].x);
      field.gradH[k] = float(-normal[k].y);
    }
  }
  return field;
}

}  // namespace bake::revolution
