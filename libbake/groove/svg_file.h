// SVG files as groove input (svg_file.cpp; formats/groove-scene.md "Paths", `svgFile`): the centreline
// of every shape of a drawing (path, line, polyline, polygon, rect, circle, and ellipses that are
// circles) becomes a groove, placed in texture space by an origin and a scale.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "groove/scene.h"

namespace bake::groove {

// Where a drawing lands: the bottom-left corner of its viewBox (or of its width x height) at
// `origin`, one SVG user unit = `scale` texture units, y flipped so the drawing reads upright with
// v pointing up.
struct SvgPlacement {
  Vec2 origin{0, 0};
  double scale = 1;
};

// One list of pieces per subpath, in document order. Element transforms (matrix, translate, scale,
// rotate, skewX, skewY) apply; an arc under a transform that is not a similarity would become an
// ellipse and is refused. Errors name the file, the element (tag, line, id) and, through `where`,
// the scene's JSON pointer; I/O errors exit 2, bad content 3.
Result<std::vector<std::vector<PathPiece>>> readSvgFile(const std::filesystem::path& file, const SvgPlacement& placement,
                                                        const std::string& where);

}  // namespace bake::groove
