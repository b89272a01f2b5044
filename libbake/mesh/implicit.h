// Polygonising implicit surfaces by marching tetrahedra (Bloomenthal 1988, "Polygonization of implicit
// surfaces"; Treece, Prager and Gee 1999): each grid cube is split into six tetrahedra around its main
// diagonal, so neighbouring cubes agree on shared faces and no ambiguous cases arise. Crossing points
// are shared through their grid edge, so the result is a welded, closed, consistently oriented mesh
// (outward normals = the field's gradient direction) whenever the surface stays inside the box.
#pragma once

#include <array>
#include <functional>

#include "bake/io/mesh.h"

namespace bake {

struct ImplicitGrid {
  std::array<double, 3> min{-1, -1, -1};
  std::array<double, 3> max{1, 1, 1};
  std::array<int, 3> cells{32, 32, 32};
};

// The surface f = 0 of a field negative inside. Normals are the normalised gradient (central
// differences); texture coordinates are not produced.
TriangleMesh polygonize(const std::function<double(double, double, double)>& field, const ImplicitGrid& grid);

}  // namespace bake
