// The texturing stages of revolbake. Seed 001 ("Texturing function") attaches the projection that
// suits the object to its shape map by hand; we measure the distortion of each candidate
// (projection.cpp) and record the choice, overridable with --projection. For the arc-length
// projection the runtime needs, at a hit, how far along the profile the nearest surface point lies:
// a second map over the shape map's grid holds that normalised arc length. The displacement map holds
// the derivatives of the user's height map (displacement.cpp).
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "io/image.h"
#include "revolution/bake_stages.h"
#include "revolution/profile_geometry.h"

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

// Normalised arc length of the nearest surface point, per texel, as unorm16.
std::vector<std::uint8_t> arcLengthMap(const Profile& profile, const ShapeGrid& grid, unsigned threads) {
  struct Piece {
    const Segment* segment;
    double start;
  };
  std::vector<Piece> pieces;
  double total = 0;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) {
      if (s.onAxis) continue;
      pieces.push_back({&s, total});
      total += pieceLength(s);
    }
  std::vector<std::uint8_t> bytes(std::size_t(grid.width) * grid.height * 2, 0);
  if (pieces.empty() || total <= 0) return bytes;
  parallelFor(std::size_t(grid.height), threads, [&](std::size_t j) {
    for (int i = 0; i < grid.width; ++i) {
      const Point2 p{grid.centreR(i), grid.centreH(int(j))};
      double best = 1e300, along = 0;
      for (const Piece& piece : pieces) {
        const Point2 q = closestPoint(*piece.segment, p);
        const double d2 = (q.r - p.r) * (q.r - p.r) + (q.h - p.h) * (q.h - p.h);
        if (d2 < best) {
          best = d2;
          along = piece.start + lengthAlong(*piece.segment, q);
        }
      }
      const auto value = std::uint16_t(std::lround(std::clamp(along / total, 0.0, 1.0) * 65535.0));
      const std::size_t at = (j * grid.width + i) * 2;
      bytes[at] = std::uint8_t(value & 0xff);
      bytes[at + 1] = std::uint8_t(value >> 8);
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
    state.arcLengthMap = arcLengthMap(state.profile, state.field.grid, settings.common.threads);
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
