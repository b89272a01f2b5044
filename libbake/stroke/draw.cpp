// Drawing one element of a paintstroke into the local buffer. A piece's pixels are found row by row
// (the span of each row inside the piece's rectangle, solved from the linear s and d of the pixel
// centre); each gets the exact box-filtered ink of the piece's band (coverage.h) at the radius and
// opacity interpolated where its centre projects, times the optional texture. Discs (dots, joins) get
// the exact area of the pixel inside them. A cap's pixel gets the exact area of its part in the band's
// square end (the pixel square clipped by the band's four half-planes) plus its part in the disc's half
// beyond the end (the square clipped by the end's half-plane, intersected with the disc), which is
// exact for a uniform breadthwise opacity; otherwise the band's part is filtered as on a piece.
#include <algorithm>
#include <cmath>

#include "bake/stroke/paintstroke.h"
#include "stroke/coverage.h"
#include "stroke/stroke_stages.h"

namespace bake::stroke::detail {
namespace {

// Pixels whose centres (i + 0.5) lie in [lo, hi], clipped to [clipLo, clipHi].
std::pair<std::int64_t, std::int64_t> pixelRange(double lo, double hi, double clipLo, double clipHi) {
  lo = std::max(std::ceil(lo - 0.5), clipLo);
  hi = std::min(std::floor(hi - 0.5), clipHi);
  if (!(lo <= hi)) return {1, 0};
  return {std::int64_t(lo), std::int64_t(hi)};
}

double textureAlpha(const StrokeTexture& t, double u, double v) {
  if (t.width <= 0 || t.height <= 0 || t.alpha.size() < std::size_t(t.width) * std::size_t(t.height)) return 1;
  const double fx = std::clamp(u, 0.0, 1.0) * t.width - 0.5, fy = std::clamp(v, 0.0, 1.0) * t.height - 0.5;
  const int x0 = std::clamp(int(std::floor(fx)), 0, t.width - 1), y0 = std::clamp(int(std::floor(fy)), 0, t.height - 1);
  const int x1 = std::min(x0 + 1, t.width - 1), y1 = std::min(y0 + 1, t.height - 1);
  const double wx = std::clamp(fx - x0, 0.0, 1.0), wy = std::clamp(fy - y0, 0.0, 1.0);
  auto at = [&](int x, int y) { return double(t.alpha[std::size_t(y) * t.width + x]); };
  const double top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * wx;
  const double bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * wx;
  return std::clamp(top + (bottom - top) * wy, 0.0, 1.0);
}

// The breadthwise opacity of a disc pixel at distance rho from its centre: the profile at rho for a
// disc larger than a pixel, its mean over the disc for one smaller (the pixel sees all of it).
double discProfile(double rho, double r, double centre, double edge) {
  const double sampled = centre + (edge - centre) * std::min(rho / r, 1.0);
  const double mean = centre + (edge - centre) * (2.0 / 3.0);
  const double w = std::clamp(r - 0.5, 0.0, 1.0);
  return mean + (sampled - mean) * w;
}

}  // namespace

Box pieceBox(const Piece& p, double clipX0, double clipY0, double clipX1, double clipY1) {
  const double reach = std::max(p.r0, p.r1) + p.filter.halfWidth();
  const double ax = p.x0 - p.tx * p.before, ay = p.y0 - p.ty * p.before;
  const double bx = p.x0 + p.tx * (p.length + p.after), by = p.y0 + p.ty * (p.length + p.after);
  const auto [x0, x1] = pixelRange(std::min(ax, bx) - reach, std::max(ax, bx) + reach, clipX0, clipX1);
  const auto [y0, y1] = pixelRange(std::min(ay, by) - reach, std::max(ay, by) + reach, clipY0, clipY1);
  return {x0, y0, x1, y1};
}

Box discBox(const Disc& d, double clipX0, double clipY0, double clipX1, double clipY1) {
  // A cap also draws the band's end: pixels up to a half-diagonal along and r + a half-diagonal across.
  const double reach = d.r + (d.cap ? 1.5 : 0.75);
  const auto [x0, x1] = pixelRange(d.x - reach, d.x + reach, clipX0, clipX1);
  const auto [y0, y1] = pixelRange(d.y - reach, d.y + reach, clipY0, clipY1);
  return {x0, y0, x1, y1};
}

void drawPiece(const Geometry& st, std::int32_t index, const Box& clip, Buffer& buffer) {
  const Piece& p = st.pieces[std::size_t(index)];
  const Box box = pieceBox(p, double(clip.x0), double(clip.y0), double(clip.x1), double(clip.y1));
  const double h = p.filter.halfWidth();
  const double invLength = 1 / p.length;
  const double reach = std::max(p.r0, p.r1) + h;
  for (std::int64_t y = box.y0; y <= box.y1; ++y) {
    const double dy = double(y) + 0.5 - p.y0;
    // The row's pixels inside the piece's rectangle: -before <= s <= length + after and |d| <= reach,
    // with s = dx tx + dy ty and d = dx ty - dy tx linear in dx.
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    auto limit = [&](double coef, double constant, double from, double to) {
      if (std::abs(coef) < 1e-12) {
        if (constant < from || constant > to) lo = 1, hi = 0;
        return;
      }
      const double a = (from - constant) / coef, b = (to - constant) / coef;
      lo = std::max(lo, std::min(a, b));
      hi = std::min(hi, std::max(a, b));
    };
    limit(p.tx, dy * p.ty, -p.before, p.length + p.after);
    limit(p.ty, -dy * p.tx, -reach, reach);
    if (!(lo <= hi)) continue;
    const auto [rx0, rx1] = pixelRange(p.x0 + lo, p.x0 + hi, double(box.x0), double(box.x1));
    if (rx0 > rx1) continue;
    buffer.touch(y, rx0, rx1);
    for (std::int64_t x = rx0; x <= rx1; ++x) {
      const double dx = double(x) + 0.5 - p.x0;
      const double s = dx * p.tx + dy * p.ty;
      if (s < -p.before || s > p.length + p.after) continue;
      const double d = dx * p.ty - dy * p.tx;  // offset to the left of the direction of travel
      const double u = std::clamp(s * invLength, 0.0, 1.0);
      const double r = p.r0 + (p.r1 - p.r0) * u;
      if (std::abs(d) >= r + h || r < kMinRadius) continue;
      double ink = p.filter.band(d, r, st.centreOpacity, st.edgeOpacity) * (p.opacity0 + (p.opacity1 - p.opacity0) * u);
      const double arc = p.arc0 + s;
      if (arc < h || arc > st.length - h) ink *= std::max(0.0, p.filter.cdf(st.length - arc) - p.filter.cdf(-arc));
      if (st.texture && ink > 0)
        ink *= textureAlpha(*st.texture, st.length > 0 ? arc / st.length : 0.5, 0.5 - 0.5 * d / r);
      if (ink > 0) buffer.merge(x, y, ink, index, u, s >= 0 && s <= p.length);
    }
  }
}

// The ink of a round cap in the pixel centred at (px, py), before the opacity along the stroke: the
// exact area of the pixel in the band's end plus that in the disc's half beyond the end, each with its
// breadthwise opacity (the band's part with uniform opacity is exact; otherwise filtered as a piece).
double capInk(const Geometry& st, const Disc& cap, double px, double py) {
  const double rx = px - cap.x, ry = py - cap.y;
  const double s = rx * cap.ix + ry * cap.iy;  // along the stroke from the cap's centre
  const double nx = cap.iy, ny = -cap.ix;
  const double d = rx * nx + ry * ny;
  const double rho = std::sqrt(rx * rx + ry * ry);
  if (s >= detail::kPixelHalfDiagonal) return 0;  // wholly in the band: the pieces draw it
  const double profile = discProfile(rho, cap.r, st.centreOpacity, st.edgeOpacity);
  if (s <= -detail::kPixelHalfDiagonal) return detail::discInPixel(px, py, cap.x, cap.y, cap.r) * profile;
  if (rho >= cap.r + detail::kPixelHalfDiagonal && std::abs(d) >= cap.r + detail::kPixelHalfDiagonal) return 0;
  const bool uniform = st.centreOpacity == st.edgeOpacity;
  if (uniform && rho + detail::kPixelHalfDiagonal <= cap.r) return st.centreOpacity;
  const detail::Polygon square = detail::pixelSquare(px, py);
  const double c = cap.x * cap.ix + cap.y * cap.iy, cn = cap.x * nx + cap.y * ny;
  double beyond = detail::discArea(detail::clip(square, cap.ix, cap.iy, c), cap.x, cap.y, cap.r);
  if (cap.orad > 0)
    beyond += detail::discArea(detail::clip(square, cap.oix, cap.oiy, cap.ox * cap.oix + cap.oy * cap.oiy), cap.ox, cap.oy, cap.orad);
  double band;
  if (uniform) {
    detail::Polygon b = detail::clip(square, -cap.ix, -cap.iy, -c);
    b = detail::clip(b, cap.ix, cap.iy, c + cap.band);
    b = detail::clip(b, nx, ny, cn + cap.r);
    b = detail::clip(b, -nx, -ny, -cn + cap.r);
    band = st.centreOpacity * detail::area(b);
  } else {
    const PixelFilter filter(nx, ny);
    band = filter.band(d, cap.r, st.centreOpacity, st.edgeOpacity) * std::max(0.0, filter.cdf(cap.band - s) - filter.cdf(-s));
  }
  return std::min(1.0, band + beyond * profile);
}

namespace {

// A dot's (or join's) area in the pixels of `box`, as discInPixel gives it, bit for bit: each pixel's
// area is the signed quadrant areas at its four corners added and subtracted, and neighbouring pixels
// share corners, so the quadrant areas are computed once per corner of the box (a dot a few pixels
// wide then costs about a quarter of the inverse sines). The corners live in per-thread storage: one
// DiscCoverage at a time per thread. A cap's pixels take capInk instead: it computes no corners.
class DiscCoverage {
 public:
  DiscCoverage(const Disc& disc, const Box& box) : disc_(disc), box_(box) {
    cornered_ = !disc.cap && disc.r > 0 && disc.r <= kMaxQuadrantRadius;
    if (!cornered_) return;
    columns_ = box.x1 - box.x0 + 2;
    const std::int64_t rows = box.y1 - box.y0 + 2;
    thread_local std::vector<double> storage;  // reused from disc to disc: no allocation per dot
    storage.resize(std::size_t(columns_ * rows));
    corner_ = storage.data();
    for (std::int64_t j = 0; j < rows; ++j)
      for (std::int64_t i = 0; i < columns_; ++i)
        corner_[std::size_t(j * columns_ + i)] =
            detail::discQuadrant(double(box.x0 + i) - disc.x, double(box.y0 + j) - disc.y, disc.r);
  }

  double operator()(std::int64_t x, std::int64_t y) const {
    const double px = double(x) + 0.5, py = double(y) + 0.5;
    if (!cornered_) return detail::discInPixel(px, py, disc_.x, disc_.y, disc_.r);
    const double dist = std::sqrt((px - disc_.x) * (px - disc_.x) + (py - disc_.y) * (py - disc_.y));
    if (dist >= disc_.r + detail::kPixelHalfDiagonal) return 0;
    if (dist + detail::kPixelHalfDiagonal <= disc_.r) return 1;
    const std::size_t k = std::size_t((y - box_.y0) * columns_ + (x - box_.x0));
    const double area = corner_[k + std::size_t(columns_) + 1] - corner_[k + std::size_t(columns_)] - corner_[k + 1] + corner_[k];
    return std::clamp(area, 0.0, 1.0);
  }

 private:
  static constexpr double kMaxQuadrantRadius = 64;  // discInPixel's limit for exact areas
  const Disc& disc_;
  Box box_;
  bool cornered_ = false;
  std::int64_t columns_ = 0;
  double* corner_ = nullptr;
};

}  // namespace

void drawDisc(const Geometry& st, std::int32_t index, const Box& clip, Buffer& buffer) {
  const Disc& disc = st.discs[std::size_t(index) - st.pieces.size()];
  const Box box = discBox(disc, double(clip.x0), double(clip.y0), double(clip.x1), double(clip.y1));
  if (box.x0 > box.x1 || box.y0 > box.y1) return;
  const DiscCoverage coverage(disc, box);
  for (std::int64_t y = box.y0; y <= box.y1; ++y) {
    const double py = double(y) + 0.5;
    buffer.touch(y, box.x0, box.x1);
    for (std::int64_t x = box.x0; x <= box.x1; ++x) {
      const double px = double(x) + 0.5;
      double ink = disc.cap ? capInk(st, disc, px, py)
                            : coverage(x, y) * discProfile(std::sqrt((px - disc.x) * (px - disc.x) + (py - disc.y) * (py - disc.y)),
                                                           disc.r, st.centreOpacity, st.edgeOpacity);
      if (!(ink > 0)) continue;
      ink *= disc.opacity;
      if (st.texture && ink > 0) {
        const double d = (px - disc.x) * disc.ty - (py - disc.y) * disc.tx;
        ink *= textureAlpha(*st.texture, st.length > 0 ? disc.arc / st.length : 0.5,
                            0.5 - 0.5 * std::clamp(d / disc.r, -1.0, 1.0));
      }
      if (ink > 0) buffer.merge(x, y, ink, index, 0, false);
    }
  }
}

std::array<float, 3> cellColour(const Geometry& st, const Cell& c) {
  const std::size_t e = std::size_t(c.source);
  if (e >= st.pieces.size()) return st.discs[e - st.pieces.size()].colour;
  const Piece& p = st.pieces[e];
  return {p.colour0[0] + (p.colour1[0] - p.colour0[0]) * c.along, p.colour0[1] + (p.colour1[1] - p.colour0[1]) * c.along,
          p.colour0[2] + (p.colour1[2] - p.colour0[2]) * c.along};
}

}  // namespace bake::stroke::detail
