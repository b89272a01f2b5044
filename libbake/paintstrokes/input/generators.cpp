// The "generators" entries of a stroke list (formats/paintstroke-generators.md): one JSON object per
// generator, {"type": "grow", ...} or {"type": "tree", ...}, whose other members are the settings'
// fields in camelCase. Reading never throws whatever the JSON holds (wrong types are errors naming the
// member, core/json_keys.h); unknown members are refused with the nearest known name suggested, so a
// typo does not silently fall back to a default. The settings' own checks (grow.cpp, tree.cpp) then
// run, their element renamed to the entry's member ("generators[2].count").
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "bake/paintstrokes/generators.h"
#include "bake_formats/paintstrokes.h"
#include "core/json_keys.h"

namespace bake::paintstrokes {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// `key` inside `element`: a JSON pointer child when the caller names entries by pointer
// ("/generators/2", "generators/2"), otherwise a dotted member ("generators[2].count").
std::string member(const std::string& element, const std::string& key) {
  if (element.find('/') != std::string::npos) return jsonPointerChild(element, key);
  return element.empty() ? key : element + "." + key;
}

struct EntryReader {
  const json& entry;
  Location where;

  Status error(const std::string& key, const std::string& message) const {
    return invalidInput(message, {where.file, member(where.element, key)});
  }
  bool has(const char* key) const { return entry.contains(key); }

  Status number(const char* key, double& out) const {
    if (!has(key)) return Status::ok();
    const json& node = entry[key];
    if (!node.is_number() || !std::isfinite(node.get<double>())) return error(key, "must be a finite number");
    out = node.get<double>();
    return Status::ok();
  }
  // An integer within [lo, hi] (an integral number like 1e4 is accepted).
  Status integer(const char* key, std::uint64_t lo, std::uint64_t hi, std::uint64_t& out) const {
    if (!has(key)) return Status::ok();
    const json& node = entry[key];
    const std::string range = "must be an integer within " + std::to_string(lo) + " .. " + std::to_string(hi);
    if (node.is_number_unsigned()) {
      out = node.get<std::uint64_t>();
    } else if (node.is_number_integer()) {  // signed: a parser may store 300 so
      if (node.get<std::int64_t>() < 0) return error(key, range + ", not " + node.dump());
      out = std::uint64_t(node.get<std::int64_t>());
    } else if (node.is_number_float()) {
      const double x = node.get<double>();
      if (!(x >= 0) || !(x < 0x1.0p64) || x != std::floor(x)) return error(key, range + ", not " + node.dump());
      out = std::uint64_t(x);
    } else {
      return error(key, range);
    }
    if (out < lo || out > hi) return error(key, range + ", not " + std::to_string(out));
    return Status::ok();
  }
  Status integer(const char* key, int lo, int hi, int& out) const {
    std::uint64_t value = std::uint64_t(std::max(out, 0));
    BAKE_RETURN_IF_ERROR(integer(key, std::uint64_t(lo), std::uint64_t(hi), value));
    out = int(value);
    return Status::ok();
  }
  Status size(const char* key, std::uint64_t lo, std::uint64_t hi, std::size_t& out) const {
    std::uint64_t value = out;
    BAKE_RETURN_IF_ERROR(integer(key, lo, hi, value));
    out = std::size_t(value);
    return Status::ok();
  }
  Status vector(const char* key, Vec3d& out) const {
    if (!has(key)) return Status::ok();
    const json& node = entry[key];
    if (!node.is_array() || node.size() != 3) return error(key, "must be a list of three numbers");
    for (std::size_t i = 0; i < 3; ++i) {
      if (!node[i].is_number() || !std::isfinite(node[i].get<double>())) {
        return error(key, "component " + std::to_string(i) + " must be a finite number");
      }
      out[i] = node[i].get<double>();
    }
    return Status::ok();
  }
  Status string(const char* key, std::string& out) const {
    if (!has(key)) return Status::ok();
    if (!entry[key].is_string()) return error(key, "must be a string");
    out = entry[key].get<std::string>();
    return Status::ok();
  }
  Status known(std::initializer_list<const char*> keys) const {
    if (const auto unknown = findUnknownKey(entry, keys)) return error(unknown->key, unknown->message);
    return Status::ok();
  }
  // A settings check's failure (element = the field) located at this entry.
  Status located(const Status& status) const {
    return status.isOk() ? status : error(status.where().element, status.message());
  }
};

constexpr std::uint64_t kMaxSeed = std::numeric_limits<std::uint64_t>::max();

// A file named by the entry: relative paths are relative to the input file's folder.
std::string resolve(const fs::path& inputDirectory, const std::string& path) {
  const fs::path p(path);
  return (p.is_absolute() ? p : inputDirectory / p).lexically_normal().string();
}

// "texture:PATH" with PATH resolved, recorded as an input; anything else unchanged.
std::string resolveTexture(const fs::path& inputDirectory, const std::string& source, std::vector<std::string>& textures) {
  if (source.rfind("texture:", 0) != 0 || source.size() == 8) return source;
  const std::string path = resolve(inputDirectory, source.substr(8));
  textures.push_back(path);
  return "texture:" + path;
}

Result<GrowSettings> readGrow(const EntryReader& r, const fs::path& inputDirectory, std::vector<std::string>& files) {
  BAKE_RETURN_IF_ERROR(r.known({"type", "mesh", "count", "length", "radius", "tipRadius", "bend", "bendDirection",
                                "pointsPerStroke", "rootColour", "tipColour", "jitter", "lengthFrom", "colourFrom",
                                "style", "seed"}));
  GrowSettings s;
  if (!r.has("mesh")) return r.error("mesh", "is missing (the mesh to grow strokes on, relative to the input file)");
  BAKE_RETURN_IF_ERROR(r.string("mesh", s.mesh));
  if (s.mesh.empty()) return r.error("mesh", "must name a mesh file");
  BAKE_RETURN_IF_ERROR(r.size("count", 1, kMaxGeneratedStrokes, s.count));
  BAKE_RETURN_IF_ERROR(r.number("length", s.length));
  BAKE_RETURN_IF_ERROR(r.number("radius", s.radius));
  BAKE_RETURN_IF_ERROR(r.number("tipRadius", s.tipRadius));
  BAKE_RETURN_IF_ERROR(r.number("bend", s.bend));
  BAKE_RETURN_IF_ERROR(r.vector("bendDirection", s.bendDirection));
  BAKE_RETURN_IF_ERROR(r.integer("pointsPerStroke", 2, 64, s.pointsPerStroke));
  BAKE_RETURN_IF_ERROR(r.vector("rootColour", s.rootColour));
  BAKE_RETURN_IF_ERROR(r.vector("tipColour", s.tipColour));
  BAKE_RETURN_IF_ERROR(r.number("jitter", s.jitter));
  BAKE_RETURN_IF_ERROR(r.string("lengthFrom", s.lengthFrom));
  BAKE_RETURN_IF_ERROR(r.string("colourFrom", s.colourFrom));
  BAKE_RETURN_IF_ERROR(r.size("style", 0, format::paintstrokes::kMaxStyles - 1, s.style));
  BAKE_RETURN_IF_ERROR(r.integer("seed", 0, kMaxSeed, s.seed));
  BAKE_RETURN_IF_ERROR(r.located(checkGrowSettings(s)));
  s.mesh = resolve(inputDirectory, s.mesh);
  files.push_back(s.mesh);
  s.lengthFrom = resolveTexture(inputDirectory, s.lengthFrom, files);
  s.colourFrom = resolveTexture(inputDirectory, s.colourFrom, files);
  return s;
}

Result<TreeSettings> readTree(const EntryReader& r) {
  BAKE_RETURN_IF_ERROR(r.known({"type", "depth", "branching", "height", "trunkRadius", "lengthRatio", "radiusRatio",
                                "spreadDegrees", "pointsPerStroke", "barkColour", "twigColour", "origin", "style", "seed"}));
  TreeSettings s;
  BAKE_RETURN_IF_ERROR(r.integer("depth", 0, 20, s.depth));
  BAKE_RETURN_IF_ERROR(r.integer("branching", 1, 16, s.branching));
  BAKE_RETURN_IF_ERROR(r.number("height", s.height));
  BAKE_RETURN_IF_ERROR(r.number("trunkRadius", s.trunkRadius));
  BAKE_RETURN_IF_ERROR(r.number("lengthRatio", s.lengthRatio));
  BAKE_RETURN_IF_ERROR(r.number("radiusRatio", s.radiusRatio));
  BAKE_RETURN_IF_ERROR(r.number("spreadDegrees", s.spreadDegrees));
  BAKE_RETURN_IF_ERROR(r.integer("pointsPerStroke", 2, 64, s.pointsPerStroke));
  BAKE_RETURN_IF_ERROR(r.vector("barkColour", s.barkColour));
  BAKE_RETURN_IF_ERROR(r.vector("twigColour", s.twigColour));
  BAKE_RETURN_IF_ERROR(r.vector("origin", s.origin));
  BAKE_RETURN_IF_ERROR(r.size("style", 0, format::paintstrokes::kMaxStyles - 1, s.style));
  BAKE_RETURN_IF_ERROR(r.integer("seed", 0, kMaxSeed, s.seed));
  BAKE_RETURN_IF_ERROR(r.located(checkTreeSettings(s)));
  return s;
}

// Appends a grown-on mesh's primitive to the one mesh handed back (several grow entries, several
// primitives; the same file grown on twice is kept once).
void keepMesh(glb::Mesh&& mesh, bool alreadyGrownOn, std::optional<glb::Mesh>& into) {
  if (!into) {
    into = std::move(mesh);
  } else if (!alreadyGrownOn) {
    for (glb::Primitive& p : mesh.primitives) into->primitives.push_back(std::move(p));
  }
}

}  // namespace

std::vector<std::string> generatorFiles(const nlohmann::json& entry, const std::filesystem::path& inputDirectory) {
  std::vector<std::string> files;
  if (!entry.is_object() || entry.value("type", json()) != "grow") return files;
  const EntryReader r{entry, Location{}};
  if (!readGrow(r, inputDirectory, files).isOk()) files.clear();
  return files;
}

Status runGenerator(const nlohmann::json& entry, const std::filesystem::path& inputDirectory, const Location& where,
                    const Budgets& budgets, StrokeSet& into, std::vector<std::string>& inputs,
                    std::optional<glb::Mesh>* grownOn) {
  const EntryReader r{entry, where};
  if (!entry.is_object()) return invalidInput("must be a JSON object with a \"type\"", where);
  if (!r.has("type")) return r.error("type", "is missing (\"grow\" or \"tree\")");
  std::string type;
  BAKE_RETURN_IF_ERROR(r.string("type", type));
  if (type != "grow" && type != "tree") {
    return r.error("type", "unknown generator type \"" + type + "\" (expected \"grow\" or \"tree\")");
  }

  // The styles are the input's; an index beyond them is this entry's fault (checked here, before
  // growing, when the caller has read its styles already; validation checks every stroke in any case).
  const auto checkStyle = [&](std::size_t style) {
    if (into.styles.empty() || style < into.styles.size()) return Status::ok();
    return r.error("style", "is " + std::to_string(style) + " but the input has " + std::to_string(into.styles.size()) +
                                " style(s)");
  };
  StrokeSet made;
  if (type == "grow") {
    std::vector<std::string> files;
    BAKE_ASSIGN_OR_RETURN(const GrowSettings settings, readGrow(r, inputDirectory, files));
    BAKE_RETURN_IF_ERROR(checkStyle(settings.style));
    const bool alreadyGrownOn = std::find(inputs.begin(), inputs.end(), settings.mesh) != inputs.end();
    glb::Mesh mesh;
    auto grown = growOnMesh(settings, budgets, grownOn ? &mesh : nullptr);
    // Settings errors name the field; the entry's member then (the budget check on count, say).
    if (!grown.isOk() && grown.status().where().file.empty()) return r.located(grown.status());
    BAKE_ASSIGN_OR_RETURN(made, std::move(grown));
    if (grownOn) keepMesh(std::move(mesh), alreadyGrownOn, *grownOn);
    inputs.insert(inputs.end(), files.begin(), files.end());
  } else {
    BAKE_ASSIGN_OR_RETURN(const TreeSettings settings, readTree(r));
    BAKE_RETURN_IF_ERROR(checkStyle(settings.style));
    const std::uint64_t points = treeStrokeCount(settings) * std::uint64_t(settings.pointsPerStroke);
    if (points > budgets.controlPoints) {
      return r.error("depth", std::to_string(points) + " control points exceed the budget of " +
                                  std::to_string(budgets.controlPoints) + " (raise it with --budget control-points=N)");
    }
    made = growTree(settings);
  }
  into.strokes.insert(into.strokes.end(), std::make_move_iterator(made.strokes.begin()),
                      std::make_move_iterator(made.strokes.end()));
  return Status::ok();
}

}  // namespace bake::paintstrokes
