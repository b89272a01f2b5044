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
// each piece, row span by row span. This file holds the last step; geometry.cpp lays the elements
// out and draw.cpp draws them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bake/stroke/paintstroke.h"
#include "stroke/stroke_stages.h"

namespace bake::stroke {
namespace {

using namespace detail;

constexpr double kMaxBufferCells = double(1 << 18);  // 3 MB: strokes up to ~700 px across in one

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

// The image the footprint is for.
struct Target {
  int width, height;
  bool wrap;
};

// Consecutive elements whose pixels fit one buffer: [first, end) over `box`.
struct Chunk {
  std::size_t first, end;
  Box box;
};

// Groups the elements (pieces, then discs) into chunks whose bounding box fits a buffer: one chunk
// unless the stroke is very long. Elements with no pixel in the image (without wrap) are left out.
std::vector<Chunk> planChunks(const Geometry& st, const Target& target) {
  constexpr double kFar = 1e15;  // keeps the pixel indices of far-away pieces in range
  const double cx0 = target.wrap ? -kFar : 0, cy0 = target.wrap ? -kFar : 0;
  const double cx1 = target.wrap ? kFar : target.width - 1, cy1 = target.wrap ? kFar : target.height - 1;
  const std::size_t elements = st.pieces.size() + st.discs.size();
  std::vector<Chunk> chunks;
  for (std::size_t e = 0; e < elements; ++e) {
    const Box b = e < st.pieces.size() ? pieceBox(st.pieces[e], cx0, cy0, cx1, cy1)
                                       : discBox(st.discs[e - st.pieces.size()], cx0, cy0, cx1, cy1);
    if (b.empty()) continue;
    if (!chunks.empty()) {
      Box merged = chunks.back().box;
      merged.add(b);
      if (merged.cells() <= kMaxBufferCells) {
        chunks.back().box = merged;
        chunks.back().end = e + 1;
        continue;
      }
    }
    chunks.push_back({e, e + 1, b});
  }
  return chunks;
}

// Draws a chunk's elements into a buffer over `band` (the chunk's box or a band of its rows).
Buffer fill(const Geometry& st, const Chunk& chunk, const Box& band) {
  Buffer buffer(band);
  for (std::size_t e = chunk.first; e < chunk.end; ++e) {
    if (e < st.pieces.size()) drawPiece(st, std::int32_t(e), band, buffer);
    else drawDisc(st, std::int32_t(e), band, buffer);
  }
  return buffer;
}

// One buffer no wider or taller than the image: no pixel is hit twice, so its cells are listed as they
// are, in the wrapped row-major order (rows from the one that wraps to 0, and in each row the cells
// from the first wrapped column xs on, then those before it).
void listCells(const Geometry& st, const Buffer& buffer, const Target& target, InkFootprint& out) {
  const Box& b = buffer.box();
  const std::int64_t ys = target.wrap ? wrappedStart(b.y0, b.y1, target.height) : b.y0;
  const std::int64_t xs = target.wrap ? wrappedStart(b.x0, b.x1, target.width) : b.x0;
  const std::int64_t rows = b.y1 - b.y0 + 1;
  std::size_t capacity = 0;
  for (std::int64_t y = b.y0; y <= b.y1; ++y)
    capacity += std::size_t(std::max<std::int64_t>(0, buffer.rowHi(y) - buffer.rowLo(y) + 1));
  out.pixels.reserve(capacity);
  auto run = [&](std::int64_t y, std::int32_t wy, std::int64_t from, std::int64_t to) {
    if (from > to) return;
    const std::int64_t base = from - (target.wrap ? wrapIndex(from, target.width) : from);
    for (std::int64_t x = from; x <= to; ++x) {
      const Cell& c = buffer.at(x, y);
      if (c.alpha > 0) out.pixels.push_back({std::int32_t(x - base), wy, c.alpha, cellColour(st, c)});
    }
  };
  for (std::int64_t j = 0; j < rows; ++j) {
    const std::int64_t y = ys + j > b.y1 ? ys + j - rows : ys + j;
    const std::int32_t wy = std::int32_t(target.wrap ? wrapIndex(y, target.height) : y);
    const std::int64_t lo = buffer.rowLo(y), hi = buffer.rowHi(y);
    run(y, wy, std::max(lo, xs), hi);
    run(y, wy, lo, std::min(hi, xs - 1));
  }
}

// The general case: periodic copies overlap, or the stroke needed several chunks. Each chunk is drawn
// in bands of rows that fit a buffer, and the cells are summed per image pixel in a grid folded over
// the part of the image the stroke reaches, then listed in row-major order, clamped to 1.
void foldCells(const Geometry& st, const std::vector<Chunk>& chunks, const Target& target, InkFootprint& out) {
  const std::int64_t width = target.width, height = target.height;
  const bool wrap = target.wrap;
  Box all = kEmptyBox;
  for (const Chunk& chunk : chunks) all.add(chunk.box);
  const std::int64_t fx0 = wrap ? wrapIndex(all.x0, width) : all.x0, fy0 = wrap ? wrapIndex(all.y0, height) : all.y0;
  const std::int64_t fw = std::min(all.x1 - all.x0 + 1, width), fh = std::min(all.y1 - all.y0 + 1, height);
  std::vector<float> alpha(std::size_t(fw * fh), 0.0f);
  std::vector<std::array<float, 3>> colour(std::size_t(fw * fh), std::array<float, 3>{0, 0, 0});
  // The folded grid's cell of a pixel: its wrapped offset from (fx0, fy0).
  auto foldX = [&](std::int64_t x) { return wrap ? wrapIndex(wrapIndex(x, width) - fx0, width) : x - fx0; };
  auto foldY = [&](std::int64_t y) { return wrap ? wrapIndex(wrapIndex(y, height) - fy0, height) : y - fy0; };
  for (const Chunk& chunk : chunks) {
    const Box& box = chunk.box;
    const std::int64_t rowsPerBand = std::max<std::int64_t>(1, std::int64_t(kMaxBufferCells / double(box.x1 - box.x0 + 1)));
    for (std::int64_t by = box.y0; by <= box.y1; by += rowsPerBand) {
      const Buffer buffer = fill(st, chunk, Box{box.x0, by, box.x1, std::min(box.y1, by + rowsPerBand - 1)});
      for (std::int64_t y = buffer.box().y0; y <= buffer.box().y1; ++y) {
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
  const std::int64_t rowStart = !wrap ? 0 : fh == height ? wrapIndex(-fy0, height) : wrappedStart(fy0, fy0 + fh - 1, height) - fy0;
  const std::int64_t colStart = !wrap ? 0 : fw == width ? wrapIndex(-fx0, width) : wrappedStart(fx0, fx0 + fw - 1, width) - fx0;
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
}

}  // namespace

InkFootprint rasterize(const Paintstroke& stroke, int width, int height, bool wrap, const RasterOptions& options) {
  InkFootprint out;
  if (width <= 0 || height <= 0 || stroke.points.size() < 2) return out;
  // With wrap-around, move the stroke by whole periods next to the origin first (keeps precision for
  // strokes given at huge coordinates), and limit the radius to the image's size: a larger one only
  // covers the image again (and would only cost time).
  double shiftX = 0, shiftY = 0;
  if (wrap) {
    const ControlPoint& first = stroke.points.front();
    shiftX = std::floor(first.x / width) * width;
    shiftY = std::floor(first.y / height) * height;
    if (!std::isfinite(shiftX) || !std::isfinite(shiftY)) shiftX = shiftY = 0;
  }
  const double maxRadius = wrap ? double(std::max(width, height)) : std::numeric_limits<double>::infinity();
  const Geometry st = buildGeometry(stroke, shiftX, shiftY, maxRadius, options);
  const Target target{width, height, wrap};
  const std::vector<Chunk> chunks = planChunks(st, target);
  if (chunks.empty()) return out;
  const Box& box = chunks.front().box;
  if (chunks.size() == 1 && (!wrap || (box.x1 - box.x0 < width && box.y1 - box.y0 < height)))
    listCells(st, fill(st, chunks.front(), box), target, out);
  else
    foldCells(st, chunks, target, out);
  return out;
}

}  // namespace bake::stroke
