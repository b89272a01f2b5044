// Signed distance fields of the generated shapes, blended with a polynomial smooth minimum (Quilez,
// "smooth minimum") so the rings of the pretzel join without creases.
#include "bake/mesh/shapes.h"

#include <algorithm>
#include <cmath>

#include "mesh/implicit.h"

namespace bake {
namespace {

double torusField(double x, double y, double z, double cx, double major, double minor) {
  const double ring = std::hypot(x - cx, y) - major;
  return std::hypot(ring, z) - minor;
}

double smoothMin(double a, double b, double k) {
  const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return b + (a - b) * h - k * h * (1.0 - h);
}

// `rings` tori of radii 0.8 / 0.3 whose centres are 1.6 apart, so neighbouring rings overlap.
double ringsField(double x, double y, double z, int rings) {
  const double spacing = 1.6, offset = -0.5 * spacing * (rings - 1);
  double value = torusField(x, y, z, offset, 0.8, 0.3);
  for (int r = 1; r < rings; ++r) value = smoothMin(value, torusField(x, y, z, offset + spacing * r, 0.8, 0.3), 0.15);
  return value;
}

ImplicitGrid gridAround(double halfX, double halfY, double halfZ, int resolution) {
  const double longest = std::max({halfX, halfY, halfZ});
  ImplicitGrid grid;
  grid.min = {-halfX, -halfY, -halfZ};
  grid.max = {halfX, halfY, halfZ};
  // Odd cell counts keep the symmetry planes off the grid points, so no sample is exactly 0.
  auto cellsFor = [&](double half) { return std::max(3, int(std::ceil(resolution * half / longest)) | 1); };
  grid.cells = {cellsFor(halfX), cellsFor(halfY), cellsFor(halfZ)};
  return grid;
}

}  // namespace

std::vector<std::string> shapeNames() { return {"sphere", "torus", "double-torus", "pretzel"}; }

Result<TriangleMesh> makeShape(const ShapeSettings& settings) {
  if (settings.resolution < 4 || settings.resolution > 1024)
    return usageError("--resolution must be between 4 and 1024 (got " + std::to_string(settings.resolution) + ")");
  const int n = settings.resolution;
  if (settings.name == "sphere")
    return polygonize([](double x, double y, double z) { return std::sqrt(x * x + y * y + z * z) - 1.0; },
                      gridAround(1.2, 1.2, 1.2, n));
  if (settings.name == "torus")
    return polygonize([](double x, double y, double z) { return torusField(x, y, z, 0.0, 1.0, 0.4); },
                      gridAround(1.5, 1.5, 0.5, n));
  if (settings.name == "double-torus")
    return polygonize([](double x, double y, double z) { return ringsField(x, y, z, 2); },
                      gridAround(2.0, 1.2, 0.4, n));
  if (settings.name == "pretzel")
    return polygonize([](double x, double y, double z) { return ringsField(x, y, z, 3); },
                      gridAround(2.8, 1.2, 0.4, n));
  std::string names;
  for (const std::string& name : shapeNames()) names += (names.empty() ? "" : ", ") + name;
  return usageError("unknown shape \"" + settings.name + "\" (known: " + names + ")");
}

}  // namespace bake
