// Rasterizing a paintstroke (seed 002 reduced to the image plane; see paintstroke.h). The sampled
// centreline (spline.cpp) is a chain of short straight pieces. Each pixel whose centre projects onto a
// piece (extended a little past the piece's ends, so the outside of a bend leaves no gaps) gets the
// exact box-filtered ink of that piece's band: half-width = the radius interpolated at the projection,
// density = breadthwise opacity (centre -> edge, section 4.3 of the seed) x the opacity along the
// length, times the along-length fraction of the pixel inside [0, length] near the two ends (butt
// ends), times the optional stroke texture. Round caps: a disc of the end radius at each end (and a
// round join at sharp turns) contributes its exact pixel area. Pieces of one stroke merge by maximum,
// so the overlaps at their joints do not double the ink; this happens in a small buffer over the
// stroke's (unwrapped) bounding box. With wrap-around the buffer's cells then fold onto the image by
// summing the periodic copies, clamped to 1. Work per stroke: the pixels within radius + 1 of each
// piece, each evaluated with a few multiplications (coverage.h).
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
constexpr std::int64_t kMaxBufferCells = std::int64_t(1) << 22;
constexpr double kMinRadius = 1e-9;
constexpr double kSharpTurn = 0.5;  // radians: beyond this a joint gets a round join

struct Piece {
  double x0, y0, tx, ty, length;
  double r0, r1, arc0;
  double opacity0, opacity1;
  double before, after;  // how far past its start and end the piece's band reaches
  PixelFilter filter;
  int sample;  // the centreline sample it starts at
};

struct Disc {
  double x, y, r, opacity, tx, ty, arc;
  int sample;
};

struct Cell {
  float alpha;
  std::int32_t source;  // >= 0: piece index; < 0: -(sample index + 1)
};

struct Box {
  std::int64_t x0, y0, x1, y1;  // inclusive pixel indices
  bool empty() const { return x1 < x0 || y1 < y0; }
  std::int64_t cells() const { return empty() ? 0 : (x1 - x0 + 1) * (y1 - y0 + 1); }
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

Stroke buildStroke(const Paintstroke& stroke, double dx, double dy, const RasterOptions& options) {
  Stroke out;
  double piece = options.maxPieceLength;
  if (!(piece > 0) || !std::isfinite(piece)) piece = 0.5;
  piece = std::clamp(piece, 1e-3, 64.0);
  out.samples = detail::sampleCentreline(stroke, piece, kMaxSamples);
  if (out.samples.size() < 2) return out;
  for (Sample& s : out.samples) s.x -= dx, s.y -= dy;
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
    Piece p{s[i].x, s[i].y, ex / len, ey / len, len, s[i].radius, s[i + 1].radius, s[i].arc,
            s[i].opacity, s[i + 1].opacity, 0.75, 0.75, PixelFilter(ey, -ex), int(i)};
    if (previous >= 0 && out.pieces[previous].arc0 + out.pieces[previous].length >= p.arc0 - 1e-9) {
      Piece& q = out.pieces[previous];
      const double turn = std::acos(std::clamp(q.tx * p.tx + q.ty * p.ty, -1.0, 1.0));
      const double r = std::max(q.r1, p.r0);
      const double margin = 0.75 + r * std::min(turn, kSharpTurn);
      q.after = std::max(q.after, margin);
      p.before = margin;
      if (turn > kSharpTurn && s[i].radius >= kMinRadius)
        out.discs.push_back({s[i].x, s[i].y, s[i].radius, s[i].opacity, p.tx, p.ty, s[i].arc, int(i)});
    }
    out.pieces.push_back(p);
    previous = int(out.pieces.size()) - 1;
  }
  // Round caps. The cap's tangent (for the texture's across coordinate) is its piece's.
  const double t0x = out.pieces.empty() ? 1 : out.pieces.front().tx, t0y = out.pieces.empty() ? 0 : out.pieces.front().ty;
  const double t1x = out.pieces.empty() ? 1 : out.pieces.back().tx, t1y = out.pieces.empty() ? 0 : out.pieces.back().ty;
  if (s.front().radius >= kMinRadius)
    out.discs.push_back({s.front().x, s.front().y, s.front().radius, s.front().opacity, t0x, t0y, 0.0, 0});
  if (s.back().radius >= kMinRadius && (out.length > 0 || s.front().radius < kMinRadius))
    out.discs.push_back({s.back().x, s.back().y, s.back().radius, s.back().opacity, t1x, t1y, out.length,
                         int(s.size() - 1)});
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
  const double reach = d.r + 0.75;
  const auto [x0, x1] = pixelRange(d.x - reach, d.x + reach, clipX0, clipX1);
  const auto [y0, y1] = pixelRange(d.y - reach, d.y + reach, clipY0, clipY1);
  return {x0, y0, x1, y1};
}

// A dense buffer of cells over `box`, max-merging.
class Buffer {
 public:
  explicit Buffer(const Box& box) : box_(box), width_(box.x1 - box.x0 + 1),
      cells_(std::size_t(box.cells()), Cell{0.0f, 0}) {}
  const Box& box() const { return box_; }
  // On a tie (inside a solid stroke) the piece the pixel projects onto wins, for its colour.
  void merge(std::int64_t x, std::int64_t y, double alpha, std::int32_t source, bool preferred) {
    Cell& c = cells_[std::size_t((y - box_.y0) * width_ + (x - box_.x0))];
    const float a = float(std::min(alpha, 1.0));
    if (a > c.alpha || (a == c.alpha && preferred)) c = {a, source};
  }
  const Cell& at(std::int64_t x, std::int64_t y) const {
    return cells_[std::size_t((y - box_.y0) * width_ + (x - box_.x0))];
  }

 private:
  Box box_;
  std::int64_t width_;
  std::vector<Cell> cells_;
};

void drawPiece(const Stroke& st, std::int32_t index, const Box& clip, Buffer& buffer) {
  const Piece& p = st.pieces[std::size_t(index)];
  const Box box = pieceBox(p, double(clip.x0), double(clip.y0), double(clip.x1), double(clip.y1));
  const double h = p.filter.halfWidth();
  const double invLength = 1 / p.length;
  for (std::int64_t y = box.y0; y <= box.y1; ++y) {
    const double dy = double(y) + 0.5 - p.y0;
    for (std::int64_t x = box.x0; x <= box.x1; ++x) {
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
      if (ink > 0) buffer.merge(x, y, ink, index, s >= 0 && s <= p.length);
    }
  }
}

void drawDisc(const Stroke& st, const Disc& disc, const Box& clip, Buffer& buffer) {
  const Box box = discBox(disc, double(clip.x0), double(clip.y0), double(clip.x1), double(clip.y1));
  for (std::int64_t y = box.y0; y <= box.y1; ++y) {
    const double py = double(y) + 0.5;
    for (std::int64_t x = box.x0; x <= box.x1; ++x) {
      const double px = double(x) + 0.5;
      const double area = detail::discInPixel(px, py, disc.x, disc.y, disc.r);
      if (!(area > 0)) continue;
      const double rho = std::hypot(px - disc.x, py - disc.y);
      double ink = area * disc.opacity * discProfile(rho, disc.r, st.centreOpacity, st.edgeOpacity);
      if (st.texture && ink > 0) {
        const double d = (px - disc.x) * disc.ty - (py - disc.y) * disc.tx;
        ink *= textureAlpha(*st.texture, st.length > 0 ? disc.arc / st.length : 0.5,
                            0.5 - 0.5 * std::clamp(d / disc.r, -1.0, 1.0));
      }
      if (ink > 0) buffer.merge(x, y, ink, -(disc.sample + 1), false);
    }
  }
}

std::array<float, 3> cellColour(const Stroke& st, std::int32_t source) {
  std::array<float, 3> c{};
  if (source < 0) {
    const Sample& s = st.samples[std::size_t(-source - 1)];
    for (int k = 0; k < 3; ++k) c[k] = float(s.colour[k]);
    return c;
  }
  // A piece's colour is the mean of its ends' (the piece is at most maxPieceLength long).
  const std::size_t i = std::size_t(st.pieces[std::size_t(source)].sample);
  for (int k = 0; k < 3; ++k) c[k] = float(0.5 * (st.samples[i].colour[k] + st.samples[i + 1].colour[k]));
  return c;
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

// A pixel's cell before folding: its wrapped position, its order of arrival, its ink and colour.
struct Entry {
  std::int64_t key;
  std::int64_t order;
  float alpha;
  std::array<float, 3> colour;
};

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
  const Stroke st = buildStroke(stroke, shiftX, shiftY, options);
  if (st.pieces.empty() && st.discs.empty()) return out;

  constexpr double kFar = 1e15;  // keeps the pixel indices of far-away pieces in range
  const double cx0 = wrap ? -kFar : 0, cy0 = wrap ? -kFar : 0;
  const double cx1 = wrap ? kFar : width - 1, cy1 = wrap ? kFar : height - 1;
  const Box clip{std::int64_t(cx0), std::int64_t(cy0), std::int64_t(cx1), std::int64_t(cy1)};

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

  auto fill = [&](std::size_t chunk) {
    Buffer buffer(chunks[chunk].second);
    const std::size_t end = chunk + 1 < chunks.size() ? chunks[chunk + 1].first : elements;
    for (std::size_t e = chunks[chunk].first; e < end; ++e) {
      if (e < st.pieces.size()) drawPiece(st, std::int32_t(e), clip, buffer);
      else drawDisc(st, st.discs[e - st.pieces.size()], clip, buffer);
    }
    return buffer;
  };

  const Box& first = chunks.front().second;
  const bool direct = chunks.size() == 1 &&
      (!wrap || (first.x1 - first.x0 < width && first.y1 - first.y0 < height));
  if (direct) {
    // No pixel is hit twice: list the cells in the wrapped row-major order.
    const Buffer buffer = fill(0);
    const Box& b = buffer.box();
    const std::int64_t ys = wrap ? wrappedStart(b.y0, b.y1, height) : b.y0;
    const std::int64_t xs = wrap ? wrappedStart(b.x0, b.x1, width) : b.x0;
    const std::int64_t rows = b.y1 - b.y0 + 1, cols = b.x1 - b.x0 + 1;
    for (std::int64_t j = 0; j < rows; ++j) {
      const std::int64_t y = ys + j > b.y1 ? ys + j - rows : ys + j;
      for (std::int64_t i = 0; i < cols; ++i) {
        const std::int64_t x = xs + i > b.x1 ? xs + i - cols : xs + i;
        const Cell& c = buffer.at(x, y);
        if (c.alpha > 0)
          out.pixels.push_back({std::int32_t(wrap ? wrapIndex(x, width) : x), std::int32_t(wrap ? wrapIndex(y, height) : y),
                                c.alpha, cellColour(st, c.source)});
      }
    }
    return out;
  }

  // General case: periodic copies overlap (or several chunks): sum the cells per wrapped pixel.
  std::vector<Entry> entries;
  for (std::size_t chunk = 0; chunk < chunks.size(); ++chunk) {
    const Buffer buffer = fill(chunk);
    const Box& b = buffer.box();
    for (std::int64_t y = b.y0; y <= b.y1; ++y)
      for (std::int64_t x = b.x0; x <= b.x1; ++x) {
        const Cell& c = buffer.at(x, y);
        if (c.alpha > 0) {
          const std::int64_t wx = wrap ? wrapIndex(x, width) : x, wy = wrap ? wrapIndex(y, height) : y;
          entries.push_back({wy * width + wx, std::int64_t(entries.size()), c.alpha, cellColour(st, c.source)});
        }
      }
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.key != b.key ? a.key < b.key : a.order < b.order; });
  for (std::size_t i = 0; i < entries.size();) {
    double alpha = 0;
    std::array<double, 3> colour{0, 0, 0};
    std::size_t j = i;
    for (; j < entries.size() && entries[j].key == entries[i].key; ++j) {
      alpha += entries[j].alpha;
      for (int k = 0; k < 3; ++k) colour[k] += double(entries[j].alpha) * entries[j].colour[k];
    }
    std::array<float, 3> mean{};
    for (int k = 0; k < 3; ++k) mean[k] = float(colour[k] / alpha);
    out.pixels.push_back({std::int32_t(entries[i].key % width), std::int32_t(entries[i].key / width),
                          float(std::min(alpha, 1.0)), mean});
    i = j;
  }
  return out;
}

}  // namespace bake::stroke
