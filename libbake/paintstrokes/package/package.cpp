// Writes the BAKE_paintstrokes package (formats/paintstrokes.md) of a validated stroke set and its
// baked shadow table.
//
// Quantisation is per stroke: each stroke's control points are stored as uint16 positions over the
// stroke's own box and uint16 radii over its largest radius, so a short hair on a large model keeps
// the full 16 bits. The box's origin and step are what a reader sees, fp32; they are chosen in fp32
// first (origin rounded down, step rounded up so origin + 65535 step reaches the box's top) and the
// points quantised against those stored values, so the stated bound (step / 2 per axis) holds for the
// stored numbers, not only for the double ones. Colour, opacity, reflectance and shadows are 8-bit
// unorm (error <= 1/510).
//
// The culling sphere must hold the interpolated tube, which a Catmull-Rom spline may push outside the
// control points' hull (overshoot). Each uniform Catmull-Rom segment is a cubic Bezier with the
// control points p1, p1 + (p2 - p0) / 6, p2 - (p3 - p1) / 6, p2 and lies in their convex hull; the
// radius spline likewise stays below the largest of its four Bezier values. The sphere round all
// Bezier points, grown by that largest radius, is therefore a bound, not a sample.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "paintstrokes/package/package.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;
namespace fmt = format::paintstrokes;

// Coordinates and radii beyond this are refused: fp32 origins and steps must stay finite.
constexpr double kLargestCoordinate = 1e30;

float floatDown(double x) {
  float f = float(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

float floatUp(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

std::uint8_t unorm8(double v) { return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// The quantisation frame of one stroke (the fp32 values the package stores).
struct StrokeFrame {
  float origin[3], step[3];
  float radiusStep;
};

StrokeFrame frameOf(const Stroke& stroke) {
  Vec3d lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  double rmax = 0;
  for (const StrokePoint& p : stroke.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p.position[k]);
      hi[k] = std::max(hi[k], p.position[k]);
    }
    rmax = std::max(rmax, p.radius);
  }
  StrokeFrame frame{};
  for (int k = 0; k < 3; ++k) {
    frame.origin[k] = floatDown(lo[k]);
    // Zero only when the axis is flat and its value is exactly an fp32 number.
    frame.step[k] = hi[k] > double(frame.origin[k]) ? floatUp((hi[k] - double(frame.origin[k])) / fmt::kPositionLevels) : 0.0f;
    // Rounding of the division may leave origin + 65535 step just short of the top: step up once more.
    while (double(frame.origin[k]) + fmt::kPositionLevels * double(frame.step[k]) < hi[k])
      frame.step[k] = std::nextafter(frame.step[k], std::numeric_limits<float>::infinity());
  }
  frame.radiusStep = floatUp(rmax / fmt::kRadiusLevels);
  while (fmt::kRadiusLevels * double(frame.radiusStep) < rmax)
    frame.radiusStep = std::nextafter(frame.radiusStep, std::numeric_limits<float>::infinity());
  return frame;
}

std::uint16_t quantise(double value, double origin, double step) {
  if (!(step > 0)) return 0;
  return std::uint16_t(std::clamp(std::round((value - origin) / step), 0.0, fmt::kPositionLevels));
}

fmt::ControlPoint packPoint(const StrokePoint& p, const StrokeFrame& frame) {
  fmt::ControlPoint out{};
  for (int k = 0; k < 3; ++k) out.position[k] = quantise(p.position[k], frame.origin[k], frame.step[k]);
  // A stored radius is never 0 (the header's rule): the thinnest radius is one step.
  out.radius = std::uint16_t(std::clamp(std::round(p.radius / double(frame.radiusStep)), 1.0, fmt::kRadiusLevels));
  for (int k = 0; k < 3; ++k) out.colour[k] = unorm8(p.colour[k]);
  out.opacity = unorm8(p.opacity);
  out.reflectance = unorm8(p.reflectance);
  return out;
}

std::array<double, 4> dequantise(const fmt::ControlPoint& q, const StrokeFrame& frame) {
  return {double(frame.origin[0]) + double(q.position[0]) * double(frame.step[0]),
          double(frame.origin[1]) + double(q.position[1]) * double(frame.step[1]),
          double(frame.origin[2]) + double(q.position[2]) * double(frame.step[2]), double(q.radius) * double(frame.radiusStep)};
}

// The Bezier form of the uniform Catmull-Rom spline as the runtime evaluates it (beyond either end,
// the neighbour reflected through the end point: p[-1] = 2 p[0] - p[1]): for segment i, the 4 Bezier
// values of component `get`. At an end the inner Bezier point lies on the chord, so the bound would
// hold as well with doubled end points.
template <class Get>
std::array<double, 4> bezierOf(const std::vector<StrokePoint>& p, std::size_t i, Get get) {
  const std::size_t n = p.size();
  const double p1 = get(p[i]), p2 = get(p[i + 1]);
  const double p0 = i == 0 ? 2 * p1 - p2 : get(p[i - 1]);
  const double p3 = i + 2 < n ? get(p[i + 2]) : 2 * p2 - p1;
  return {p1, p1 + (p2 - p0) / 6, p2 - (p3 - p1) / 6, p2};
}

// Culling sphere (centre, radius) round every Bezier point of the path, grown by the largest value
// the radius spline can take; in fp32, rounded outwards.
std::array<float, 4> cullingSphere(const Stroke& stroke) {
  const auto& p = stroke.points;
  std::vector<Vec3d> hull;
  double rmax = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    std::array<std::array<double, 4>, 3> axes;
    for (int k = 0; k < 3; ++k) axes[k] = bezierOf(p, i, [k](const StrokePoint& s) { return s.position[k]; });
    for (int j = 0; j < 4; ++j) hull.push_back({axes[0][j], axes[1][j], axes[2][j]});
    for (double r : bezierOf(p, i, [](const StrokePoint& s) { return s.radius; })) rmax = std::max(rmax, std::abs(r));
  }
  Vec3d lo = hull.front(), hi = hull.front();
  for (const Vec3d& x : hull)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  std::array<float, 4> sphere{};
  double reach = 0;
  for (int k = 0; k < 3; ++k) sphere[k] = float(0.5 * (lo[k] + hi[k]));
  for (const Vec3d& x : hull) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (x[k] - double(sphere[k])) * (x[k] - double(sphere[k]));
    reach = std::max(reach, std::sqrt(d2));
  }
  // Relative slack covers the rounding of the sums above.
  sphere[3] = floatUp((reach + rmax) * (1 + 1e-12));
  return sphere;
}

fmt::Style packStyle(const StrokeStyle& s) {
  fmt::Style out{};
  out.opacity[0] = float(s.centreOpacity);
  out.opacity[1] = float(s.edgeOpacity);
  out.opacity[2] = float(s.volumeAcross);
  out.opacity[3] = float(s.volumeAlong);
  for (int k = 0; k < 3; ++k) out.specular[k] = float(s.specular[k]);
  out.specular[3] = float(s.shininess);
  out.shading[0] = float(s.ambient);
  out.shading[1] = float(s.edgeSoftness);
  return out;
}

template <class T>
glb::Blob blobOf(const std::vector<T>& items) {
  return glb::blobOf(items, fmt::kBufferAlignment);
}

Status checkStrokes(const StrokeSet& set, const std::vector<Vec3d>& directions, const std::vector<double>& shadows) {
  if (set.styles.empty() || set.styles.size() > fmt::kMaxStyles)
    return invalidInput("paintstrokes package: " + std::to_string(set.styles.size()) + " styles (1 to " +
                        std::to_string(fmt::kMaxStyles) + " allowed)");
  if (set.strokes.empty()) return invalidInput("paintstrokes package: no strokes");
  if (directions.size() > fmt::kMaxShadowDirections)
    return invalidInput("paintstrokes package: " + std::to_string(directions.size()) + " shadow directions (at most " +
                        std::to_string(fmt::kMaxShadowDirections) + ")");
  std::uint64_t points = 0;
  for (std::size_t s = 0; s < set.strokes.size(); ++s) {
    const Stroke& stroke = set.strokes[s];
    const std::string where = "stroke " + std::to_string(s);
    if (stroke.points.size() < 2 || stroke.points.size() > fmt::kMaxPointsPerStroke)
      return invalidInput(where + ": " + std::to_string(stroke.points.size()) + " control points (2 to " +
                          std::to_string(fmt::kMaxPointsPerStroke) + " allowed)");
    if (stroke.style >= set.styles.size())
      return invalidInput(where + ": style " + std::to_string(stroke.style) + " does not exist (" +
                          std::to_string(set.styles.size()) + " styles)");
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
      const StrokePoint& p = stroke.points[i];
      bool ok = std::isfinite(p.radius) && p.radius > 0 && p.radius <= kLargestCoordinate;
      for (double x : p.position) ok = ok && std::isfinite(x) && std::abs(x) <= kLargestCoordinate;
      if (!ok)
        return invalidInput(where + ", control point " + std::to_string(i) +
                            ": position or radius is not finite, not positive or beyond 1e30 (fp32 range)");
    }
    points += stroke.points.size();
  }
  if (points > std::numeric_limits<std::uint32_t>::max()) return invalidInput("paintstrokes package: more than 2^32-1 control points");
  if (shadows.size() != points * directions.size())
    return internalError("paintstrokes package: the shadow table holds " + std::to_string(shadows.size()) + " values, expected " +
                         std::to_string(points * directions.size()));
  for (double v : shadows)
    if (!(v >= 0 && v <= 1)) return internalError("paintstrokes package: a shadow value is outside [0, 1]");
  return {};
}

// The fallback every glTF viewer shows: the control points joined stroke by stroke as lines.
glb::Mesh previewLines(const std::vector<fmt::Stroke>& strokes, const std::vector<fmt::ControlPoint>& points) {
  std::vector<float> positions;
  positions.reserve(points.size() * 3);
  std::vector<std::uint32_t> indices;
  for (const fmt::Stroke& s : strokes) {
    for (std::uint32_t i = 0; i < s.info[1]; ++i) {
      const fmt::ControlPoint& q = points[s.info[0] + i];
      for (int k = 0; k < 3; ++k) positions.push_back(float(double(s.origin[k]) + double(q.position[k]) * double(s.step[k])));
      if (i + 1 < s.info[1]) {
        indices.push_back(s.info[0] + i);
        indices.push_back(s.info[0] + i + 1);
      }
    }
  }
  glb::Primitive primitive;
  primitive.mode = 1;  // LINES
  primitive.attributes.push_back(glb::Attribute::fromFloats("POSITION", 3, positions));
  primitive.indices = std::move(indices);
  primitive.material = 0;
  glb::Mesh mesh;
  mesh.name = "paintstrokes";
  mesh.primitives.push_back(std::move(primitive));
  return mesh;
}

json vec3(const auto& v) { return json::array({v[0], v[1], v[2]}); }

}  // namespace

std::array<double, 4> PaintstrokePackage::positionRadius(std::size_t stroke, std::size_t pointInStroke) const {
  const fmt::Stroke& s = strokes.at(stroke);
  const fmt::ControlPoint& q = points.at(std::size_t(s.info[0]) + pointInStroke);
  return {double(s.origin[0]) + double(q.position[0]) * double(s.step[0]),
          double(s.origin[1]) + double(q.position[1]) * double(s.step[1]),
          double(s.origin[2]) + double(q.position[2]) * double(s.step[2]), double(q.radius) * double(s.origin[3])};
}

Result<glb::Package> buildPaintstrokePackage(const StrokeSet& set, const std::vector<Vec3d>& directions,
                                             const std::vector<double>& shadows, const glb::Mesh* extraMesh,
                                             QuantizationError* error) {
  BAKE_RETURN_IF_ERROR(checkStrokes(set, directions, shadows));
  std::vector<fmt::Stroke> strokes;
  std::vector<fmt::ControlPoint> points;
  strokes.reserve(set.strokes.size());
  QuantizationError measured;
  std::array<float, 3> lo, hi;
  lo.fill(std::numeric_limits<float>::infinity());
  hi.fill(-std::numeric_limits<float>::infinity());
  double colourSum[3] = {0, 0, 0};
  for (const Stroke& stroke : set.strokes) {
    const StrokeFrame frame = frameOf(stroke);
    fmt::Stroke out{};
    out.info[0] = std::uint32_t(points.size());
    out.info[1] = std::uint32_t(stroke.points.size());
    out.info[2] = std::uint32_t(stroke.style);
    for (int k = 0; k < 3; ++k) {
      out.origin[k] = frame.origin[k];
      out.step[k] = frame.step[k];
    }
    out.origin[3] = frame.radiusStep;
    const std::array<float, 4> sphere = cullingSphere(stroke);
    std::copy(sphere.begin(), sphere.end(), out.sphere);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], floatDown(double(sphere[k]) - double(sphere[3])));
      hi[k] = std::max(hi[k], floatUp(double(sphere[k]) + double(sphere[3])));
    }
    double strokeRadiusBound = 0.5 * double(frame.radiusStep);
    for (const StrokePoint& p : stroke.points) {
      // Below half a step a radius is stored as one step: off by less than a whole step.
      if (p.radius < 0.5 * double(frame.radiusStep)) strokeRadiusBound = double(frame.radiusStep);
      const fmt::ControlPoint q = packPoint(p, frame);
      const std::array<double, 4> back = dequantise(q, frame);
      for (int k = 0; k < 3; ++k) {
        measured.position = std::max(measured.position, std::abs(back[k] - p.position[k]));
        measured.unorm = std::max(measured.unorm, std::abs(q.colour[k] / 255.0 - p.colour[k]));
        colourSum[k] += p.colour[k];
      }
      measured.radius = std::max(measured.radius, std::abs(back[3] - p.radius));
      measured.unorm = std::max({measured.unorm, std::abs(q.opacity / 255.0 - p.opacity), std::abs(q.reflectance / 255.0 - p.reflectance)});
      points.push_back(q);
    }
    measured.radiusBound = std::max(measured.radiusBound, strokeRadiusBound);
    strokes.push_back(out);
  }
  std::vector<fmt::Style> styles;
  json styleNames = json::array();
  for (const StrokeStyle& s : set.styles) {
    styles.push_back(packStyle(s));
    styleNames.push_back(s.name);
  }
  std::vector<std::uint8_t> shadowBytes(shadows.size());
  for (std::size_t i = 0; i < shadows.size(); ++i) shadowBytes[i] = unorm8(shadows[i]);
  json directionList = json::array();
  for (const Vec3d& d : directions) directionList.push_back(vec3(d));

  glb::Package package;
  // Blob i is bufferView i, in the order of fmt::kArrayKeys.
  package.blobs.push_back(blobOf(strokes));
  package.blobs.push_back(blobOf(points));
  package.blobs.push_back(blobOf(styles));
  package.blobs.push_back(blobOf(shadowBytes));
  json views = json::object();
  for (std::size_t k = 0; k < fmt::kArrayCount; ++k) views[fmt::kArrayKeys[k]] = k;
  json extension = {
      {"version", fmt::kVersion},
      {fmt::kCounts, {{fmt::kStrokes, strokes.size()}, {fmt::kPoints, points.size()}, {fmt::kStyles, styles.size()},
                      {fmt::kShadows, shadowBytes.size()}}},
      {"strides", {{fmt::kStrokes, sizeof(fmt::Stroke)}, {fmt::kPoints, sizeof(fmt::ControlPoint)},
                   {fmt::kStyles, sizeof(fmt::Style)}, {fmt::kShadows, 1}}},
      {fmt::kBufferViews, views},
      {"bounds", {{"min", vec3(lo)}, {"max", vec3(hi)}}},
      {"shadowDirections", directionList},
      {"styleNames", styleNames},
      {"quantization", {{"position", measured.position}, {"radius", measured.radius}, {"unorm", measured.unorm}}}};
  if (!set.units.empty()) extension["units"] = set.units;

  const double n = std::max<double>(1, double(points.size()));
  package.materials.push_back({{"name", "paintstrokes"},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {colourSum[0] / n, colourSum[1] / n, colourSum[2] / n, 1.0}},
                                                         {"metallicFactor", 0.0},
                                                         {"roughnessFactor", 0.8}}},
                               {"extensions", {{fmt::kExtension, extension}}}});
  package.meshes.push_back(previewLines(strokes, points));
  if (extraMesh) {
    glb::Mesh mesh = *extraMesh;
    if (mesh.name.empty()) mesh.name = "grown on";
    for (glb::Primitive& primitive : mesh.primitives) primitive.material = 1;
    package.materials.push_back({{"name", "surface"},
                                 {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}},
                                                           {"metallicFactor", 0.0},
                                                           {"roughnessFactor", 0.9}}}});
    package.meshes.push_back(std::move(mesh));
  }
  if (error) *error = measured;
  return package;
}

}  // namespace bake::paintstrokes
