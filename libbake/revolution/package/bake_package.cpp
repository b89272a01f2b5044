// The package of a revolbake run (formats/revolution.md): one node with a coarse revolved mesh of the
// profile (what any glTF viewer draws), its material carrying BAKE_revolution with the shape map, the optional
// displacement and arc-length maps in bufferViews aligned for direct upload, the march parameters and
// the projection, and an optional embedded PNG as the standard base colour texture.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "bake/core/atomic_file.h"
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

std::vector<std::pair<Point2, Point2>> fallbackEdges(const Profile& profile, double tolerance) {
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
  if (edges.size() > kFallbackMaxEdges) {
    const std::size_t stride = (edges.size() + kFallbackMaxEdges - 1) / kFallbackMaxEdges;
    std::vector<std::pair<Point2, Point2>> coarse;
    for (std::size_t k = 0; k < edges.size(); k += stride)
      coarse.push_back({edges[k].first, edges[std::min(edges.size(), k + stride) - 1].second});
    edges = std::move(coarse);
  }
  return edges;
}

glb::Mesh revolvedFallback(const Profile& profile, const ShapeGrid& grid, const double repeat[2]) {
  const double hMax = grid.hMin + grid.height * grid.texelSize;
  const double extent = std::max(grid.width, grid.height) * grid.texelSize;
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> indices;
  for (const auto& [a, b] : fallbackEdges(profile, extent / 200)) {
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

  package.meshes.push_back(revolvedFallback(state.profile, grid, state.repeat));
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
