// Rasterizing a paintstroke (seed 002 reduced to the image plane; see paintstroke.h). The sampled
// centreline (spline.cpp) is a chain of short straight pieces. Each pixel whose centre projects onto a
// piece (extended a little past the piece's ends, so the outside of a bend leaves no gaps) gets the
// exact box-filtered ink of that piece's band (coverage.h): half-width = the radius interpolated at the
// projection, density = breadthwise opacity (centre -> edge, the seed's "breadthwise opacity") x the
// opacity along the length, times the optional stroke texture. The ends are round: a cap's pixels get
// the exact area of their part in the band's square end plus their part in the disc's half beyond it
// (pixel squares clipped by half-planes, areas of polygons and of polygon-disc intersections); a dot
// is a disc, and sharp turns get a round join. Pieces of one stroke merge by maximum, so the overlaps
// at their joints do not double the ink; this happens in a small buffer over the stroke's (unwrapped)
// bounding box, whose cells are then listed in row-major order, or, when periodic copies overlap,
// folded onto the image by summing, clamped to 1. Work per stroke: the pixels within radius + 1 of
// each piece, row span by row span.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "stroke/coverage.h"
#include "stroke/paintstroke.h"
#include "stroke/stroke_stages.h"

namespace bake::stroke {
namespace {

using detail::PixelFilter;
using detail::Sample;

constexpr std::size_t kMaxSamples = std::size_t(1) << 20;  // 0.5 M pixels of centreline at 0.5 px pieces
constexpr double kMaxBufferCells = double(1 << 22);
constexpr double kMinRadius = 1e-9;
constexpr double kSharpTurn = 0.5;  // radians: beyond this a joint gets a round join

struct Piece {
  double x0, y0, tx, ty, length;
  double r0, r1, arc0;
  double opacity0, opacity1;
  double before, after;  // how far past its start and end the piece's band reaches
  PixelFilter filter;
  std::array<float, 3> colour0, colour1;  // at its start and end
};

// A disc (a dot, or a round join at a sharp turn), or a round cap: the disc's half beyond an end of
// the stroke together with the band's square end, whose pixels get the exact area of their union.
struct Disc {
  double x, y, r, opacity, tx, ty, arc;  // (tx, ty): the direction of travel, for the texture
  std::array<float, 3> colour;
  bool cap = false;
  double ix = 0, iy = 0;  // a cap's direction into the stroke
  double band = 0;        // how far the band runs from a cap's centre (the stroke's length)
  // On a stroke too short for its caps to be apart, each cap adds the other's half beyond its end.
  double ox = 0, oy = 0, oix = 0, oiy = 0, orad = 0;
};

struct Cell {
  float alpha;
  std::int32_t source;  // the element (piece, then disc) that gave the alpha, for the colour ...
  float along;          // ... and where along it
};

struct Box {
  std::int64_t x0, y0, x1, y1;  // inclusive pixel indices
  bool empty() const { return x1 < x0 || y1 < y0; }
  double cells() const { return empty() ? 0 : double(x1 - x0 + 1) * double(y1 - y0 + 1); }
  void add(const Box& o) {
    x0 = std::min(x0, o.x0), y0 = std::min(y0, o.y0), x1 = std::max(x1, o.x1), y1 = std::max(y1, o.y1);
  }
};

constexpr Box kEmptyBox{std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max(),
                        std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::min()};

// Pixels whose centres (i + 0.5) lie in [lo, hi], clipped to [clipLo, clipHi].
std::pair<std::int64_t, std::int64_t> pixelRange(double lo, double hi, double clipLo, double clipHi) {
  lo = std::max(std::ceil(lo - 0.5), clipLo);
  hi = std::min(std::floor(hi - 0.5), clipHi);
  if (!(lo <= hi)) return {1, 0};
  return {std::int64_t(lo), std::int64_t(hi)};
}

// Everything one rasterization needs, built once per stroke.
struct Stroke {
  std::vector<Sample> samples;
  std::vector<Piece> pieces;
  std::vector<Disc> discs;
  double length = 0;
  double centreOpacity = 1, edgeOpacity = 1;
  const StrokeTexture* texture = nullptr;
};

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

std::array<float, 3> inkColour(const Sample& s) {
  return {float(s.colour[0]), float(s.colour[1]), float(s.colour[2])};
}

Stroke buildStroke(const Paintstroke& stroke, double dx, double dy, double maxRadius, const RasterOptions& options) {
  Stroke out;
  double piece = options.maxPieceLength;
  if (!(piece > 0) || !std::isfinite(piece)) piece = RasterOptions{}.maxPieceLength;
  piece = std::clamp(piece, 1e-3, 64.0);
  out.samples = detail::sampleCentreline(stroke, piece, options.maxDeviation, kMaxSamples);
  if (out.samples.size() < 2) return out;
  for (Sample& s : out.samples) {
    s.x -= dx, s.y -= dy;
    s.radius = std::min(s.radius, maxRadius);
  }
  out.length = out.samples.back().arc;
  out.centreOpacity = std::clamp(std::isfinite(stroke.centreOpacity) ? stroke.centreOpacity : 1.0, 0.0, 1.0);
  out.edgeOpacity = std::clamp(std::isfinite(stroke.edgeOpacity) ? stroke.edgeOpacity : 1.0, 0.0, 1.0);
  out.texture = stroke.texture;

  const auto& s = out.samples;
  out.pieces.reserve(s.size() - 1);
  int previous = -1;  // the last piece with a direction, for the joint margins
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const double ex = s[i + 1].x - s[i].x, ey = s[i + 1].y - s[i].y;
    const double len = std::hypot(ex, ey);
    if (!(len > 1e-12) || std::max(s[i].radius, s[i + 1].radius) < kMinRadius) continue;
    const PixelFilter filter(ey, -ex);
    // A pixel is drawn by the piece its centre projects onto; the first and last pieces reach a pixel
    // further, for the along-length filter of the butt ends (the caps are discs).
    Piece p{s[i].x, s[i].y, ex / len, ey / len, len, s[i].radius, s[i + 1].radius, s[i].arc,
            s[i].opacity, s[i + 1].opacity, 0, 0, filter, inkColour(s[i]), inkColour(s[i + 1])};
    if (previous >= 0 && out.pieces[previous].arc0 + out.pieces[previous].length >= p.arc0 - 1e-9) {
      // Joints: on the outside of a turn the two pieces' bands leave a wedge of width r x turn
      // between them, so each reaches past the joint by that much (and a little more for rounding).
      Piece& q = out.pieces[previous];
      const double chord = std::sqrt(std::max(0.0, 2 - 2 * (q.tx * p.tx + q.ty * p.ty)));  // ~ turn angle
      const double r = std::max(q.r1, p.r0);
      const double margin = 0.05 + r * std::min(1.1 * chord, kSharpTurn);
      q.after = margin;
      p.before = margin;
      if (chord > kSharpTurn && s[i].radius >= kMinRadius)
        out.discs.push_back({s[i].x, s[i].y, s[i].radius, s[i].opacity, p.tx, p.ty, s[i].arc, inkColour(s[i])});
    }
    out.pieces.push_back(p);
    previous = int(out.pieces.size()) - 1;
  }
  if (!out.pieces.empty()) {
    out.pieces.front().before = out.pieces.front().filter.halfWidth();
    out.pieces.back().after = out.pieces.back().filter.halfWidth();
  }
  if (out.pieces.empty()) {  // a dot
    if (s.front().radius >= kMinRadius)
      out.discs.push_back({s.front().x, s.front().y, s.front().radius, s.front().opacity, 1, 0, 0.0, inkColour(s.front())});
    return out;
  }
  // Round caps, drawn with the band's end; the first and last pieces leave them the end pixels.
  Piece& first = out.pieces.front();
  Piece& last = out.pieces.back();
  if (s.front().radius >= kMinRadius) {
    Disc cap{s.front().x, s.front().y, s.front().radius, s.front().opacity, first.tx, first.ty, 0.0, inkColour(s.front())};
    cap.cap = true, cap.ix = first.tx, cap.iy = first.ty, cap.band = out.length;
    out.discs.push_back(cap);
    first.before = -first.filter.halfWidth();
  }
  if (s.back().radius >= kMinRadius) {
    Disc cap{s.back().x, s.back().y, s.back().radius, s.back().opacity, last.tx, last.ty, out.length, inkColour(s.back())};
    cap.cap = true, cap.ix = -last.tx, cap.iy = -last.ty, cap.band = out.length;
    out.discs.push_back(cap);
    last.after = -last.filter.halfWidth();
  }
  if (out.discs.size() >= 2) {
    Disc& a = out.discs[out.discs.size() - 2];
    Disc& b = out.discs.back();
    if (a.cap && b.cap && out.length < a.r + b.r + 2) {
      a.ox = b.x, a.oy = b.y, a.oix = b.ix, a.oiy = b.iy, a.orad = b.r;
      b.ox = a.x, b.oy = a.y, b.oix = a.ix, b.oiy = a.iy, b.orad = a.r;
    }
  }
  return out;
}

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

// A dense buffer of cells over `box`, max-merging, which keeps the extent of each row's cells.
class Buffer {
 public:
  explicit Buffer(const Box& box) : box_(box), width_(box.x1 - box.x0 + 1),
      cells_(std::size_t(box.cells()), Cell{0.0f, 0, 0.0f}),
      rowLo_(std::size_t(box.y1 - box.y0 + 1), box.x1 + 1), rowHi_(std::size_t(box.y1 - box.y0 + 1), box.x0 - 1) {}
  const Box& box() const { return box_; }
  // Declares that row y may get cells in [x0, x1] (call before merging them).
  void touch(std::int64_t y, std::int64_t x0, std::int64_t x1) {
    const std::size_t j = std::size_t(y - box_.y0);
    rowLo_[j] = std::min(rowLo_[j], x0);
    rowHi_[j] = std::max(rowHi_[j], x1);
  }
  std::int64_t rowLo(std::int64_t y) const { return rowLo_[std::size_t(y - box_.y0)]; }
  std::int64_t rowHi(std::int64_t y) const { return rowHi_[std::size_t(y - box_.y0)]; }
  // On a tie (inside a solid stroke) the piece the pixel projects onto wins, for its colour.
  void merge(std::int64_t x, std::int64_t y, double alpha, std::int32_t source, double along, bool preferred) {
    Cell& c = cells_[std::size_t((y - box_.y0) * width_ + (x - box_.x0))];
    const float a = float(std::min(alpha, 1.0));
    if (a > c.alpha || (a == c.alpha && preferred)) c = {a, source, float(along)};
  }
  const Cell& at(std::int64_t x, std::int64_t y) const {
    return cells_[std::size_t((y - box_.y0) * width_ + (x - box_.x0))];
  }

 private:
  Box box_;
  std::int64_t width_;
  std::vector<Cell> cells_;
  std::vector<std::int64_t> rowLo_, rowHi_;
};

void drawPiece(const Stroke& st, std::int32_t index, const Box& clip, Buffer& buffer) {
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
double capInk(const Stroke& st, const Disc& cap, double px, double py) {
  const double rx = px - cap.x, ry = py - cap.y;
  const double s = rx * cap.ix + ry * cap.iy;  // along the stroke from the cap's centre
  const double nx = cap.iy, ny = -cap.ix;
  const double d = rx * nx + ry * ny;
  const double rho = std::sqrt(rx * rx + ry * ry);
  constexpr double kHalfDiagonal = 0.70710678118654757;
  if (s >= kHalfDiagonal) return 0;  // wholly in the band: the pieces draw it
  const double profile = discProfile(rho, cap.r, st.centreOpacity, st.edgeOpacity);
  if (s <= -kHalfDiagonal) return detail::discInPixel(px, py, cap.x, cap.y, cap.r) * profile;
  if (rho >= cap.r + kHalfDiagonal && std::abs(d) >= cap.r + kHalfDiagonal) return 0;
  const bool uniform = st.centreOpacity == st.edgeOpacity;
  if (uniform && rho + kHalfDiagonal <= cap.r) return st.centreOpacity;
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

void drawDisc(const Stroke& st, std::int32_t index, const Box& clip, Buffer& buffer) {
  const Disc& disc = st.discs[std::size_t(index) - st.pieces.size()];
  const Box box = discBox(disc, double(clip.x0), double(clip.y0), double(clip.x1), double(clip.y1));
  for (std::int64_t y = box.y0; y <= box.y1; ++y) {
    const double py = double(y) + 0.5;
    buffer.touch(y, box.x0, box.x1);
    for (std::int64_t x = box.x0; x <= box.x1; ++x) {
      const double px = double(x) + 0.5;
      double ink = disc.cap ? capInk(st, disc, px, py)
                            : detail::discInPixel(px, py, disc.x, disc.y, disc.r) *
                                  discProfile(std::hypot(px - disc.x, py - disc.y), disc.r, st.centreOpacity, st.edgeOpacity);
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

std::array<float, 3> cellColour(const Stroke& st, const Cell& c) {
  const std::size_t e = std::size_t(c.source);
  if (e >= st.pieces.size()) return st.discs[e - st.pieces.size()].colour;
  const Piece& p = st.pieces[e];
  return {p.colour0[0] + (p.colour1[0] - p.colour0[0]) * c.along, p.colour0[1] + (p.colour1[1] - p.colour0[1]) * c.along,
          p.colour0[2] + (p.colour1[2] - p.colour0[2]) * c.along};
}

std::int64_t wrapIndex(std::int64_t v, std::int64_t n) {
  const std::int64_t m = v % n;
  return m < 0 ? m + n : m;
}

// The first index of [lo, hi] (hi - lo < n) whose wrapped value is the smallest: where the row-major
// order of the wrapped pixels starts.
std::int64_t wrappedStart(std::int64_t lo, std::int64_t hi, std::int64_t n) {
  const std::int64_t next = lo + (n - wrapIndex(lo, n)) % n;  // the first index that wraps to 0
  return next <= hi ? next : lo;
}

}  // namespace

InkFootprint rasterize(const Paintstroke& stroke, int width, int height, bool wrap, const RasterOptions& options) {
  InkFootprint out;
  if (width <= 0 || height <= 0 || stroke.points.size() < 2) return out;
  // With wrap-around, move the stroke by whole periods next to the origin first (keeps precision for
  // strokes given at huge coordinates).
  double shiftX = 0, shiftY = 0;
  if (wrap) {
    const ControlPoint& first = stroke.points.front();
    shiftX = std::floor(first.x / width) * width;
    shiftY = std::floor(first.y / height) * height;
    if (!std::isfinite(shiftX) || !std::isfinite(shiftY)) shiftX = shiftY = 0;
  }
  // With wrap-around a radius beyond the image's size only covers the image again: it is limited to
  // that (which bounds the work).
  const double maxRadius = wrap ? double(std::max(width, height)) : std::numeric_limits<double>::infinity();
  const Stroke st = buildStroke(stroke, shiftX, shiftY, maxRadius, options);
  if (st.pieces.empty() && st.discs.empty()) return out;

  constexpr double kFar = 1e15;  // keeps the pixel indices of far-away pieces in range
  const double cx0 = wrap ? -kFar : 0, cy0 = wrap ? -kFar : 0;
  const double cx1 = wrap ? kFar : width - 1, cy1 = wrap ? kFar : height - 1;

  // Elements (pieces, then discs) in chunks whose bounding box fits the buffer; one chunk in practice.
  const std::size_t elements = st.pieces.size() + st.discs.size();
  auto elementBox = [&](std::size_t e) {
    return e < st.pieces.size() ? pieceBox(st.pieces[e], cx0, cy0, cx1, cy1)
                                : discBox(st.discs[e - st.pieces.size()], cx0, cy0, cx1, cy1);
  };
  std::vector<std::pair<std::size_t, Box>> chunks;  // (first element, box)
  for (std::size_t e = 0; e < elements; ++e) {
    const Box b = elementBox(e);
    if (b.empty()) continue;
    if (!chunks.empty()) {
      Box merged = chunks.back().second;
      merged.add(b);
      if (merged.cells() <= kMaxBufferCells) {
        chunks.back().second = merged;
        continue;
      }
    }
    chunks.push_back({e, b});
  }
  if (chunks.empty()) return out;

  // Draws a chunk's elements into a buffer over `band` (the chunk's box or a band of its rows).
  auto fill = [&](std::size_t chunk, const Box& band) {
    Buffer buffer(band);
    const std::size_t end = chunk + 1 < chunks.size() ? chunks[chunk + 1].first : elements;
    for (std::size_t e = chunks[chunk].first; e < end; ++e) {
      if (e < st.pieces.size()) drawPiece(st, std::int32_t(e), band, buffer);
      else drawDisc(st, std::int32_t(e), band, buffer);
    }
    return buffer;
  };

  const Box& first = chunks.front().second;
  const bool direct = chunks.size() == 1 &&
      (!wrap || (first.x1 - first.x0 < width && first.y1 - first.y0 < height));
  if (direct) {
    // No pixel is hit twice: list the cells in the wrapped row-major order, a row's cells from its
    // first wrapped column xs on, then those before it.
    const Buffer buffer = fill(0, chunks.front().second);
    const Box& b = buffer.box();
    const std::int64_t ys = wrap ? wrappedStart(b.y0, b.y1, height) : b.y0;
    const std::int64_t xs = wrap ? wrappedStart(b.x0, b.x1, width) : b.x0;
    const std::int64_t rows = b.y1 - b.y0 + 1;
    std::size_t capacity = 0;
    for (std::int64_t y = b.y0; y <= b.y1; ++y) capacity += std::size_t(std::max<std::int64_t>(0, buffer.rowHi(y) - buffer.rowLo(y) + 1));
    out.pixels.reserve(capacity);
    auto emitRun = [&](std::int64_t y, std::int32_t wy, std::int64_t from, std::int64_t to) {
      if (from > to) return;
      const std::int64_t base = from - (wrap ? wrapIndex(from, width) : from);
      for (std::int64_t x = from; x <= to; ++x) {
        const Cell& c = buffer.at(x, y);
        if (c.alpha > 0) out.pixels.push_back({std::int32_t(x - base), wy, c.alpha, cellColour(st, c)});
      }
    };
    for (std::int64_t j = 0; j < rows; ++j) {
      const std::int64_t y = ys + j > b.y1 ? ys + j - rows : ys + j;
      const std::int32_t wy = std::int32_t(wrap ? wrapIndex(y, height) : y);
      const std::int64_t lo = buffer.rowLo(y), hi = buffer.rowHi(y);
      emitRun(y, wy, std::max(lo, xs), hi);
      emitRun(y, wy, lo, std::min(hi, xs - 1));
    }
    return out;
  }

  // General case: periodic copies overlap, or the stroke needed several chunks. The cells are summed
  // per image pixel in a folded grid over the part of the image the stroke reaches.
  Box all = kEmptyBox;
  for (const auto& chunk : chunks) all.add(chunk.second);
  const std::int64_t fx0 = wrap ? wrapIndex(all.x0, width) : all.x0, fy0 = wrap ? wrapIndex(all.y0, height) : all.y0;
  const std::int64_t fw = std::min<std::int64_t>(all.x1 - all.x0 + 1, width);
  const std::int64_t fh = std::min<std::int64_t>(all.y1 - all.y0 + 1, height);
  std::vector<float> alpha(std::size_t(fw * fh), 0.0f);
  std::vector<std::array<float, 3>> colour(std::size_t(fw * fh), std::array<float, 3>{0, 0, 0});
  // The folded grid's cell of a pixel: its wrapped offset from (fx0, fy0).
  auto foldX = [&](std::int64_t x) { return wrap ? wrapIndex(wrapIndex(x, width) - fx0, width) : x - fx0; };
  auto foldY = [&](std::int64_t y) { return wrap ? wrapIndex(wrapIndex(y, height) - fy0, height) : y - fy0; };
  for (std::size_t chunk = 0; chunk < chunks.size(); ++chunk) {
    const Box& box = chunks[chunk].second;
    const std::int64_t rowsPerBand = std::max<std::int64_t>(1, std::int64_t(kMaxBufferCells / double(box.x1 - box.x0 + 1)));
    for (std::int64_t by = box.y0; by <= box.y1; by += rowsPerBand) {
      const Buffer buffer = fill(chunk, Box{box.x0, by, box.x1, std::min(box.y1, by + rowsPerBand - 1)});
      const Box& b = buffer.box();
      for (std::int64_t y = b.y0; y <= b.y1; ++y) {
        const std::int64_t row = foldY(y) * fw;
        for (std::int64_t x = buffer.rowLo(y); x <= buffer.rowHi(y); ++x) {
          const Cell& c = buffer.at(x, y);
          if (!(c.alpha > 0)) continue;
          const std::size_t k = std::size_t(row + foldX(x));
          alpha[k] += c.alpha;
          const std::array<float, 3> ink = cellColour(st, c);
          for (int ch = 0; ch < 3; ++ch) colour[k][ch] += c.alpha * ink[ch];
        }
      }
    }
  }
  // Row-major order of the image: folded rows (and columns) from the one that wraps to 0 on.
  const std::int64_t rowStart = wrap ? (fh == height ? wrapIndex(-fy0, height) : wrappedStart(fy0, fy0 + fh - 1, height) - fy0) : 0;
  const std::int64_t colStart = wrap ? (fw == width ? wrapIndex(-fx0, width) : wrappedStart(fx0, fx0 + fw - 1, width) - fx0) : 0;
  for (std::int64_t j = 0; j < fh; ++j) {
    const std::int64_t fy = (rowStart + j) % fh;
    const std::int32_t y = std::int32_t(wrap ? wrapIndex(fy0 + fy, height) : fy0 + fy);
    for (std::int64_t i = 0; i < fw; ++i) {
      const std::int64_t fx = (colStart + i) % fw;
      const std::size_t k = std::size_t(fy * fw + fx);
      if (!(alpha[k] > 0)) continue;
      std::array<float, 3> mean;
      for (int ch = 0; ch < 3; ++ch) mean[ch] = colour[k][ch] / alpha[k];
      out.pixels.push_back({std::int32_t(wrap ? wrapIndex(fx0 + fx, width) : fx0 + fx), y, std::min(alpha[k], 1.0f), mean});
    }
  }
  return out;
}

}  // namespace bake::stroke
