// The package of a revolbake run (formats/revolution.md): one node with the shape box (a plain box mesh
// any glTF viewer draws), its material carrying BAKE_revolution with the shape map, the optional
// displacement and arc-length maps in bufferViews aligned for direct upload, the march parameters and
// the projection, and an optional embedded PNG as the standard base colour texture.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "bake_formats/revolution.h"
#include "core/atomic_file.h"
#include "revolution/bake_stages.h"

namespace bake::revolution {
namespace {

using nlohmann::json;
namespace fmt = format::revolution;

// A box with outward normals: 6 faces x 4 corners, so every viewer shades it flat.
glb::Mesh shapeBox(double radius, double hMin, double hMax) {
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
  const float lo[3] = {float(-radius), float(hMin), float(-radius)};
  const float hi[3] = {float(radius), float(hMax), float(radius)};
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const std::uint32_t base = std::uint32_t(positions.size() / 3);
      for (int corner = 0; corner < 4; ++corner) {
        float p[3];
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = (corner == 1 || corner == 2) ? hi[u] : lo[u];
        p[v] = (corner >= 2) ? hi[v] : lo[v];
        positions.insert(positions.end(), p, p + 3);
        float n[3] = {0, 0, 0};
        n[axis] = side ? 1.0f : -1.0f;
        normals.insert(normals.end(), n, n + 3);
      }
      // Corners 0..3 go round the face counter-clockwise seen from +axis; flip for the -axis side.
      const std::uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
      for (int k = 0; k < 6; ++k) indices.push_back(base + quad[side ? k : 5 - k]);
    }
  }
  glb::Primitive primitive;
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.attributes.push_back(glb::Attribute::fromFloats("NORMAL", 3, normals));
  primitive.indices = std::move(indices);
  primitive.material = 0;
  glb::Mesh mesh;
  mesh.name = "shape box";
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

  package.meshes.push_back(shapeBox(grid.width * grid.texelSize, grid.hMin, grid.hMin + grid.height * grid.texelSize));
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
