// The texturing stages of revolbake. Seed 001 ("Texturing function") attaches the projection that
// suits the object to its shape map by hand; we measure the distortion of each candidate
// (projection.cpp) and record the choice, overridable with --projection. For the arc-length
// projection the runtime needs, at a hit, how far along the profile the nearest surface point lies:
// a second map over the shape map's grid holds that normalised arc length. The displacement map holds
// the derivatives of the user's height map (displacement.cpp).
#include <algorithm>
#include <cmath>

#include "bake/io/image.h"
#include "core/parallel.h"
#include "revolution/bake/bake_stages.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {
namespace {

// Arc length from a piece's start to a point on it.
double lengthAlong(const Segment& s, Point2 p) {
  if (!isArc(s)) return std::hypot(p.r - s.a.r, p.h - s.a.h);
  const ArcGeometry arc = arcGeometry(s);
  double turned = std::atan2(p.h - arc.centre.h, p.r - arc.centre.r) - arc.startAngle;
  // Bring the angle onto the side the arc sweeps.
  const double twoPi = 2 * M_PI;
  if (arc.sweep >= 0) {
    turned = std::fmod(std::fmod(turned, twoPi) + twoPi, twoPi);
  } else {
    turned = -std::fmod(std::fmod(-turned, twoPi) + twoPi, twoPi);
  }
  return arc.radius * std::abs(turned);
}

double pieceLength(const Segment& s) {
  if (!isArc(s)) return std::hypot(s.b.r - s.a.r, s.b.h - s.a.h);
  const ArcGeometry arc = arcGeometry(s);
  return arc.radius * std::abs(arc.sweep);
}

// The surface pieces with where each starts along the profile, bucketed by their bounding boxes in a
// uniform grid so that the pieces near a point are found without visiting them all.
class PieceIndex {
 public:
  struct Piece {
    const Segment* segment;
    double start;
  };

  PieceIndex(const Profile& profile, const ShapeGrid& grid) : grid_(grid) {
    for (const Contour& contour : profile.contours)
      for (const Segment& s : contour.segments) {
        if (s.onAxis) continue;
        pieces_.push_back({&s, total_});
        total_ += pieceLength(s);
      }
    // About one bucket per 8 x 8 texels.
    cell_ = 8 * grid.texelSize;
    columns_ = std::max(1, int(std::ceil(grid.width * grid.texelSize / cell_)) + 1);
    rows_ = std::max(1, int(std::ceil(grid.height * grid.texelSize / cell_)) + 1);
    buckets_.resize(std::size_t(columns_) * rows_);
    for (std::uint32_t k = 0; k < pieces_.size(); ++k) {
      Point2 lo, hi;
      segmentBox(*pieces_[k].segment, lo, hi);
      for (int j = row(lo.h); j <= row(hi.h); ++j)
        for (int i = column(lo.r); i <= column(hi.r); ++i) buckets_[std::size_t(j) * columns_ + i].push_back(k);
    }
  }

  double total() const { return total_; }
  bool empty() const { return pieces_.empty() || !(total_ > 0); }

  // Arc length at the point of the profile nearest to q: the pieces of q's bucket and its
  // neighbours first (q is a surface point, so the nearest piece is there), all pieces otherwise.
  double arcLengthNear(Point2 q) const {
    double best = 1e300, along = 0;
    auto consider = [&](const Piece& piece) {
      const Point2 c = closestPoint(*piece.segment, q);
      const double d2 = (c.r - q.r) * (c.r - q.r) + (c.h - q.h) * (c.h - q.h);
      if (d2 < best) {
        best = d2;
        along = piece.start + lengthAlong(*piece.segment, c);
      }
    };
    const int ci = column(q.r), cj = row(q.h);
    for (int j = std::max(0, cj - 1); j <= std::min(rows_ - 1, cj + 1); ++j)
      for (int i = std::max(0, ci - 1); i <= std::min(columns_ - 1, ci + 1); ++i)
        for (std::uint32_t k : buckets_[std::size_t(j) * columns_ + i]) consider(pieces_[k]);
    // Nothing within a bucket's reach (an image's distance can be off by a fraction of a texel; the
    // reach is 8 texels): look at every piece.
    if (best > cell_ * cell_)
      for (const Piece& piece : pieces_) consider(piece);
    return along;
  }

 private:
  int column(double r) const { return std::clamp(int(std::floor(r / cell_)), 0, columns_ - 1); }
  int row(double h) const { return std::clamp(int(std::floor((h - grid_.hMin) / cell_)), 0, rows_ - 1); }

  ShapeGrid grid_;
  std::vector<Piece> pieces_;
  double total_ = 0;
  double cell_ = 1;
  int columns_ = 1, rows_ = 1;
  std::vector<std::vector<std::uint32_t>> buckets_;
};

// Normalised arc length of the nearest surface point, per texel, as unorm16. The nearest surface
// point is the texel centre moved back along the unit gradient by the signed distance.
std::vector<std::uint8_t> arcLengthMap(const Profile& profile, const ShapeField& field, unsigned threads) {
  const ShapeGrid& grid = field.grid;
  const PieceIndex index(profile, grid);
  std::vector<std::uint8_t> bytes(std::size_t(grid.width) * grid.height * 2, 0);
  if (index.empty()) return bytes;
  parallelFor(std::size_t(grid.height), threads, [&](std::size_t j) {
    for (int i = 0; i < grid.width; ++i) {
      const std::size_t k = j * std::size_t(grid.width) + i;
      const double d = field.distance[k];
      const Point2 q{grid.centreR(i) - d * field.gradR[k], grid.centreH(int(j)) - d * field.gradH[k]};
      const double along = index.arcLengthNear(q);
      const auto value = std::uint16_t(std::lround(std::clamp(along / index.total(), 0.0, 1.0) * 65535.0));
      bytes[2 * k] = std::uint8_t(value & 0xff);
      bytes[2 * k + 1] = std::uint8_t(value >> 8);
    }
  }, 1);
  return bytes;
}

}  // namespace

void chooseTextureProjection(const Settings& settings, BakeState& state) {
  state.projection = chooseProjection(state.profile);
  if (settings.projection) state.projection.chosen = *settings.projection;
  const ProjectionScore& score = state.projection.scores[std::size_t(state.projection.chosen)];
  // Repeats: what the user asked for, else the recommended u:v ratio with v once.
  state.repeat[1] = settings.repeatV > 0 ? settings.repeatV : 1.0;
  state.repeat[0] = settings.repeatU > 0 ? settings.repeatU
                                         : std::max(1.0, std::round(score.repeatRatio * state.repeat[1]));
  if (state.projection.chosen == Projection::ArcLength)
    state.arcLengthMap = arcLengthMap(state.profile, state.field, settings.common.threads);
}

Status buildDisplacement(const Settings& settings, BakeState& state) {
  BAKE_ASSIGN_OR_RETURN(const Image image, readImage(settings.heightMap));
  if (image.width < 2 || image.height < 2) return invalidInput("a height map needs at least 2 x 2 pixels", {settings.heightMap, ""});
  HeightMap height;
  height.width = image.width;
  height.height = image.height;
  height.height01.resize(std::size_t(image.width) * image.height);
  const int colours = (image.channels == 2 || image.channels == 4) ? image.channels - 1 : image.channels;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      float value = 0;
      for (int c = 0; c < colours; ++c) value += image.at(x, y, c);
      value /= float(colours);
      if (!std::isfinite(value))
        return invalidInput("height is not finite", {settings.heightMap, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"});
      // v runs up the object like the shape map's h; image rows run down.
      height.height01[std::size_t(image.height - 1 - y) * image.width + x] = value;
    }
  state.displacement = buildDisplacementMap(height, settings.heightScale);
  return {};
}

}  // namespace bake::revolution
