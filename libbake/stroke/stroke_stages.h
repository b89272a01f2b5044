// The paintstroke rasterizer's stages (internal to libbake/stroke), in order: the centreline is sampled
// into short straight pieces (spline.cpp); the pieces, round caps and joins are laid out with their
// reach (geometry.cpp); each is drawn into a local buffer, a pixel getting the exact box-filtered ink of
// the piece's band or the cap's area (draw.cpp, with the filter and area formulas of coverage.h); and
// rasterize.cpp merges the elements by maximum, then lists or folds the cells into the image.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "bake/stroke/paintstroke.h"
#include "stroke/coverage.h"

namespace bake::stroke::detail {

// One vertex of the sampled centreline: position, radius (taper applied), arc length from the start,
// and the linearly interpolated ink parameters.
struct Sample {
  double x = 0, y = 0;
  double radius = 0;
  double arc = 0;
  double opacity = 1;
  std::array<double, 3> colour{0, 0, 0};
};

// Samples the centreline (spline.cpp): each Catmull-Rom segment is cut into equal parameter steps no
// longer than `maxPieceLength` and whose chords stray at most `maxDeviation` from the curve, the arc
// length accumulated, and the taper applied to the radius by arc length. Returns an empty list when
// the stroke has fewer than two points or a non-finite value, or when it would need more than
// `maxSamples` samples.
std::vector<Sample> sampleCentreline(const Paintstroke& stroke, double maxPieceLength, double maxDeviation,
                                     std::size_t maxSamples);

// The taper factor at arc length `arc` of a stroke `length` long (smoothstep over taper x length).
double taperFactor(double arc, double length, double taper);


constexpr std::size_t kMaxSamples = std::size_t(1) << 20;  // about 2 M pixels of centreline at 2 px pieces
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

// A buffer cell: the largest alpha any element gave the pixel.
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

// Everything one rasterization draws, built once per stroke: pieces first, then discs and caps; an
// element's index is its piece index, or the number of pieces + its disc index.
struct Geometry {
  std::vector<Sample> samples;
  std::vector<Piece> pieces;
  std::vector<Disc> discs;
  double length = 0;
  double centreOpacity = 1, edgeOpacity = 1;
  const StrokeTexture* texture = nullptr;
};

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

// Lays out the pieces, joins and caps of a stroke moved by (-dx, -dy), its radii limited to maxRadius
// (geometry.cpp). Empty when the stroke cannot be sampled.
Geometry buildGeometry(const Paintstroke& stroke, double dx, double dy, double maxRadius, const RasterOptions& options);

// The pixels an element may touch, clipped to the box [clipX0, clipX1] x [clipY0, clipY1] (draw.cpp).
Box pieceBox(const Piece& p, double clipX0, double clipY0, double clipX1, double clipY1);
Box discBox(const Disc& d, double clipX0, double clipY0, double clipX1, double clipY1);

// Draws element `index` into `buffer`, only its pixels inside `clip` (draw.cpp).
void drawPiece(const Geometry& st, std::int32_t index, const Box& clip, Buffer& buffer);
void drawDisc(const Geometry& st, std::int32_t index, const Box& clip, Buffer& buffer);

// The ink colour of a cell: its element's, at the place recorded with it (draw.cpp).
std::array<float, 3> cellColour(const Geometry& st, const Cell& c);

}  // namespace bake::stroke::detail
