// Reading and checking a BAKE_revolution material (formats/revolution.md, constants in
// bake_formats/revolution.h; revolution/package/package_read.h).
#include <bake_formats/revolution.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "bake/core/vector_text.h"
#include "core/json_keys.h"
#include "revolution/package/package_read.h"

namespace bake::revolution {
namespace {

namespace fmt = format::revolution;

// Field access with errors that name the field by its path in the extension ("shapeMap.width").
class Fields {
 public:
  Fields(const nlohmann::json& body, std::string path, const Location& where)
      : body_(body), path_(std::move(path)), where_(where) {}

  Status error(const std::string& field, const std::string& message) const {
    return invalidInput(std::string(fmt::kExtension) + " " + name(field) + " " + message, where_);
  }
  bool has(const char* key) const { return body_.is_object() && body_.contains(key); }
  const nlohmann::json& at(const char* key) const { return body_[key]; }

  Result<double> number(const char* key, double lo, double hi) const {
    if (!has(key)) return error(key, "is missing");
    const nlohmann::json& v = body_[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      return error(key, "must be a finite number, not " + v.dump());
    const double x = v.get<double>();
    if (x < lo || x > hi) return error(key, "is " + v.dump() + "; it must be in [" + text(lo) + ", " + text(hi) + "]");
    return x;
  }
  Result<double> positive(const char* key, double hi = 1e30) const {
    BAKE_ASSIGN_OR_RETURN(const double x, number(key, 0, hi));
    if (!(x > 0)) return error(key, "must be positive");
    return x;
  }
  Result<int> integer(const char* key, long long lo, long long hi) const {
    if (!has(key)) return error(key, "is missing");
    const nlohmann::json& v = body_[key];
    if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
      return error(key, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v.dump());
    return int(v.get<long long>());
  }
  Result<std::string> string(const char* key) const {
    if (!has(key)) return error(key, "is missing");
    if (!body_[key].is_string()) return error(key, "must be a string, not " + body_[key].dump());
    return body_[key].get<std::string>();
  }
  Result<Fields> object(const char* key) const {
    if (!has(key)) return error(key, "is missing");
    if (!body_[key].is_object()) return error(key, "must be an object");
    return Fields(body_[key], name(key), where_);
  }
  std::string name(const std::string& field) const { return path_.empty() ? field : path_ + "." + field; }

 private:
  static std::string text(double v) {
    char out[32];
    std::snprintf(out, sizeof out, "%g", v);
    return out;
  }
  const nlohmann::json& body_;
  std::string path_;
  Location where_;
};

// A bufferView that must hold `texels` texels of `texelBytes` bytes each.
Status checkBufferView(const Fields& in, const char* key, int index, const glb::Package& package,
                       std::size_t texels, std::size_t texelBytes, const std::string& layout) {
  if (index < 0 || std::size_t(index) >= package.blobs.size()) {
    return in.error(key, "is " + std::to_string(index) + " but the package has " +
                             std::to_string(package.blobs.size()) + " bufferViews");
  }
  const std::size_t expected = texels * texelBytes;
  const std::size_t actual = package.blobs[std::size_t(index)].bytes.size();
  if (actual != expected) {
    return in.error(key, "(bufferView " + std::to_string(index) + ") holds " + std::to_string(actual) +
                             " bytes; " + layout + " needs " + std::to_string(expected));
  }
  return {};
}

std::size_t texelBytesOf(DistanceEncoding encoding) {
  return encoding == DistanceEncoding::Float ? 16 : encoding == DistanceEncoding::Unorm16 ? 8 : 4;
}

Status readShapeMap(const Fields& root, const glb::Package& package, RevolutionParams::ShapeMap& map) {
  BAKE_ASSIGN_OR_RETURN(const Fields in, root.object(fmt::kShapeMap));
  BAKE_ASSIGN_OR_RETURN(map.width, in.integer("width", 1, 16384));
  BAKE_ASSIGN_OR_RETURN(map.height, in.integer("height", 1, 16384));
  BAKE_ASSIGN_OR_RETURN(const double texel, in.positive("texelSize"));
  map.texelSize = float(texel);
  BAKE_ASSIGN_OR_RETURN(const double hMin, in.number("hMin", -1e30, 1e30));
  map.hMin = float(hMin);
  BAKE_ASSIGN_OR_RETURN(const std::string encoding, in.string("encoding"));
  if (encoding == fmt::kEncodingFloat) {
    map.encoding = DistanceEncoding::Float;
  } else if (encoding == fmt::kEncodingUnorm16) {
    map.encoding = DistanceEncoding::Unorm16;
  } else if (encoding == fmt::kEncodingSqrt8) {
    map.encoding = DistanceEncoding::Sqrt8;
  } else {
    return in.error("encoding", "is \"" + encoding + "\"; known: float, unorm16, sqrt8");
  }
  if (map.encoding != DistanceEncoding::Float) {
    BAKE_ASSIGN_OR_RETURN(const double scale, in.positive("distanceScale"));
    map.distanceScale = float(scale);
  }
  BAKE_ASSIGN_OR_RETURN(map.bufferView, in.integer(fmt::kBufferView, 0, 1 << 30));
  return checkBufferView(in, "bufferView", map.bufferView, package,
                         std::size_t(map.width) * std::size_t(map.height), texelBytesOf(map.encoding),
                         std::to_string(map.width) + "x" + std::to_string(map.height) + " RGBA " + encoding);
}

Status readMarch(const Fields& root, RevolutionParams& params) {
  BAKE_ASSIGN_OR_RETURN(const double margin, root.number("safetyMargin", 0, 1e30));
  params.safetyMargin = float(margin);
  BAKE_ASSIGN_OR_RETURN(const Fields in, root.object("march"));
  BAKE_ASSIGN_OR_RETURN(params.iterations, in.integer("iterations", 1, 4096));
  params.overRelaxation = fmt::kDefaultOverRelaxation;
  if (in.has("overRelaxation")) {
    // omega < 2 keeps the undo test of over-relaxed sphere tracing meaningful (Keinert et al. 2014).
    BAKE_ASSIGN_OR_RETURN(const double omega, in.number("overRelaxation", 1, 1.999));
    params.overRelaxation = float(omega);
  }
  params.hitEpsilon = fmt::kHitEpsilonTexels * params.shapeMap.texelSize;
  if (in.has("hitEpsilon")) {
    BAKE_ASSIGN_OR_RETURN(const double epsilon, in.number("hitEpsilon", 0, 1e30));
    params.hitEpsilon = float(epsilon);
  }
  return {};
}

Status readBands(const Fields& root, RevolutionParams& params) {
  if (!root.has("proxyBands")) return {};
  const nlohmann::json& list = root.at("proxyBands");
  if (!list.is_array()) return root.error("proxyBands", "must be a list of [hMin, hMax, rMax]");
  if (list.size() > std::size_t(fmt::kMaxProxyBands)) {
    return root.error("proxyBands", "holds " + std::to_string(list.size()) + " bands; at most " +
                                        std::to_string(fmt::kMaxProxyBands) + " are allowed");
  }
  for (std::size_t b = 0; b < list.size(); ++b) {
    const std::string field = "proxyBands[" + std::to_string(b) + "]";
    const nlohmann::json& band = list[b];
    if (!band.is_array() || band.size() != 3) return root.error(field, "must be [hMin, hMax, rMax]");
    std::array<float, 3> values{};
    for (std::size_t k = 0; k < 3; ++k) {
      if (!band[k].is_number() || !std::isfinite(band[k].get<double>()))
        return root.error(field, "must hold three finite numbers, not " + band.dump());
      values[k] = band[k].get<float>();
    }
    if (!(values[0] < values[1])) return root.error(field, "has hMin >= hMax: " + band.dump());
    if (!(values[2] > 0)) return root.error(field, "has rMax <= 0: " + band.dump());
    params.proxyBands.push_back(values);
  }
  return {};
}

Status readDisplacement(const Fields& root, const glb::Package& package, RevolutionParams& params) {
  if (!root.has(fmt::kDisplacementMap)) return {};
  BAKE_ASSIGN_OR_RETURN(const Fields in, root.object(fmt::kDisplacementMap));
  RevolutionParams::Displacement d;
  BAKE_ASSIGN_OR_RETURN(d.width, in.integer("width", 1, 16384));
  BAKE_ASSIGN_OR_RETURN(d.height, in.integer("height", 1, 16384));
  BAKE_ASSIGN_OR_RETURN(const double scale, in.number("derivativeScale", 0, 1e30));
  d.derivativeScale = float(scale);
  if (in.has("heightScale")) {
    BAKE_ASSIGN_OR_RETURN(const double height, in.number("heightScale", 0, 1e30));
    d.heightScale = float(height);
  }
  BAKE_ASSIGN_OR_RETURN(d.bufferView, in.integer(fmt::kBufferView, 0, 1 << 30));
  BAKE_RETURN_IF_ERROR(checkBufferView(in, "bufferView", d.bufferView, package,
                                       std::size_t(d.width) * std::size_t(d.height), 4,
                                       std::to_string(d.width) + "x" + std::to_string(d.height) + " RG unorm16"));
  params.displacement = d;
  return {};
}

Status readProjection(const Fields& root, const glb::Package& package, RevolutionParams& params) {
  const RevolutionParams::ShapeMap& map = params.shapeMap;
  params.sphereCentreH = 0.5f * (map.hMin + map.hMax());
  if (root.has("projection")) {
    BAKE_ASSIGN_OR_RETURN(const Fields in, root.object("projection"));
    BAKE_ASSIGN_OR_RETURN(const std::string type, in.string("type"));
    if (type == fmt::kProjectionCylindrical) {
      params.projection = Projection::Cylindrical;
    } else if (type == fmt::kProjectionSpherical) {
      params.projection = Projection::Spherical;
    } else if (type == fmt::kProjectionArcLength) {
      params.projection = Projection::ArcLength;
    } else {
      return in.error("type", "is \"" + type + "\"; known: cylindrical, spherical, arc-length");
    }
    if (in.has("repeat")) {
      const nlohmann::json& repeat = in.at("repeat");
      if (!repeat.is_array() || repeat.size() != 2 || !repeat[0].is_number() || !repeat[1].is_number() ||
          !std::isfinite(repeat[0].get<double>()) || !std::isfinite(repeat[1].get<double>()) ||
          !(repeat[0].get<double>() > 0) || !(repeat[1].get<double>() > 0)) {
        return in.error("repeat", "must be [u, v], two positive numbers, not " + repeat.dump());
      }
      params.repeat = {repeat[0].get<float>(), repeat[1].get<float>()};
    }
    if (in.has("sphereCentreH")) {
      BAKE_ASSIGN_OR_RETURN(const double centre, in.number("sphereCentreH", -1e30, 1e30));
      params.sphereCentreH = float(centre);
    }
  }
  if (root.has(fmt::kArcLengthMap)) {
    BAKE_ASSIGN_OR_RETURN(const Fields in, root.object(fmt::kArcLengthMap));
    BAKE_ASSIGN_OR_RETURN(const int view, in.integer(fmt::kBufferView, 0, 1 << 30));
    BAKE_RETURN_IF_ERROR(checkBufferView(in, "bufferView", view, package,
                                         std::size_t(map.width) * std::size_t(map.height), 2,
                                         "one R unorm16 per shape-map texel"));
    params.arcLengthBufferView = view;
  }
  if (params.projection == Projection::ArcLength && !params.arcLengthBufferView) {
    return root.error("arcLengthMap", "is missing; the arc-length projection reads it");
  }
  return {};
}

Result<std::array<double, 3>> triple(const Fields& in, const char* key, double lo, double hi) {
  const nlohmann::json& v = in.at(key);
  std::array<double, 3> out{};
  bool ok = v.is_array() && v.size() == 3;
  for (std::size_t k = 0; ok && k < 3; ++k) {
    ok = v[k].is_number() && std::isfinite(v[k].get<double>()) && v[k].get<double>() >= lo && v[k].get<double>() <= hi;
    if (ok) out[k] = v[k].get<double>();
  }
  if (!ok) return in.error(key, "must be three numbers in [" + numberText(lo) + ", " + numberText(hi) + "], not " + v.dump());
  return out;
}

// The grid of copies: counts, spacings no smaller than the box (copies never overlap, so the march's
// cells hold one copy each), mirrored axes.
Status readGridReplicas(const Fields& in, RevolutionParams& params) {
  RevolutionParams::Replicas& r = params.replicas;
  r.layout = RevolutionParams::Replicas::Layout::Grid;
  if (!in.has("count")) return in.error("count", "is missing");
  BAKE_ASSIGN_OR_RETURN(const auto count, triple(in, "count", 1, fmt::kMaxReplicasPerAxis));
  const std::array<float, 3> extent = {2 * params.shapeMap.rMax(), params.shapeMap.hMax() - params.shapeMap.hMin,
                                       2 * params.shapeMap.rMax()};
  for (std::size_t a = 0; a < 3; ++a) {
    if (count[a] != std::floor(count[a])) return in.error("count", "must hold whole numbers, not " + in.at("count").dump());
    r.count[a] = int(count[a]);
    r.spacing[a] = extent[a];
  }
  if (double(r.count[0]) * r.count[1] * r.count[2] > fmt::kMaxReplicas)
    return in.error("count", "asks for more than " + std::to_string(fmt::kMaxReplicas) + " copies");
  if (in.has("spacing")) {
    BAKE_ASSIGN_OR_RETURN(const auto spacing, triple(in, "spacing", 0, 1e30));
    for (std::size_t a = 0; a < 3; ++a) {
      if (spacing[a] < double(extent[a]) * (1 - 1e-6))
        return in.error("spacing", "is " + in.at("spacing").dump() + "; each must be at least the shape box's extent on its axis (" +
                                       numberText(extent[0]) + ", " + numberText(extent[1]) + ", " +
                                       numberText(extent[2]) + ") so copies do not overlap");
      r.spacing[a] = std::max(float(spacing[a]), extent[a]);
    }
  }
  if (in.has("mirror")) {
    const nlohmann::json& m = in.at("mirror");
    if (!m.is_array() || m.size() != 3 || !m[0].is_boolean() || !m[1].is_boolean() || !m[2].is_boolean())
      return in.error("mirror", "must be three booleans (x, y, z), not " + m.dump());
    for (std::size_t a = 0; a < 3; ++a) r.mirror[a] = m[a].get<bool>();
  }
  return {};
}

// The ring of copies: each copy's solid inside its wedge.
Status readRingReplicas(const Fields& in, RevolutionParams& params) {
  RevolutionParams::Replicas& r = params.replicas;
  r.layout = RevolutionParams::Replicas::Layout::Ring;
  BAKE_ASSIGN_OR_RETURN(r.ringCount, in.integer("count", 2, fmt::kMaxReplicasPerAxis));
  BAKE_ASSIGN_OR_RETURN(const double radius, in.positive("radius"));
  const double rMax = params.shapeMap.rMax();
  const double room = radius * std::sin(std::numbers::pi / r.ringCount);
  if (room < rMax * (1 - 1e-6))
    return in.error("radius", "is " + numberText(radius) + "; " + std::to_string(r.ringCount) +
                                  " copies of radius " + numberText(rMax) + " need a ring radius of at least " +
                                  numberText(rMax / std::sin(std::numbers::pi / r.ringCount)));
  r.ringRadius = float(radius);
  return {};
}

Status readReplicas(const Fields& root, RevolutionParams& params) {
  if (root.has(fmt::kSelfShadow)) {
    if (!root.at(fmt::kSelfShadow).is_boolean()) return root.error(fmt::kSelfShadow, "must be true or false");
    params.selfShadow = root.at(fmt::kSelfShadow).get<bool>();
  }
  if (!root.has(fmt::kReplicas)) return {};
  BAKE_ASSIGN_OR_RETURN(const Fields in, root.object(fmt::kReplicas));
  BAKE_ASSIGN_OR_RETURN(const std::string layout, in.string("layout"));
  if (layout == fmt::kLayoutGrid) return readGridReplicas(in, params);
  if (layout == fmt::kLayoutRing) return readRingReplicas(in, params);
  return in.error("layout", "is \"" + layout + "\"; known: grid, ring");
}

}  // namespace

int RevolutionParams::Replicas::total() const {
  switch (layout) {
    case Layout::One: return 1;
    case Layout::Grid: return count[0] * count[1] * count[2];
    case Layout::Ring: return ringCount;
  }
  return 1;
}

int RevolutionParams::Replicas::mostCellsCrossed() const {
  switch (layout) {
    case Layout::One: return 1;
    case Layout::Grid: return count[0] + count[1] + count[2] - 2;
    case Layout::Ring: return ringCount + 1;
  }
  return 1;
}

std::array<float, 3> RevolutionParams::boxMin() const {
  const float r = shapeMap.rMax();
  if (replicas.layout == Replicas::Layout::Ring) {
    const float outer = replicas.ringRadius + r;
    return {-outer, shapeMap.hMin, -outer};
  }
  return {-r, shapeMap.hMin, -r};
}

std::array<float, 3> RevolutionParams::boxMax() const {
  const float r = shapeMap.rMax();
  if (replicas.layout == Replicas::Layout::Ring) {
    const float outer = replicas.ringRadius + r;
    return {outer, shapeMap.hMax(), outer};
  }
  std::array<float, 3> hi{r, shapeMap.hMax(), r};
  if (replicas.layout == Replicas::Layout::Grid)
    for (std::size_t a = 0; a < 3; ++a) hi[a] += float(replicas.count[a] - 1) * replicas.spacing[a];
  return hi;
}

Result<RevolutionParams> parseRevolution(const nlohmann::json& extension, const glb::Package& package,
                                         const Location& where) {
  const Fields root(extension, "", where);
  if (!extension.is_object()) return invalidInput(std::string(fmt::kExtension) + " must be an object", where);
  BAKE_ASSIGN_OR_RETURN(const int version, root.integer("version", 1, 1 << 30));
  if (version != fmt::kVersion) {
    return unsupported(std::string(fmt::kExtension) + " version " + std::to_string(version) +
                           " is not known to this runtime (it reads version " + std::to_string(fmt::kVersion) + ")",
                       where);
  }
  RevolutionParams params;
  BAKE_RETURN_IF_ERROR(readShapeMap(root, package, params.shapeMap));
  BAKE_RETURN_IF_ERROR(readMarch(root, params));
  BAKE_RETURN_IF_ERROR(readBands(root, params));
  BAKE_RETURN_IF_ERROR(readDisplacement(root, package, params));
  BAKE_RETURN_IF_ERROR(readProjection(root, package, params));
  BAKE_RETURN_IF_ERROR(readReplicas(root, params));
  return params;
}

Result<std::optional<EmbeddedImage>> baseColourTextureOf(const nlohmann::json& material, const glb::Package& package,
                                                         const Location& where) {
  const nlohmann::json& info = jsonMember(jsonMember(material, "pbrMetallicRoughness"), "baseColorTexture");
  if (info.is_null()) return std::optional<EmbeddedImage>();
  const std::int64_t texture = jsonIndexOr(info, "index");
  if (texture < 0 || std::size_t(texture) >= package.textures.size())
    return invalidInput("pbrMetallicRoughness.baseColorTexture names no texture of the package", where);
  const std::int64_t image = jsonIndexOr(package.textures[std::size_t(texture)], "source");
  if (image < 0 || std::size_t(image) >= package.images.size())
    return invalidInput("texture " + std::to_string(texture) + " has no image source", where);
  const nlohmann::json& entry = package.images[std::size_t(image)];
  const std::int64_t view = jsonIndexOr(entry, "bufferView");
  if (view < 0 || std::size_t(view) >= package.blobs.size())
    return invalidInput("image " + std::to_string(image) + " (base colour) is not embedded in a bufferView", where);
  return std::optional<EmbeddedImage>(EmbeddedImage{std::size_t(image), std::size_t(view), jsonStringOr(entry, "mimeType", "")});
}

Status checkRevolutionPackage(const glb::Package& package, const std::string& name) {
  for (std::size_t m = 0; m < package.materials.size(); ++m) {
    const nlohmann::json& material = package.materials[m];
    if (!material.is_object() || !material.contains("extensions") || !material["extensions"].is_object() ||
        !material["extensions"].contains(fmt::kExtension))
      continue;
    const Location where{name, "material " + std::to_string(m)};
    BAKE_RETURN_IF_ERROR(parseRevolution(material["extensions"][fmt::kExtension], package, where).status());
    BAKE_RETURN_IF_ERROR(baseColourTextureOf(material, package, where).status());
  }
  return {};
}

}  // namespace bake::revolution
