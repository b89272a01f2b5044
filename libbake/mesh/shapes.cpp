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

// Parametric shapes with a UV layout (for texture-space techniques such as grooves): a grid of
// `columns` x `rows` quads over (s, t) in [0, 1]^2, the seam at s = 0 / 1 kept as two vertices so the
// texture coordinates run on across it. `place(s, t)` gives position and normal, `uv(s, t)` the
// texture coordinates.
template <class Place, class Uv>
void addGrid(TriangleMesh& mesh, int columns, int rows, Place place, Uv uv) {
  const auto first = std::uint32_t(mesh.positions.size());
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) {
      const double s = double(i) / columns, t = double(j) / rows;
      const auto [position, normal] = place(s, t);
      mesh.positions.push_back(position);
      mesh.normals.push_back(normal);
      mesh.texcoords.push_back(uv(s, t));
    }
  auto at = [&](int i, int j) { return first + std::uint32_t(j * (columns + 1) + i); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (mesh.positions[a] != mesh.positions[b]) mesh.triangles.push_back({a, b, c});  // not at a pole
      if (mesh.positions[c] != mesh.positions[d]) mesh.triangles.push_back({a, c, d});
    }
}

Vec3f toFloat(double x, double y, double z) { return {float(x), float(y), float(z)}; }

// The angle of s in [0, 1] around a circle, with s = 1 exactly where s = 0 is (sin 2π is not 0 in
// floating point), so the two vertices of a seam sit at one position.
double turn(double s) { return s >= 1 ? 0 : 2 * kPi * s; }

// A capped cylinder standing on y = -1 up to y = 1, radius 0.35. The side's UV: u around (counter-
// clockwise seen from +y, starting at +z), v up; one UV unit spans the circumference in u and the
// height in v, and the caps are laid out at the side's scale, as discs outside the unit square (around
// UV (0.5, 1.2) and (0.5, -0.2)): a pattern keeps one size everywhere, and one drawn in the unit
// square without repeating leaves the caps plain.
TriangleMesh column(int resolution) {
  constexpr double kRadius = 0.35, kHeight = 2.0;
  const double circumference = 2 * kPi * kRadius;
  const int around = std::max(8, resolution), along = std::max(2, resolution / 4);
  TriangleMesh mesh;
  addGrid(mesh, around, along, [&](double s, double t) {
    const double a = turn(s);
    return std::pair{toFloat(kRadius * std::sin(a), kHeight * t - 1, kRadius * std::cos(a)), toFloat(std::sin(a), 0, std::cos(a))};
  }, [](double s, double t) { return Vec2f{float(s), float(t)}; });
  // Caps: rings from the rim (t = 0) to the centre (t = 1), facing up at the top and down below.
  for (const double y : {1.0, -1.0}) {
    const int rings = std::max(1, along / 2);
    addGrid(mesh, around, rings, [&](double s, double t) {
      const double a = turn(s) * y, r = kRadius * (1 - t);  // y < 0 reverses the turn: outward faces
      return std::pair{toFloat(r * std::sin(a), y, r * std::cos(a)), toFloat(0, y, 0)};
    }, [&](double s, double t) {
      const double a = turn(s) * y, r = kRadius * (1 - t) / circumference;
      return Vec2f{float(0.5 + r * std::sin(a)), float(0.5 + 0.7 * y - y * r * std::cos(a) * circumference / kHeight)};
    });
  }
  return mesh;
}

// A latitude-longitude sphere of radius 1: u the longitude, v from the south pole (0) to the north
// pole (1). Its UV layout is stretched toward the poles, as such layouts are.
TriangleMesh globe(int resolution) {
  const int around = std::max(8, resolution), along = std::max(4, resolution / 2);
  TriangleMesh mesh;
  addGrid(mesh, around, along, [](double s, double t) {
    const double a = turn(s), b = kPi * (t - 0.5);
    const Vec3f p = toFloat(std::cos(b) * std::sin(a), std::sin(b), std::cos(b) * std::cos(a));
    return std::pair{p, p};
  }, [](double s, double t) { return Vec2f{float(s), float(t)}; });
  return mesh;
}

}  // namespace

std::vector<std::string> shapeNames() { return {"sphere", "torus", "double-torus", "pretzel", "column", "globe"}; }

Result<TriangleMesh> makeShape(const ShapeSettings& settings) {
  if (settings.resolution < 4 || settings.resolution > 1024)
    return usageError("--resolution must be between 4 and 1024 (got " + std::to_string(settings.resolution) + ")");
  const int n = settings.resolution;
  if (settings.name == "column") return column(n);
  if (settings.name == "globe") return globe(n);
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
