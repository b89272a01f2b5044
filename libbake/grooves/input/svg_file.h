// SVG files as groove input (formats/groove-scene.md "Paths", `svgFile`): the centreline of every
// shape of a drawing (read by io/svg_drawing.h) becomes a groove, placed in texture space by an origin
// and a scale.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grooves/input/scene.h"

namespace bake::grooves {

// Where a drawing lands: the bottom-left corner of its viewBox (or of its width x height) at
// `origin`, one SVG user unit = `scale` texture units, y flipped so the drawing reads upright with
// v pointing up.
struct SvgPlacement {
  Vec2 origin{0, 0};
  double scale = 1;
};

// One list of pieces per subpath, in document order (see io/svg_drawing.h for what is followed and
// refused).
Result<std::vector<std::vector<PathPiece>>> readSvgFile(const std::filesystem::path& file, const SvgPlacement& placement,
                                                        const std::string& where);

}  // namespace bake::grooves
