// Shapes the project generates itself for examples and tests: closed surfaces of chosen genus as
// signed distance fields (Hart 1996, "Sphere tracing", for the torus field), polygonised by marching
// tetrahedra (mesh/implicit.h).
#pragma once

#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/mesh.h"

namespace bake {

struct ShapeSettings {
  std::string name = "pretzel";  // see shapeNames()
  int resolution = 64;           // grid cells along the longest side
};

std::vector<std::string> shapeNames();

// sphere: radius 1; torus: radii 1 and 0.4 (genus 1); pretzel: three tori of radii 0.8 and 0.3
// in a row, smoothly blended where they meet (genus 3); double-torus: two of them (genus 2).
// With a UV layout (TEXCOORD_0; seams and poles are split vertices): column, a capped cylinder of
// radius 0.35 from y = -1 to 1 whose UV spans its circumference and height; globe, a latitude-
// longitude sphere of radius 1.
Result<TriangleMesh> makeShape(const ShapeSettings& settings);

}  // namespace bake
