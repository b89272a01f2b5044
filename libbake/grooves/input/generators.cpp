// Generators (formats/groove-scene.md "Generators"): tile grout lines and record spirals, expanded
// into plain grooves before flattening.
#include <numbers>

#include "grooves/input/generators.h"

namespace bake::grooves {

std::vector<std::vector<PathPiece>> tileGroutLines(Vec2 origin, Vec2 tile, int nx, int ny, bool running) {
  std::vector<std::vector<PathPiece>> lines;
  auto line = [&](Vec2 a, Vec2 b) {
    PathPiece piece;
    piece.kind = PathPiece::Kind::Line;
    piece.p[0] = a;
    piece.p[1] = b;
    lines.push_back({piece});
  };
  const double u1 = origin.u + nx * tile.u, v1 = origin.v + ny * tile.v;
  for (int j = 0; j <= ny; ++j) line({origin.u, origin.v + j * tile.v}, {u1, origin.v + j * tile.v});
  if (!running) {
    for (int i = 0; i <= nx; ++i) line({origin.u + i * tile.u, origin.v}, {origin.u + i * tile.u, v1});
    return lines;
  }
  // Running bond: the two borders run the full height; the joints inside are one short segment per
  // row, ending on the horizontal lines (T-junctions), shifted by half a tile on every other row.
  line({origin.u, origin.v}, {origin.u, v1});
  line({u1, origin.v}, {u1, v1});
  for (int j = 0; j < ny; ++j) {
    const double shift = (j % 2 == 1) ? 0.5 * tile.u : 0.0;
    const double va = origin.v + j * tile.v, vb = origin.v + (j + 1) * tile.v;
    for (int i = 0; i <= nx; ++i) {
      const double u = origin.u + shift + i * tile.u;
      if (u <= origin.u + 1e-12 * tile.u || u >= u1 - 1e-12 * tile.u) continue;
      line({u, va}, {u, vb});
    }
  }
  return lines;
}

PathPiece recordSpiral(Vec2 centre, double innerRadius, double outerRadius, double turns) {
  PathPiece piece;
  piece.kind = PathPiece::Kind::Spiral;
  piece.centre = centre;
  piece.radius = innerRadius;
  piece.pitch = (outerRadius - innerRadius) / turns;
  piece.sweep = 2 * std::numbers::pi * turns;
  piece.startAngle = 0;
  return piece;
}

}  // namespace bake::grooves
