// Procedural images for the example scenes (colour textures and height maps), so examples need no
// image files from elsewhere. Every pattern tiles: u (x) wraps exactly, as the angle around a surface
// of revolution does, and so does v (y).
#pragma once

#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/image.h"

namespace bake {

std::vector<std::string> patternNames();

// glaze: RGB ceramic glaze running down over a cream body, with speckles;
// bands: RGB painted bands along v (pottery);
// hammered: grey height map of overlapping round dimples (hammered metal);
// knurl: grey height map of a diamond knurl.
Result<Image> makePattern(const std::string& name, int size);

}  // namespace bake
