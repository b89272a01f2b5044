// bakeshape: writes a generated shape (mesh/shapes.h) as a glTF binary or Wavefront OBJ, so examples
// and tests need no external models.
#pragma once

#include <string>

#include "core/options.h"
#include "core/diagnostics.h"
#include "mesh/shapes.h"

namespace bake {

struct ShapeToolSettings {
  ShapeSettings shape;
  std::string output;  // .glb or .obj
  CommonOptions common;
};

Status runShapeTool(const ShapeToolSettings& settings, Diagnostics& diagnostics);

}  // namespace bake
