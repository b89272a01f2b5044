// Marching tetrahedra. A cube of the grid is cut into six tetrahedra that all share the diagonal from
// corner 0 to corner 7; a tetrahedron whose corners change sign yields one triangle (one corner
// differs) or two (two and two). Crossings are found by linear interpolation of the field and stored
// once per grid edge, keyed by its two grid points.
#include "mesh/implicit.h"

#include <cmath>
#include <unordered_map>
#include <vector>

namespace bake {
namespace {

// Cube corners as (dx, dy, dz) bits: corner c = dx + 2 dy + 4 dz.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra{{
    {0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}}};

struct Sampler {
  const std::function<double(double, double, double)>& field;
  const ImplicitGrid& grid;
  std::array<double, 3> step;
  std::vector<double> values;

  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(grid.cells[1] + 1) + std::size_t(j)) * std::size_t(grid.cells[0] + 1) +
           std::size_t(i);
  }
  std::array<double, 3> point(int i, int j, int k) const {
    return {grid.min[0] + step[0] * i, grid.min[1] + step[1] * j, grid.min[2] + step[2] * k};
  }
  std::array<double, 3> gradient(const std::array<double, 3>& p) const {
    std::array<double, 3> g{};
    for (int a = 0; a < 3; ++a) {
      std::array<double, 3> lo = p, hi = p;
      const double h = 0.25 * step[a];
      lo[a] -= h;
      hi[a] += h;
      g[a] = (field(hi[0], hi[1], hi[2]) - field(lo[0], lo[1], lo[2])) / (2.0 * h);
    }
    return g;
  }
};

struct Builder {
  const Sampler& sampler;
  TriangleMesh mesh;
  std::unordered_map<std::uint64_t, std::uint32_t> vertexOfEdge;

  std::uint32_t crossing(std::size_t a, std::size_t b, const std::array<double, 3>& pa, const std::array<double, 3>& pb) {
    if (a > b) return crossing(b, a, pb, pa);
    const std::uint64_t key = (std::uint64_t(a) << 32) ^ std::uint64_t(b);
    if (auto found = vertexOfEdge.find(key); found != vertexOfEdge.end()) return found->second;
    const double fa = sampler.values[a], fb = sampler.values[b];
    const double t = fa / (fa - fb);
    std::array<double, 3> p{};
    for (int k = 0; k < 3; ++k) p[k] = pa[k] + t * (pb[k] - pa[k]);
    std::array<double, 3> g = sampler.gradient(p);
    const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (length > 0.0)
      for (double& c : g) c /= length;
    const auto id = std::uint32_t(mesh.positions.size());
    mesh.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
    mesh.normals.push_back({float(g[0]), float(g[1]), float(g[2])});
    vertexOfEdge.emplace(key, id);
    return id;
  }

  // Adds a triangle turned so that its normal agrees with the field's gradient (outward).
  void addOriented(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) return;
    const Vec3f& pa = mesh.positions[a];
    const Vec3f& pb = mesh.positions[b];
    const Vec3f& pc = mesh.positions[c];
    const double u[3] = {double(pb[0]) - pa[0], double(pb[1]) - pa[1], double(pb[2]) - pa[2]};
    const double v[3] = {double(pc[0]) - pa[0], double(pc[1]) - pa[1], double(pc[2]) - pa[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double outward = 0.0;
    for (std::uint32_t corner : {a, b, c})
      for (int k = 0; k < 3; ++k) outward += n[k] * mesh.normals[corner][k];
    if (outward >= 0.0) {
      mesh.triangles.push_back({a, b, c});
    } else {
      mesh.triangles.push_back({a, c, b});
    }
  }

  void tetrahedron(const std::array<std::size_t, 4>& id, const std::array<std::array<double, 3>, 4>& p) {
    std::array<int, 4> inside{}, outside{};
    int ni = 0, no = 0;
    for (int c = 0; c < 4; ++c) {
      if (sampler.values[id[c]] < 0.0) {
        inside[ni++] = c;
      } else {
        outside[no++] = c;
      }
    }
    auto cut = [&](int x, int y) { return crossing(id[x], id[y], p[x], p[y]); };
    if (ni == 1 || ni == 3) {
      const int lone = ni == 1 ? inside[0] : outside[0];
      const std::array<int, 4>& others = ni == 1 ? outside : inside;
      addOriented(cut(lone, others[0]), cut(lone, others[1]), cut(lone, others[2]));
    } else if (ni == 2) {
      const std::uint32_t a = cut(inside[0], outside[0]), b = cut(inside[0], outside[1]);
      const std::uint32_t c = cut(inside[1], outside[1]), d = cut(inside[1], outside[0]);
      addOriented(a, b, c);
      addOriented(a, c, d);
    }
  }
};

}  // namespace

TriangleMesh polygonize(const std::function<double(double, double, double)>& field, const ImplicitGrid& grid) {
  Sampler sampler{field, grid, {}, {}};
  for (int a = 0; a < 3; ++a) sampler.step[a] = (grid.max[a] - grid.min[a]) / grid.cells[a];
  sampler.values.resize(std::size_t(grid.cells[0] + 1) * std::size_t(grid.cells[1] + 1) * std::size_t(grid.cells[2] + 1));
  for (int k = 0; k <= grid.cells[2]; ++k)
    for (int j = 0; j <= grid.cells[1]; ++j)
      for (int i = 0; i <= grid.cells[0]; ++i) {
        const auto p = sampler.point(i, j, k);
        double value = field(p[0], p[1], p[2]);
        if (value == 0.0) value = 1e-300;  // keep crossings strictly between grid points
        sampler.values[sampler.index(i, j, k)] = value;
      }
  Builder builder{sampler, {}, {}};
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        std::array<std::size_t, 8> corner{};
        std::array<std::array<double, 3>, 8> position{};
        for (int c = 0; c < 8; ++c) {
          const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
          corner[std::size_t(c)] = sampler.index(i + di, j + dj, k + dk);
          position[std::size_t(c)] = sampler.point(i + di, j + dj, k + dk);
        }
        for (const auto& tet : kTetrahedra)
          builder.tetrahedron({corner[tet[0]], corner[tet[1]], corner[tet[2]], corner[tet[3]]},
                              {position[tet[0]], position[tet[1]], position[tet[2]], position[tet[3]]});
      }
  return std::move(builder.mesh);
}

}  // namespace bake
