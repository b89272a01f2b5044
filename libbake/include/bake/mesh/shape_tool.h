// bakeshape: writes a generated shape (mesh/shapes.h) as a glTF binary or Wavefront OBJ, so examples
// and tests need no external models.
#pragma once

#include <string>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/mesh/shapes.h"

namespace bake {

struct ShapeToolSettings {
  ShapeSettings shape;
  std::string output;  // .glb or .obj
  CommonOptions common;
};

Status runShapeTool(const ShapeToolSettings& settings, Diagnostics& diagnostics);

}  // namespace bake
