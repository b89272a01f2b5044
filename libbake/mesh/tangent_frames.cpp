// Tangent frames and UV stretch (mesh/tangent_frames.h). The per-triangle derivatives dP/du and dP/dv
// solve [e1 e2] = [dP/du dP/dv] [[du1 du2] [dv1 dv2]] for the triangle's edges e1, e2 and their UV
// deltas; the handedness is the sign of (normal × dP/du) · dP/dv, the convention of glTF's TANGENT.
#include "mesh/tangent_frames.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

namespace bake {
namespace {

Vec3d toDouble(const Vec3f& v) { return {v[0], v[1], v[2]}; }

struct TriangleUv {
  Vec3d dPdu{}, dPdv{}, normal{};  // normal: unnormalised, |normal| = twice the area
  bool degenerate = true;          // no UV area
  int sign = 1;                    // handedness
};

TriangleUv triangleUv(const TriangleMesh& mesh, const Triangle& t) {
  TriangleUv out;
  const Vec3d p0 = toDouble(mesh.positions[t[0]]);
  const Vec3d e1 = vec::sub(toDouble(mesh.positions[t[1]]), p0), e2 = vec::sub(toDouble(mesh.positions[t[2]]), p0);
  out.normal = vec::cross(e1, e2);
  const Vec2f& w0 = mesh.texcoords[t[0]];
  const double du1 = double(mesh.texcoords[t[1]][0]) - w0[0], dv1 = double(mesh.texcoords[t[1]][1]) - w0[1];
  const double du2 = double(mesh.texcoords[t[2]][0]) - w0[0], dv2 = double(mesh.texcoords[t[2]][1]) - w0[1];
  const double r = du1 * dv2 - du2 * dv1;
  const double extent = std::abs(du1) + std::abs(du2) + std::abs(dv1) + std::abs(dv2);
  if (!(std::abs(r) > 1e-12 * extent * extent) || !std::isfinite(r)) return out;
  out.dPdu = vec::scale(vec::sub(vec::scale(e1, dv2), vec::scale(e2, dv1)), 1 / r);
  out.dPdv = vec::scale(vec::sub(vec::scale(e2, du1), vec::scale(e1, du2)), 1 / r);
  out.degenerate = !(vec::length(out.normal) > 0);
  out.sign = vec::dot(vec::cross(out.normal, out.dPdu), out.dPdv) >= 0 ? 1 : -1;
  return out;
}

double cornerAngle(const TriangleMesh& mesh, const Triangle& t, int corner) {
  const Vec3d p = toDouble(mesh.positions[t[corner]]);
  const Vec3d a = vec::sub(toDouble(mesh.positions[t[(corner + 1) % 3]]), p);
  const Vec3d b = vec::sub(toDouble(mesh.positions[t[(corner + 2) % 3]]), p);
  return std::atan2(vec::length(vec::cross(a, b)), vec::dot(a, b));
}

// Smooth normals for a mesh without them: area-weighted face normals summed over every vertex at the
// same position, so vertices split at a UV seam share one normal.
void computeSeamlessNormals(TriangleMesh& mesh) {
  std::map<std::array<float, 3>, std::size_t> groupOf;
  std::vector<std::size_t> group(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    group[v] = groupOf.emplace(mesh.positions[v], groupOf.size()).first->second;
  std::vector<Vec3d> sum(groupOf.size(), Vec3d{0, 0, 0});
  for (const Triangle& t : mesh.triangles) {
    const Vec3d p0 = toDouble(mesh.positions[t[0]]);
    const Vec3d n = vec::cross(vec::sub(toDouble(mesh.positions[t[1]]), p0), vec::sub(toDouble(mesh.positions[t[2]]), p0));
    for (std::uint32_t v : t) sum[group[v]] = vec::add(sum[group[v]], n);
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d n = vec::unit(sum[group[v]], {0, 0, 1});
    mesh.normals[v] = {float(n[0]), float(n[1]), float(n[2])};
  }
}

void normaliseNormals(TriangleMesh& mesh) {
  for (Vec3f& n : mesh.normals) {
    const Vec3d unit = vec::unit(toDouble(n), {0, 0, 1});
    n = std::isfinite(unit[0] + unit[1] + unit[2]) ? Vec3f{float(unit[0]), float(unit[1]), float(unit[2])} : Vec3f{0, 0, 1};
  }
}

// A copy of vertex v appended to every per-vertex array; returns its index.
std::uint32_t duplicateVertex(TriangleMesh& mesh, std::uint32_t v) {
  const auto index = std::uint32_t(mesh.positions.size());
  mesh.positions.push_back(mesh.positions[v]);
  if (!mesh.normals.empty()) mesh.normals.push_back(mesh.normals[v]);
  if (!mesh.texcoords.empty()) mesh.texcoords.push_back(mesh.texcoords[v]);
  for (glb::Attribute& attribute : mesh.extraAttributes) {
    const std::size_t size = attribute.elementSize();
    if (size == 0 || attribute.bytes.size() < (std::size_t(v) + 1) * size) continue;
    attribute.bytes.resize(attribute.bytes.size() + size);
    std::memmove(attribute.bytes.data() + attribute.bytes.size() - size, attribute.bytes.data() + std::size_t(v) * size, size);
  }
  return index;
}

// Any unit vector perpendicular to n.
Vec3d perpendicular(const Vec3d& n) {
  const Vec3d axis = std::abs(n[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  return vec::unit(vec::cross(n, axis), {1, 0, 0});
}

}  // namespace

Result<TangentFrames> computeTangentFrames(TriangleMesh& mesh) {
  if (mesh.texcoords.size() != mesh.positions.size())
    return invalidInput("the mesh has no texture coordinates (TEXCOORD_0, OBJ vt): grooves are laid out in UV");
  TangentFrames frames;
  if (mesh.normals.size() != mesh.positions.size()) {
    computeSeamlessNormals(mesh);
    frames.normalsComputed = mesh.positions.size();
  }
  normaliseNormals(mesh);

  std::vector<TriangleUv> uv(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    uv[t] = triangleUv(mesh, mesh.triangles[t]);
    frames.degenerateTriangles += uv[t].degenerate ? 1 : 0;
  }
  // Angle-weighted sums per vertex and handedness (index 0: +1, 1: -1).
  const std::size_t vertices = mesh.positions.size();
  std::vector<std::array<Vec3d, 2>> sum(vertices, {Vec3d{0, 0, 0}, Vec3d{0, 0, 0}});
  std::vector<std::array<double, 2>> weight(vertices, {0, 0});
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (uv[t].degenerate) continue;
    const int side = uv[t].sign > 0 ? 0 : 1;
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint32_t v = mesh.triangles[t][corner];
      const Vec3d n = toDouble(mesh.normals[v]);
      const Vec3d along = vec::sub(uv[t].dPdu, vec::scale(n, vec::dot(n, uv[t].dPdu)));
      const double length = vec::length(along);
      if (!(length > 0) || !std::isfinite(length)) continue;
      const double angle = cornerAngle(mesh, mesh.triangles[t], corner);
      sum[v][side] = vec::add(sum[v][side], vec::scale(along, angle / length));
      weight[v][side] += angle;
    }
  }
  // Split the vertices both handednesses reach: the lighter side moves to a copy.
  std::vector<std::uint32_t> copyOf(vertices, 0);
  std::vector<int> keptSide(vertices, 0);
  for (std::size_t v = 0; v < vertices; ++v) {
    keptSide[v] = weight[v][1] > weight[v][0] ? 1 : 0;
    if (weight[v][0] > 0 && weight[v][1] > 0) {
      copyOf[v] = duplicateVertex(mesh, std::uint32_t(v));
      ++frames.splitVertices;
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (uv[t].degenerate) continue;
    const int side = uv[t].sign > 0 ? 0 : 1;
    for (std::uint32_t& v : mesh.triangles[t])
      if (v < vertices && copyOf[v] != 0 && side != keptSide[v]) v = copyOf[v];
  }
  frames.tangents.resize(mesh.positions.size());
  std::vector<bool> used(vertices, false);
  for (const Triangle& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v < vertices) used[v] = true;
  auto frameOf = [&](std::size_t v, int side, std::size_t out) {
    const Vec3d n = toDouble(mesh.normals[out]);
    Vec3d t = sum[v][side];
    if (!(weight[v][side] > 0) || !(vec::length(t) > 1e-12 * weight[v][side])) {
      t = perpendicular(n);
      frames.fallbackVertices += used[v] ? 1 : 0;  // a vertex no triangle uses needs no frame
    }
    t = vec::unit(vec::sub(t, vec::scale(n, vec::dot(n, t))), perpendicular(n));
    frames.tangents[out] = {float(t[0]), float(t[1]), float(t[2]), side == 0 ? 1.0f : -1.0f};
  };
  for (std::size_t v = 0; v < vertices; ++v) {
    frameOf(v, keptSide[v], v);
    if (copyOf[v] != 0) frameOf(v, 1 - keptSide[v], copyOf[v]);
  }
  return frames;
}

std::vector<std::array<float, 4>> usableTangents(const TriangleMesh& mesh, std::string& problem) {
  std::vector<std::array<float, 4>> out;
  const auto found = std::find_if(mesh.extraAttributes.begin(), mesh.extraAttributes.end(),
                                  [](const glb::Attribute& a) { return a.name == "TANGENT"; });
  if (found == mesh.extraAttributes.end()) return out;  // none: no problem to report
  const std::vector<float> values = found->toFloats();
  if (found->components != 4 || values.size() != mesh.positions.size() * 4) {
    problem = "its TANGENT attribute is not one VEC4 per vertex";
    return out;
  }
  out.resize(mesh.positions.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    const float* t = &values[v * 4];
    const double length = std::sqrt(double(t[0]) * t[0] + double(t[1]) * t[1] + double(t[2]) * t[2]);
    if (!std::isfinite(length) || std::abs(length - 1) > 1e-3 || std::abs(std::abs(t[3]) - 1) > 1e-6) {
      problem = "its TANGENT of vertex " + std::to_string(v) + " is not a unit vector with w = ±1";
      return {};
    }
    out[v] = {t[0], t[1], t[2], t[3] > 0 ? 1.0f : -1.0f};
  }
  return out;
}

UvStretch measureUvStretch(const TriangleMesh& mesh, const double unitsPerUv[2], double limit) {
  UvStretch out;
  struct Measured {
    double scale, stretch, area;
    bool collapsed;
  };
  std::vector<Measured> measured;
  measured.reserve(mesh.triangles.size());
  double totalArea = 0;
  for (const Triangle& t : mesh.triangles) {
    const TriangleUv uv = triangleUv(mesh, t);
    const double area = 0.5 * vec::length(uv.normal);
    totalArea += area;
    if (uv.degenerate) {
      measured.push_back({0, 0, area, true});
      continue;
    }
    // Gram matrix of the Jacobian from texture units to world: [[a b] [b c]].
    const Vec3d ju = vec::scale(uv.dPdu, 1 / unitsPerUv[0]), jv = vec::scale(uv.dPdv, 1 / unitsPerUv[1]);
    const double a = vec::dot(ju, ju), b = vec::dot(ju, jv), c = vec::dot(jv, jv);
    const double mean = 0.5 * (a + c), spread = std::hypot(0.5 * (a - c), b);
    const double s1 = std::sqrt(mean + spread), s2 = std::sqrt(std::max(0.0, mean - spread));
    const bool collapsed = !(s2 > 1e-12 * s1) || !std::isfinite(s1);
    measured.push_back({collapsed ? 0 : std::sqrt(s1 * s2), collapsed ? 0 : s1 / s2, area, collapsed});
  }
  // The area-weighted median scale over triangles that have one.
  std::vector<std::pair<double, double>> byScale;
  for (const Measured& m : measured)
    if (!m.collapsed) byScale.push_back({m.scale, m.area});
  std::sort(byScale.begin(), byScale.end());
  double half = 0;
  for (const auto& [scale, area] : byScale) half += area;
  half *= 0.5;
  for (const auto& [scale, area] : byScale) {
    out.medianScale = scale;
    half -= area;
    if (half <= 0) break;
  }
  if (!byScale.empty()) {
    out.minScale = byScale.front().first;
    out.maxScale = byScale.back().first;
  }
  double areaOver = 0;
  for (std::size_t t = 0; t < measured.size(); ++t) {
    const Measured& m = measured[t];
    bool over = m.collapsed;
    if (m.collapsed) {
      ++out.noUvArea;
    } else {
      if (m.stretch > out.maxStretch) {
        out.maxStretch = m.stretch;
        out.worstTriangle = t;
      }
      const double deviation = out.medianScale > 0 ? std::max(m.scale / out.medianScale, out.medianScale / m.scale) : 1;
      over = m.stretch > limit || deviation > limit;
    }
    if (over) {
      ++out.trianglesOver;
      areaOver += m.area;
    }
  }
  out.areaShareOver = totalArea > 0 ? areaOver / totalArea : 0;
  return out;
}

}  // namespace bake
