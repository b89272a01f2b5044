// The package of a revolbake run (formats/revolution.md): one node with a coarse revolved mesh of the
// profile (what any glTF viewer draws), its material carrying BAKE_revolution with the shape map, the optional
// displacement and arc-length maps in bufferViews aligned for direct upload, the march parameters and
// the projection, and an optional embedded PNG as the standard base colour texture.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "bake/core/atomic_file.h"
#include "bake/core/vector_text.h"
#include "bake_formats/revolution.h"
#include "revolution/bake/bake_stages.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {
namespace {

using nlohmann::json;
namespace fmt = format::revolution;

// What a viewer without BAKE_revolution draws: the profile revolved coarsely (its pieces flattened
// within 1/200 of the profile's size, 48 steps round the axis), with outward normals and the
// cylindrical texture coordinates (u round the axis, v up the shape map's height, both repeated as
// the package says), so the base colour texture shows on it. The runtime ray-marches the shape map's
// own box and never reads this mesh.
constexpr int kFallbackSteps = 48;
constexpr std::size_t kFallbackMaxEdges = 4096;

std::vector<std::pair<Point2, Point2>> fallbackEdges(const Profile& profile, double tolerance, std::size_t maxEdges) {
  std::vector<std::pair<Point2, Point2>> edges;
  std::vector<Point2> points;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) {
      if (s.onAxis) continue;
      points.assign(1, s.a);
      flattenSegment(s, tolerance, points);
      for (std::size_t k = 0; k + 1 < points.size(); ++k)
        if (points[k].r != points[k + 1].r || points[k].h != points[k + 1].h) edges.push_back({points[k], points[k + 1]});
    }
  // A profile of very many pieces: every n-th edge's ends joined (only a preview).
  if (edges.size() > maxEdges) {
    const std::size_t stride = (edges.size() + maxEdges - 1) / maxEdges;
    std::vector<std::pair<Point2, Point2>> coarse;
    for (std::size_t k = 0; k < edges.size(); k += stride)
      coarse.push_back({edges[k].first, edges[std::min(edges.size(), k + stride) - 1].second});
    edges = std::move(coarse);
  }
  return edges;
}

glb::Mesh revolvedFallback(const Profile& profile, const ShapeGrid& grid, const double repeat[2], std::size_t maxEdges) {
  const double hMax = grid.hMin + grid.height * grid.texelSize;
  const double extent = std::max(grid.width, grid.height) * grid.texelSize;
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> indices;
  for (const auto& [a, b] : fallbackEdges(profile, extent / 200, maxEdges)) {
    const double length = std::hypot(b.r - a.r, b.h - a.h);
    Point2 normal{(b.h - a.h) / length, -(b.r - a.r) / length};
    const Point2 mid{0.5 * (a.r + b.r), 0.5 * (a.h + b.h)};
    const double step = 1e-4 * extent;
    if (signedDistance(profile, {mid.r + step * normal.r, mid.h + step * normal.h}).distance < 0) normal = {-normal.r, -normal.h};
    for (int k = 0; k < kFallbackSteps; ++k) {
      const std::uint32_t base = std::uint32_t(positions.size() / 3);
      for (int corner = 0; corner < 4; ++corner) {
        const int along = corner == 1 || corner == 2 ? k + 1 : k;
        const Point2& p = corner >= 2 ? b : a;
        const double angle = 2 * std::numbers::pi * along / kFallbackSteps;
        const double c = std::cos(angle), sn = std::sin(angle);
        positions.insert(positions.end(), {float(p.r * c), float(p.h), float(p.r * sn)});
        normals.insert(normals.end(), {float(normal.r * c), float(normal.h), float(normal.r * sn)});
        texcoords.insert(texcoords.end(), {float(repeat[0] * along / kFallbackSteps),
                                           float(repeat[1] * (1 - (p.h - grid.hMin) / (hMax - grid.hMin)))});
      }
      // Wind the quad so that its face normal agrees with the outward normal.
      const float* q = positions.data() + std::size_t(base) * 3;
      const double e1[3] = {q[3] - q[0], q[4] - q[1], q[5] - q[2]}, e2[3] = {q[9] - q[0], q[10] - q[1], q[11] - q[2]};
      const double face[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      const float* n = normals.data() + std::size_t(base) * 3;
      const bool agrees = face[0] * n[0] + face[1] * n[1] + face[2] * n[2] >= 0;
      const std::uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
      for (int m = 0; m < 6; ++m) indices.push_back(base + quad[agrees ? m : 5 - m]);
    }
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.attributes.push_back(glb::Attribute::fromFloats("TEXCOORD_0", 2, texcoords));
  primitive.indices = std::move(indices);
  primitive.material = 0;
  glb::Mesh mesh;
  mesh.name = "revolved preview";
  mesh.primitives.push_back(std::move(primitive));
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Replicas (formats/revolution.md, "Replicas")

// Where copy `index` puts a point of the one object: a mirror about the box's centre on the mirrored
// axes of odd copies, then the copy's offset (grid); the ring radius along +x, then a turn about +y
// (ring).
struct CopyPlacement {
  std::array<double, 9> linear{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major
  std::array<double, 3> offset{0, 0, 0};
  bool mirrored = false;
  std::array<double, 3> apply(const float* p) const {
    std::array<double, 3> out = offset;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[std::size_t(r)] += linear[std::size_t(r * 3 + c)] * p[c];
    return out;
  }
  std::array<double, 3> turn(const float* v) const {
    std::array<double, 3> out{0, 0, 0};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[std::size_t(r)] += linear[std::size_t(r * 3 + c)] * v[c];
    return out;
  }
};

struct ReplicaLayout {
  json extension;  // nothing: one object
  std::vector<CopyPlacement> copies;
};

Result<ReplicaLayout> replicaLayout(const Settings& settings, const ShapeGrid& grid) {
  ReplicaLayout layout;
  const double rMax = grid.width * grid.texelSize;
  const double extent[3] = {2 * rMax, grid.height * grid.texelSize, 2 * rMax};
  const double centre[3] = {0, grid.hMin + 0.5 * extent[1], 0};
  if (settings.ring >= 2) {
    const double room = std::sin(std::numbers::pi / settings.ring);
    double radius = settings.ringRadius > 0 ? settings.ringRadius : rMax / room;
    if (radius * room < rMax * (1 - 1e-9))
      return invalidInput("--ring-radius " + numberText(settings.ringRadius) + " is too small: " +
                              std::to_string(settings.ring) + " copies of radius " + numberText(rMax) +
                              " need at least " + numberText(rMax / room),
                          {settings.input, ""});
    radius = std::max(radius, rMax / room);  // rounding of rMax / room must not fail the reader's check
    layout.extension = {{"layout", format::revolution::kLayoutRing}, {"count", settings.ring}, {"radius", radius}};
    for (int k = 0; k < settings.ring; ++k) {
      const double angle = 2 * std::numbers::pi * k / settings.ring, c = std::cos(angle), sn = std::sin(angle);
      CopyPlacement copy;
      copy.linear = {c, 0, -sn, 0, 1, 0, sn, 0, c};
      copy.offset = {radius * c, 0, radius * sn};
      layout.copies.push_back(copy);
    }
    return layout;
  }
  if (settings.grid == std::array<int, 3>{1, 1, 1}) {
    layout.copies.push_back({});
    return layout;
  }
  std::array<double, 3> spacing{};
  std::array<bool, 3> mirror{};
  static const char* kAxes = "xyz";
  for (std::size_t a = 0; a < 3; ++a) {
    spacing[a] = settings.gridSpacing[a] > 0 ? settings.gridSpacing[a] : extent[a];
    if (spacing[a] < extent[a] * (1 - 1e-9))
      return invalidInput(std::string("--grid-spacing ") + kAxes[a] + " " + numberText(spacing[a]) +
                              " is smaller than the shape box's extent on that axis (" + numberText(extent[a]) +
                              "): the copies would overlap",
                          {settings.input, ""});
    spacing[a] = std::max(spacing[a], extent[a]);
    mirror[a] = settings.mirror.find(kAxes[a]) != std::string::npos;
  }
  layout.extension = {{"layout", format::revolution::kLayoutGrid},
                      {"count", settings.grid},
                      {"spacing", spacing},
                      {"mirror", mirror}};
  for (int k = 0; k < settings.grid[2]; ++k)
    for (int j = 0; j < settings.grid[1]; ++j)
      for (int i = 0; i < settings.grid[0]; ++i) {
        CopyPlacement copy;
        const int index[3] = {i, j, k};
        int flips = 0;
        for (std::size_t a = 0; a < 3; ++a) {
          const bool flip = mirror[a] && index[a] % 2 == 1;
          flips += flip ? 1 : 0;
          copy.linear[a * 4] = flip ? -1 : 1;
          copy.offset[a] = index[a] * spacing[a] + (flip ? 2 * centre[a] : 0);
        }
        copy.mirrored = flips % 2 == 1;
        layout.copies.push_back(copy);
      }
  return layout;
}

// The preview mesh once per copy (a mirrored copy's triangles wound back).
void replicatePreview(glb::Mesh& mesh, const std::vector<CopyPlacement>& copies) {
  if (copies.size() <= 1) return;
  glb::Primitive& primitive = mesh.primitives[0];
  const std::vector<float> positions = primitive.attributes[0].toFloats(), normals = primitive.attributes[1].toFloats(),
                           texcoords = primitive.attributes[2].toFloats();
  const std::vector<std::uint32_t> indices = primitive.indices;
  const std::size_t vertices = positions.size() / 3;
  std::vector<float> p, n, t;
  std::vector<std::uint32_t> triangles;
  for (const CopyPlacement& copy : copies) {
    const std::uint32_t base = std::uint32_t(p.size() / 3);
    for (std::size_t v = 0; v < vertices; ++v) {
      for (double x : copy.apply(&positions[v * 3])) p.push_back(float(x));
      for (double x : copy.turn(&normals[v * 3])) n.push_back(float(x));
    }
    t.insert(t.end(), texcoords.begin(), texcoords.end());
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
      triangles.push_back(base + indices[i]);
      triangles.push_back(base + indices[copy.mirrored ? i + 2 : i + 1]);
      triangles.push_back(base + indices[copy.mirrored ? i + 1 : i + 2]);
    }
  }
  primitive.attributes.clear();
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, p));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, n));
  primitive.attributes.push_back(glb::Attribute::fromFloats("TEXCOORD_0", 2, t));
  primitive.indices = std::move(triangles);
}

json projectionJson(const BakeState& state) {
  json scores = json::object();
  for (const ProjectionScore& score : state.projection.scores) {
    json entry = {{"degenerateArea", score.degenerateArea},
                  {"meanAngleDistortion", score.meanAngleDistortion},
                  {"meanAreaDistortion", score.meanAreaDistortion},
                  {"score", score.score},
                  {"repeatRatio", score.repeatRatio}};
    if (score.projection == Projection::Spherical) entry["sphereCentreH"] = score.sphereCentreH;
    scores[projectionName(score.projection)] = entry;
  }
  const ProjectionScore& spherical = state.projection.scores[std::size_t(Projection::Spherical)];
  return {{"type", projectionName(state.projection.chosen)},
          {"repeat", {state.repeat[0], state.repeat[1]}},
          {"sphereCentreH", spherical.sphereCentreH},
          {"scores", scores}};
}

json marchJson(const Settings& settings, const BakeState& state) {
  json march = {{"iterations", state.iterations},
                {"overRelaxation", settings.overRelaxation},
                {"hitEpsilon", state.hitEpsilon},
                {"targetError", settings.targetError}};
  for (const MarchErrorPoint& point : state.marchCurve)
    if (point.iterations == state.iterations) march["silhouetteMismatch"] = point.silhouetteMismatch;
  return march;
}

// Column-major matrix taking the object's frame (axis +y through the origin) to where a mesh input
// had its axis, so the baked object sits on the original.
std::array<double, 16> axisFrameMatrix(const AxisFit& axis) {
  const double* y = axis.direction.data();
  double seed[3] = {1, 0, 0};
  if (std::abs(y[0]) > 0.9) seed[0] = 0, seed[2] = 1;
  const double dot = seed[0] * y[0] + seed[1] * y[1] + seed[2] * y[2];
  double x[3] = {seed[0] - dot * y[0], seed[1] - dot * y[1], seed[2] - dot * y[2]};
  const double xn = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  for (double& c : x) c /= xn;
  const double z[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  return {x[0], x[1], x[2], 0, y[0], y[1], y[2], 0, z[0], z[1], z[2], 0,
          axis.point[0], axis.point[1], axis.point[2], 1};
}

Result<std::vector<std::uint8_t>> readPng(const std::string& path) {
  // readFileBytes refuses a directory (an ifstream reads one as an empty file).
  Result<std::vector<std::uint8_t>> read = readFileBytes(path);
  if (!read.isOk()) return Status(read.status().code(), "the base colour texture: " + read.status().message(), {path, ""});
  const std::vector<std::uint8_t> bytes = std::move(read).value();
  static const std::uint8_t kPngMagic[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  if (bytes.size() < 8 || !std::equal(kPngMagic, kPngMagic + 8, bytes.begin()))
    return invalidInput("the base colour texture must be a PNG file (glTF embeds PNG or JPEG)", {path, ""});
  return bytes;
}

}  // namespace

Result<glb::Package> buildPackage(const Settings& settings, const BakeState& state) {
  const ShapeGrid& grid = state.field.grid;
  glb::Package package;
  json extension = {{"version", fmt::kVersion}};

  package.blobs.push_back({state.encoded.bytes, 16});
  extension[fmt::kShapeMap] = {{fmt::kBufferView, 0},
                           {"width", grid.width},
                           {"height", grid.height},
                           {"texelSize", grid.texelSize},
                           {"hMin", grid.hMin},
                           {"encoding", encodingName(state.encoded.encoding)},
                           {"distanceScale", state.encoded.distanceScale}};
  extension["safetyMargin"] = state.margin.total();
  extension["safetyMarginParts"] = {{"bilinear", state.margin.bilinearOverestimate},
                                    {"quantisation", state.margin.quantisation}};
  extension["march"] = marchJson(settings, state);
  json bands = json::array();
  for (const ProxyBand& band : state.bands) bands.push_back({band.hMin, band.hMax, band.rMax});
  extension["proxyBands"] = bands;
  if (state.displacement) {
    extension[fmt::kDisplacementMap] = {{fmt::kBufferView, package.blobs.size()},
                                    {"width", state.displacement->width},
                                    {"height", state.displacement->height},
                                    {"derivativeScale", state.displacement->derivativeScale},
                                    {"heightScale", settings.heightScale}};
    package.blobs.push_back({state.displacement->bytes, 16});
  }
  extension["projection"] = projectionJson(state);
  if (!state.arcLengthMap.empty()) {
    extension[fmt::kArcLengthMap] = {{fmt::kBufferView, package.blobs.size()}};
    package.blobs.push_back({state.arcLengthMap, 16});
  }
  BAKE_ASSIGN_OR_RETURN(const ReplicaLayout replicas, replicaLayout(settings, grid));
  if (!replicas.extension.is_null()) extension[fmt::kReplicas] = replicas.extension;
  extension[fmt::kSelfShadow] = settings.selfShadow;

  json material = {{"name", "revolution"},
                   {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}},
                                             {"metallicFactor", 0.0},
                                             {"roughnessFactor", 0.6}}},
                   {"extensions", {{fmt::kExtension, extension}}}};
  if (!settings.baseColorTexture.empty()) {
    BAKE_ASSIGN_OR_RETURN(std::vector<std::uint8_t> png, readPng(settings.baseColorTexture));
    package.images.push_back({{"bufferView", package.blobs.size()}, {"mimeType", "image/png"}});
    package.blobs.push_back({std::move(png), 4});
    // Repeat in both directions: the projections wrap u at the seam and repeat v as asked.
    package.samplers.push_back({{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
    package.textures.push_back({{"source", 0}, {"sampler", 0}});
    material["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  }
  package.materials.push_back(material);

  // The preview's edges shared among the copies, so many copies do not make a huge preview.
  const std::size_t edgeBudget = std::max<std::size_t>(64, kFallbackMaxEdges / replicas.copies.size());
  package.meshes.push_back(revolvedFallback(state.profile, grid, state.repeat, edgeBudget));
  replicatePreview(package.meshes.back(), replicas.copies);
  glb::Node node;
  node.name = std::filesystem::path(settings.input).stem().string();
  node.mesh = 0;
  if (state.meshAxis) {
    std::array<double, 16> matrix = axisFrameMatrix(*state.meshAxis);
    for (int k = 0; k < 3; ++k) matrix[12 + k] += settings.position[k];
    node.matrix = matrix;
  } else {
    node.translation = settings.position;
  }
  package.nodes.push_back(node);
  return package;
}

}  // namespace bake::revolution
