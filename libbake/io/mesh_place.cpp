// A float holds about 7 significant digits: a 1 m object 10 km from the origin keeps millimetres, one
// 10,000 km away (1e7 m, a geospatial frame) keeps nothing below a metre. Storing positions relative
// to the mesh's centre, chosen in double, makes the rounding relative to the object's size instead.
#include "io/mesh_place.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bake {

Vec3d nearOriginFor(const std::vector<Vec3d>& vertices) {
  if (vertices.empty()) return {};
  Vec3d lower, upper;
  lower.fill(std::numeric_limits<double>::infinity());
  upper.fill(-std::numeric_limits<double>::infinity());
  for (const Vec3d& p : vertices) {
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], p[k]);
      upper[k] = std::max(upper[k], p[k]);
    }
  }
  Vec3d centre{};
  double diagonal2 = 0.0, farthest = 0.0;
  for (int k = 0; k < 3; ++k) {
    centre[k] = 0.5 * (lower[k] + upper[k]);
    diagonal2 += (upper[k] - lower[k]) * (upper[k] - lower[k]);
    farthest = std::max(farthest, std::abs(centre[k]));
  }
  // Near enough: coordinates at most about 1.5 diagonals, so rounding stays below 1e-7 of the size.
  if (!(farthest > std::sqrt(diagonal2))) return {};
  return centre;
}

void placeNearOrigin(const WorldPositions& world, TriangleMesh& mesh) {
  mesh.origin = nearOriginFor(world.vertices);
  if (mesh.origin == Vec3d{}) return;
  auto relative = [&](const Vec3d& p) {
    return Vec3f{float(p[0] - mesh.origin[0]), float(p[1] - mesh.origin[1]), float(p[2] - mesh.origin[2])};
  };
  for (std::size_t v = 0; v < mesh.positions.size() && v < world.vertices.size(); ++v)
    mesh.positions[v] = relative(world.vertices[v]);
  for (std::size_t n = 0; n < mesh.namedPoints.size() && n < world.namedPoints.size(); ++n)
    mesh.namedPoints[n].position = relative(world.namedPoints[n]);
}

}  // namespace bake
