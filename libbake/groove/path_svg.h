// SVG 1.1 path data in texture units (path_svg.cpp; formats/groove-scene.md "Paths").
#pragma once

#include <string>
#include <vector>

#include "groove/scene.h"

namespace bake::groove {

// Each subpath (started by M/m) becomes one list of pieces. Elliptical arcs (rx != ry) are refused;
// errors name the command index and its (u, v) in the message, and are placed at `where`.
Result<std::vector<std::vector<PathPiece>>> parseSvgPath(const std::string& data, const std::string& source,
                                                         const std::string& where);

}  // namespace bake::groove
