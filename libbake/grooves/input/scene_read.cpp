// The groove scene reader (grooves/input/scene.h; formats/groove-scene.md, formats/groove-scene.schema.json).
// Strict like the other readers: unknown keys are errors with the nearest known key as a suggestion,
// and every error names the file and the JSON pointer of the element at fault.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bake/core/atomic_file.h"
#include "bake/core/limits.h"
#include "core/json_keys.h"
#include "core/json_read.h"
#include "grooves/input/generators.h"
#include "grooves/input/scene.h"
#include "grooves/input/svg_file.h"
#include "io/svg_path.h"

namespace bake::grooves {
namespace {

using nlohmann::json;
constexpr double kDegree = std::numbers::pi / 180;

std::string child(const std::string& parent, const std::string& key) { return jsonPointerChild(parent, key); }
std::string child(const std::string& parent, std::size_t index) { return jsonPointerChild(parent, index); }

struct Reader : JsonReader {
  // The scene file's folder, for the drawings an `svgFile` path names (null: the scene came from
  // memory, and naming files is an error); the files read are listed in `filesRead`.
  const std::filesystem::path* directory = nullptr;
  std::vector<std::string>* filesRead = nullptr;

  Result<Vec2> point(const json& node, const std::string& where) const {
    if (!node.is_array() || node.size() != 2) return error(where, "must be a pair of numbers [u, v]");
    BAKE_ASSIGN_OR_RETURN(const double u, number(node[0], child(where, std::size_t(0))));
    BAKE_ASSIGN_OR_RETURN(const double v, number(node[1], child(where, std::size_t(1))));
    return Vec2{u, v};
  }
  Result<std::vector<Vec2>> points(const json& node, const std::string& where, std::size_t minimum) const {
    if (!node.is_array()) return error(where, "must be a list of points");
    if (node.size() < minimum) return error(where, "needs at least " + std::to_string(minimum) + " points");
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < node.size(); ++i) {
      BAKE_ASSIGN_OR_RETURN(const Vec2 p, point(node[i], child(where, i)));
      out.push_back(p);
    }
    return out;
  }
  Status colour(const json& node, const std::string& where, double out[3], bool unit) const {
    if (!node.is_array() || node.size() != 3) return error(where, "must be [r, g, b]");
    for (std::size_t i = 0; i < 3; ++i) {
      BAKE_ASSIGN_OR_RETURN(out[i], number(node[i], child(where, i)));
      if (out[i] < 0 || (unit && out[i] > 1)) return error(child(where, i), "must be within [0, 1]");
    }
    return Status::ok();
  }
  Result<double> positive(const json& node, const std::string& where) const {
    BAKE_ASSIGN_OR_RETURN(const double x, number(node, where));
    if (!(x > 0)) return error(where, "must be > 0");
    return x;
  }
  Result<int> count(const json& node, const std::string& where) const {
    if (!node.is_number_integer() || node.get<long long>() < 1 || node.get<long long>() > 1000000)
      return error(where, "must be an integer within 1 .. 1000000");
    return int(node.get<long long>());
  }
};

// A groove waiting for its flattening: from the list or from a generator.
struct PendingGroove {
  std::string name;
  std::string pointer;
  std::size_t profile = 0, material = 0;
  Perturbation perturbation;
  std::vector<PathPiece> pieces;
};

Result<std::size_t> lookup(const Reader& r, const json& node, const std::string& where, const std::vector<std::string>& names,
                           const char* what) {
  BAKE_ASSIGN_OR_RETURN(const std::string name, r.string(node, where));
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return r.error(where, std::string("unknown ") + what + " \"" + name + "\"");
  return std::size_t(it - names.begin());
}

// {"svgFile": {"file": PATH relative to the scene, "origin": [u, v], "scale": s}}: every shape of the
// drawing becomes a groove (svg_file.h).
Result<std::vector<std::vector<PathPiece>>> readSvgFilePath(const Reader& r, const json& node, const std::string& at) {
  BAKE_RETURN_IF_ERROR(r.object(node, at, {"file", "origin", "scale"}));
  if (!node.contains("file")) return r.error(child(at, "file"), "is missing");
  BAKE_ASSIGN_OR_RETURN(const std::string name, r.string(node["file"], child(at, "file")));
  SvgPlacement placement;
  if (node.contains("origin")) { BAKE_ASSIGN_OR_RETURN(placement.origin, r.point(node["origin"], child(at, "origin"))); }
  if (node.contains("scale")) { BAKE_ASSIGN_OR_RETURN(placement.scale, r.positive(node["scale"], child(at, "scale"))); }
  if (!r.directory) return r.error(child(at, "file"), "names a drawing, but the scene was not read from a file");
  const std::filesystem::path file = *r.directory / name;
  if (r.filesRead) r.filesRead->push_back(file.string());
  return readSvgFile(file, placement, child(at, "file"));
}

Result<std::vector<std::vector<PathPiece>>> readPath(const Reader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"line", "polyline", "arc", "spiral", "quadratic", "cubic", "svg", "svgFile"}));
  if (node.size() != 1) return r.error(where, "must have exactly one of line, polyline, arc, spiral, quadratic, cubic, svg, svgFile");
  const std::string kind = node.begin().key();
  const json& value = node.begin().value();
  const std::string at = child(where, kind);
  std::vector<PathPiece> pieces;
  if (kind == "line" || kind == "polyline") {
    BAKE_ASSIGN_OR_RETURN(const std::vector<Vec2> pts, r.points(value, at, 2));
    if (kind == "line" && pts.size() != 2) return r.error(at, "a line has exactly 2 points");
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      PathPiece piece;
      piece.p[0] = pts[i];
      piece.p[1] = pts[i + 1];
      pieces.push_back(piece);
    }
  } else if (kind == "quadratic" || kind == "cubic") {
    const std::size_t n = kind == "quadratic" ? 3 : 4;
    BAKE_ASSIGN_OR_RETURN(const std::vector<Vec2> pts, r.points(value, at, n));
    if (pts.size() != n) return r.error(at, "needs exactly " + std::to_string(n) + " points");
    PathPiece piece;
    piece.kind = n == 3 ? PathPiece::Kind::Quadratic : PathPiece::Kind::Cubic;
    std::copy(pts.begin(), pts.end(), piece.p);
    pieces.push_back(piece);
  } else if (kind == "arc") {
    BAKE_RETURN_IF_ERROR(r.object(value, at, {"centre", "radius", "start", "end"}));
    for (const char* key : {"centre", "radius", "start", "end"})
      if (!value.contains(key)) return r.error(child(at, key), "is missing");
    PathPiece piece;
    piece.kind = PathPiece::Kind::Arc;
    BAKE_ASSIGN_OR_RETURN(piece.centre, r.point(value["centre"], child(at, "centre")));
    BAKE_ASSIGN_OR_RETURN(piece.radius, r.positive(value["radius"], child(at, "radius")));
    BAKE_ASSIGN_OR_RETURN(const double start, r.number(value["start"], child(at, "start")));
    BAKE_ASSIGN_OR_RETURN(const double end, r.number(value["end"], child(at, "end")));
    piece.startAngle = start * kDegree;
    piece.sweep = (end - start) * kDegree;  // end < start: clockwise
    pieces.push_back(piece);
  } else if (kind == "spiral") {
    BAKE_RETURN_IF_ERROR(r.object(value, at, {"centre", "startRadius", "pitch", "turns", "startAngle"}));
    for (const char* key : {"centre", "startRadius", "pitch", "turns"})
      if (!value.contains(key)) return r.error(child(at, key), "is missing");
    PathPiece piece;
    piece.kind = PathPiece::Kind::Spiral;
    BAKE_ASSIGN_OR_RETURN(piece.centre, r.point(value["centre"], child(at, "centre")));
    BAKE_ASSIGN_OR_RETURN(piece.radius, r.number(value["startRadius"], child(at, "startRadius")));
    if (piece.radius < 0) return r.error(child(at, "startRadius"), "must be >= 0");
    BAKE_ASSIGN_OR_RETURN(piece.pitch, r.number(value["pitch"], child(at, "pitch")));
    BAKE_ASSIGN_OR_RETURN(const double turns, r.positive(value["turns"], child(at, "turns")));
    if (piece.radius + piece.pitch * turns < 0) return r.error(at, "the radius would become negative (startRadius + pitch x turns < 0)");
    double startAngle = 0;
    if (value.contains("startAngle")) { BAKE_ASSIGN_OR_RETURN(startAngle, r.number(value["startAngle"], child(at, "startAngle"))); }
    piece.startAngle = startAngle * kDegree;
    piece.sweep = 2 * std::numbers::pi * turns;
    pieces.push_back(piece);
  } else if (kind == "svg") {
    BAKE_ASSIGN_OR_RETURN(const std::string data, r.string(value, at));
    return svg::parsePathData(data, r.file, at);
  } else {
    return readSvgFilePath(r, value, at);
  }
  return std::vector<std::vector<PathPiece>>{pieces};
}

Result<Perturbation> readPerturbation(const Reader& r, const json& node, const std::string& where) {
  BAKE_RETURN_IF_ERROR(r.object(node, where, {"kind", "amplitude", "wavelength", "phase"}));
  for (const char* key : {"kind", "amplitude", "wavelength"})
    if (!node.contains(key)) return r.error(child(where, key), "is missing");
  Perturbation p;
  BAKE_ASSIGN_OR_RETURN(const std::string kind, r.string(node["kind"], child(where, "kind")));
  if (kind == "scale") p.kind = Perturbation::Kind::Scale;
  else if (kind == "offset") p.kind = Perturbation::Kind::Offset;
  else return r.error(child(where, "kind"), "must be \"scale\" or \"offset\"");
  BAKE_ASSIGN_OR_RETURN(p.amplitude, r.number(node["amplitude"], child(where, "amplitude")));
  if (p.amplitude < 0 || (p.kind == Perturbation::Kind::Scale && p.amplitude >= 1))
    return r.error(child(where, "amplitude"), p.kind == Perturbation::Kind::Scale ? "must be within [0, 1)" : "must be >= 0");
  BAKE_ASSIGN_OR_RETURN(p.wavelength, r.positive(node["wavelength"], child(where, "wavelength")));
  if (node.contains("phase")) { BAKE_ASSIGN_OR_RETURN(p.phase, r.number(node["phase"], child(where, "phase"))); }
  return p;
}

}  // namespace

Result<GrooveScene> parseGrooveScene(const std::string& jsonText, const std::string& source,
                                     const std::filesystem::path* directory) {
  GrooveScene scene;
  Reader r{{source}};
  r.directory = directory;
  r.filesRead = &scene.files;
  BAKE_ASSIGN_OR_RETURN(json doc, parseJsonText(jsonText, source));
  BAKE_RETURN_IF_ERROR(r.object(doc, "", {"$schema", "description", "version", "units", "domain", "wrap",
                                          "flatteningTolerance", "profiles", "materials", "base", "grooves", "generators"}));
  for (const char* key : {"version", "domain", "profiles", "materials", "base"})
    if (!doc.contains(key)) return r.error(child("", key), "is missing");
  if (!doc["version"].is_number_integer() || doc["version"].get<long long>() != 1) return r.error("/version", "must be 1");
  scene.source = source;
  if (doc.contains("units")) { BAKE_ASSIGN_OR_RETURN(scene.units, r.string(doc["units"], "/units")); }
  BAKE_RETURN_IF_ERROR(r.object(doc["domain"], "/domain", {"size"}));
  if (!doc["domain"].contains("size")) return r.error("/domain/size", "is missing");
  BAKE_ASSIGN_OR_RETURN(const Vec2 size, r.point(doc["domain"]["size"], "/domain/size"));
  if (!(size.u > 0) || !(size.v > 0)) return r.error("/domain/size", "must be > 0 both ways");
  scene.domain[0] = size.u;
  scene.domain[1] = size.v;
  if (doc.contains("wrap")) {
    BAKE_ASSIGN_OR_RETURN(const std::string wrap, r.string(doc["wrap"], "/wrap"));
    if (wrap != "none" && wrap != "repeat") return r.error("/wrap", "must be \"none\" or \"repeat\"");
    scene.wrapRepeat = wrap == "repeat";
  }
  // Profiles.
  if (!doc["profiles"].is_object() || doc["profiles"].empty()) return r.error("/profiles", "must be a non-empty object of named profiles");
  std::vector<std::string> profileNames, materialNames;
  for (const auto& [name, node] : doc["profiles"].items()) {
    const std::string at = child("/profiles", name);
    BAKE_RETURN_IF_ERROR(r.object(node, at, {"description", "points"}));
    if (!node.contains("points")) return r.error(child(at, "points"), "is missing");
    Profile profile;
    profile.name = name;
    BAKE_ASSIGN_OR_RETURN(profile.points, r.points(node["points"], child(at, "points"), 0));
    BAKE_RETURN_IF_ERROR(validateProfile(profile, source).atElement(at));
    scene.profiles.push_back(profile);
    profileNames.push_back(name);
  }
  // Materials.
  if (!doc["materials"].is_object() || doc["materials"].empty()) return r.error("/materials", "must be a non-empty object of named materials");
  for (const auto& [name, node] : doc["materials"].items()) {
    const std::string at = child("/materials", name);
    BAKE_RETURN_IF_ERROR(r.object(node, at, {"description", "albedo", "specular", "shininess", "mirror"}));
    Material m;
    m.name = name;
    if (node.contains("albedo")) BAKE_RETURN_IF_ERROR(r.colour(node["albedo"], child(at, "albedo"), m.albedo, true));
    if (node.contains("specular")) BAKE_RETURN_IF_ERROR(r.colour(node["specular"], child(at, "specular"), m.specular, true));
    if (node.contains("shininess")) { BAKE_ASSIGN_OR_RETURN(m.shininess, r.positive(node["shininess"], child(at, "shininess"))); }
    if (node.contains("mirror")) {
      m.hasMirror = true;
      BAKE_RETURN_IF_ERROR(r.colour(node["mirror"], child(at, "mirror"), m.mirror, true));
    }
    scene.materials.push_back(m);
    materialNames.push_back(name);
  }
  BAKE_ASSIGN_OR_RETURN(scene.baseMaterial, lookup(r, doc["base"], "/base", materialNames, "material"));
  double smallestWidth = std::numeric_limits<double>::infinity();
  for (const Profile& p : scene.profiles) smallestWidth = std::min(smallestWidth, p.wmax);
  scene.flatteningTolerance = 1e-3 * smallestWidth;
  if (doc.contains("flatteningTolerance")) { BAKE_ASSIGN_OR_RETURN(scene.flatteningTolerance, r.positive(doc["flatteningTolerance"], "/flatteningTolerance")); }

  std::vector<PendingGroove> pending;
  if (doc.contains("grooves")) {
    if (!doc["grooves"].is_array()) return r.error("/grooves", "must be a list");
    for (std::size_t g = 0; g < doc["grooves"].size(); ++g) {
      const json& node = doc["grooves"][g];
      const std::string at = child("/grooves", g);
      BAKE_RETURN_IF_ERROR(r.object(node, at, {"name", "profile", "material", "perturbation", "path"}));
      for (const char* key : {"profile", "path"})
        if (!node.contains(key)) return r.error(child(at, key), "is missing");
      PendingGroove groove;
      groove.pointer = at;
      if (node.contains("name")) { BAKE_ASSIGN_OR_RETURN(groove.name, r.string(node["name"], child(at, "name"))); }
      BAKE_ASSIGN_OR_RETURN(groove.profile, lookup(r, node["profile"], child(at, "profile"), profileNames, "profile"));
      groove.material = scene.baseMaterial;
      if (node.contains("material")) { BAKE_ASSIGN_OR_RETURN(groove.material, lookup(r, node["material"], child(at, "material"), materialNames, "material")); }
      if (node.contains("perturbation")) { BAKE_ASSIGN_OR_RETURN(groove.perturbation, readPerturbation(r, node["perturbation"], child(at, "perturbation"))); }
      BAKE_ASSIGN_OR_RETURN(const auto subpaths, readPath(r, node["path"], child(at, "path")));
      for (std::size_t k = 0; k < subpaths.size(); ++k) {
        PendingGroove one = groove;
        if (subpaths.size() > 1 && !one.name.empty()) one.name += "#" + std::to_string(k);
        one.pieces = subpaths[k];
        pending.push_back(one);
      }
    }
  }
  if (doc.contains("generators")) {
    if (!doc["generators"].is_array()) return r.error("/generators", "must be a list");
    for (std::size_t k = 0; k < doc["generators"].size(); ++k) {
      const std::string at0 = child("/generators", k);
      const json& node0 = doc["generators"][k];
      BAKE_RETURN_IF_ERROR(r.object(node0, at0, {"tiles", "record"}));
      if (node0.size() != 1) return r.error(at0, "must have exactly one of tiles, record");
      const std::string kind = node0.begin().key();
      const json& node = node0.begin().value();
      const std::string at = child(at0, kind);
      PendingGroove groove;
      groove.pointer = at;
      if (kind == "tiles")
        BAKE_RETURN_IF_ERROR(r.object(node, at, {"origin", "tileSize", "count", "bond", "profile", "material"}));
      else
        BAKE_RETURN_IF_ERROR(r.object(node, at, {"centre", "innerRadius", "outerRadius", "grooves", "profile", "material"}));
      if (!node.contains("profile")) return r.error(child(at, "profile"), "is missing");
      BAKE_ASSIGN_OR_RETURN(groove.profile, lookup(r, node["profile"], child(at, "profile"), profileNames, "profile"));
      groove.material = scene.baseMaterial;
      if (node.contains("material")) { BAKE_ASSIGN_OR_RETURN(groove.material, lookup(r, node["material"], child(at, "material"), materialNames, "material")); }
      if (kind == "tiles") {
        for (const char* key : {"tileSize", "count"})
          if (!node.contains(key)) return r.error(child(at, key), "is missing");
        Vec2 origin;
        if (node.contains("origin")) { BAKE_ASSIGN_OR_RETURN(origin, r.point(node["origin"], child(at, "origin"))); }
        BAKE_ASSIGN_OR_RETURN(const Vec2 tile, r.point(node["tileSize"], child(at, "tileSize")));
        if (!(tile.u > 0) || !(tile.v > 0)) return r.error(child(at, "tileSize"), "must be > 0 both ways");
        if (!node["count"].is_array() || node["count"].size() != 2) return r.error(child(at, "count"), "must be [nx, ny]");
        BAKE_ASSIGN_OR_RETURN(const int nx, r.count(node["count"][0], child(child(at, "count"), std::size_t(0))));
        BAKE_ASSIGN_OR_RETURN(const int ny, r.count(node["count"][1], child(child(at, "count"), std::size_t(1))));
        std::string bond = "stack";
        if (node.contains("bond")) { BAKE_ASSIGN_OR_RETURN(bond, r.string(node["bond"], child(at, "bond"))); }
        if (bond != "stack" && bond != "running") return r.error(child(at, "bond"), "must be \"stack\" or \"running\"");
        // Before generating: a running bond has a joint per tile, so counts of a million each way
        // would mean 10^12 grooves.
        const std::uint64_t lines = bond == "running" ? std::uint64_t(ny + 1) + std::uint64_t(nx + 1) * std::uint64_t(ny)
                                                      : std::uint64_t(nx + 1) + std::uint64_t(ny + 1);
        BAKE_RETURN_IF_ERROR(checkBudget(Budget::Grooves, pending.size() + lines, "grooves", {source, child(at, "count")}));
        // Every grout line crosses or meets every line of the other direction: each meeting is a
        // special-case record of the grid, and each costs the grid build an intersection.
        const std::uint64_t crossings = bond == "running" ? 2 * std::uint64_t(nx + 1) * std::uint64_t(ny)
                                                          : std::uint64_t(nx + 1) * std::uint64_t(ny + 1);
        BAKE_RETURN_IF_ERROR(checkBudget(Budget::Crossings, crossings, "groove crossings", {source, child(at, "count")}));
        for (auto& pieces : tileGroutLines(origin, tile, nx, ny, bond == "running")) {
          PendingGroove one = groove;
          one.pieces = pieces;
          pending.push_back(one);
        }
      } else {
        for (const char* key : {"centre", "innerRadius", "outerRadius", "grooves"})
          if (!node.contains(key)) return r.error(child(at, key), "is missing");
        BAKE_ASSIGN_OR_RETURN(const Vec2 centre, r.point(node["centre"], child(at, "centre")));
        BAKE_ASSIGN_OR_RETURN(const double r0, r.number(node["innerRadius"], child(at, "innerRadius")));
        BAKE_ASSIGN_OR_RETURN(const double r1, r.number(node["outerRadius"], child(at, "outerRadius")));
        if (!(r0 >= 0) || !(r1 > r0)) return r.error(at, "needs 0 <= innerRadius < outerRadius");
        BAKE_ASSIGN_OR_RETURN(const double n, r.positive(node["grooves"], child(at, "grooves")));
        groove.pieces = {recordSpiral(centre, r0, r1, n)};
        pending.push_back(groove);
      }
    }
  }
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::Grooves, pending.size(), "grooves", {source, ""}));
  // Flattening (flatten.cpp), each groove checked against its own half-width.
  for (std::size_t g = 0; g < pending.size(); ++g) {
    const PendingGroove& p = pending[g];
    Groove groove;
    groove.name = p.name;
    groove.profile = p.profile;
    groove.material = p.material;
    groove.perturbation = p.perturbation;
    grooveBounds(scene.profiles[p.profile], p.perturbation, groove.wmax, groove.hmax, groove.dmax);
    groove.firstPrimitive = scene.primitives.size();
    std::string label = "groove " + std::to_string(g);
    if (!p.name.empty()) label += " (\"" + p.name + "\")";
    BAKE_RETURN_IF_ERROR(
        flattenPath(p.pieces, scene.flatteningTolerance, groove.wmax, g, label, source, scene.primitives).atElement(p.pointer));
    groove.primitiveCount = scene.primitives.size() - groove.firstPrimitive;
    scene.grooves.push_back(groove);
  }
  BAKE_RETURN_IF_ERROR(finishScene(scene));
  return scene;
}

Result<GrooveScene> readGrooveScene(const std::string& path) {
  // readFileBytes refuses a directory (an ifstream reads one as an empty file).
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  return parseGrooveScene(std::string(bytes.begin(), bytes.end()), path, &directory);
}

}  // namespace bake::grooves
