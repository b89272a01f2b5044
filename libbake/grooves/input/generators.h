// Generators of grooves (generators.cpp; formats/groove-scene.md "Generators").
#pragma once

#include <vector>

#include "grooves/input/scene.h"

namespace bake::grooves {

// The grout lines of an nx x ny grid of tiles from `origin`, one path per line. Stack bond: full
// lines both ways. Running bond: every other row shifted by half a tile, its joints short segments
// ending on the horizontal lines (T-junctions).
std::vector<std::vector<PathPiece>> tileGroutLines(Vec2 origin, Vec2 tile, int nx, int ny, bool running);

// One Archimedean spiral from innerRadius to outerRadius in `turns` turns (pitch (r1 - r0) / turns).
PathPiece recordSpiral(Vec2 centre, double innerRadius, double outerRadius, double turns);

}  // namespace bake::grooves
