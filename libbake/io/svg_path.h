// SVG 1.1 path data (svg_path.cpp), as groove scenes give it inline and as the drawings of
// svg_drawing.h hold it (formats/groove-scene.md "Paths", formats/revolution.md).
#pragma once

#include <string>
#include <vector>

#include "bake/core/status.h"
#include "io/planar_path.h"

namespace bake::svg {

using planar::PathPiece;
using planar::Vec2;

// Each subpath (started by M/m) becomes one list of pieces. Elliptical arcs (rx != ry) are refused;
// errors name the command index and its (u, v) in the message, and are placed at `where`.
Result<std::vector<std::vector<PathPiece>>> parsePathData(const std::string& data, const std::string& source,
                                                          const std::string& where);

}  // namespace bake::svg
