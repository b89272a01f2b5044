// The stroke list readers (paintstrokes/input/input.h; formats/paintstroke-input.md, -input.schema.json).
//
// JSON is read strictly in its structure (unknown keys are errors with the nearest known key
// suggested, wrong types name the stroke and control point) and leniently in its content: every
// control point field but "p" and "r" has a default, and the values' ranges are left to
// validate.cpp, which can repair what is harmless. A document the JSON parser refuses (a number
// overflowing a double such as 1e999, NaN, a truncated file) is parsed again by a SAX pass that only
// follows the path, so the message names the stroke and control point where parsing stopped.
//
// CSV: one header row naming the columns, then one control point per row; consecutive rows with the
// same stroke id form one stroke, in order; '#' starts a comment line. Lines, fields and numbers are
// read as in every CSV we take (core/csv_read.h): "nan" and "inf" are read (and refused by validation
// with their place) while "1.2.3" is an error here.
#include "paintstrokes/input/input.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <system_error>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "bake/core/limits.h"
#include "bake_formats/paintstrokes.h"
#include "core/csv_read.h"
#include "core/json_keys.h"
#include "core/json_read.h"

namespace bake::paintstrokes {
namespace {

using nlohmann::json;

// Follows the parser's position in the document so a parse error can be placed.
struct PathTracker : json::json_sax_t {
  struct Frame {
    bool array = false;
    std::size_t index = 0;
    std::string key;
  };
  std::vector<Frame> stack;
  std::string failure;
  std::size_t failedAt = 0;

  void valueDone() {
    if (!stack.empty() && stack.back().array) ++stack.back().index;
  }
  bool null() override { return valueDone(), true; }
  bool boolean(bool) override { return valueDone(), true; }
  bool number_integer(number_integer_t) override { return valueDone(), true; }
  bool number_unsigned(number_unsigned_t) override { return valueDone(), true; }
  bool number_float(number_float_t, const string_t&) override { return valueDone(), true; }
  bool string(string_t&) override { return valueDone(), true; }
  bool binary(binary_t&) override { return valueDone(), true; }
  bool start_object(std::size_t) override { return stack.push_back({}), true; }
  bool key(string_t& k) override { return stack.back().key = k, true; }
  bool end_object() override { return stack.pop_back(), valueDone(), true; }
  bool start_array(std::size_t) override { return stack.push_back({true, 0, {}}), true; }
  bool end_array() override { return stack.pop_back(), valueDone(), true; }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) override {
    failedAt = position;
    failure = ex.what();
    return false;
  }

  std::vector<std::string> path() const {
    std::vector<std::string> out;
    for (const Frame& f : stack) out.push_back(f.array ? std::to_string(f.index) : f.key);
    return out;
  }
};

bool isIndexText(const std::string& s) { return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }); }

// The index a path part names, when it is all digits and fits (a hostile document may have an object
// where the array should be, with a key of forty digits).
std::optional<std::size_t> indexOf(const std::string& part) {
  std::size_t value = 0;
  if (!isIndexText(part)) return std::nullopt;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
  if (error != std::errc() || end != part.data() + part.size()) return std::nullopt;
  return value;
}

// "stroke 12, control point 3" for a path strokes/12/points/3/..., else the JSON pointer.
std::string describePath(const std::vector<std::string>& path) {
  const std::optional<std::size_t> stroke = path.size() >= 2 ? indexOf(path[1]) : std::nullopt;
  if (path.size() >= 2 && path[0] == "strokes" && stroke) {
    const std::optional<std::size_t> point = path.size() >= 4 ? indexOf(path[3]) : std::nullopt;
    if (path.size() >= 4 && path[2] == "points" && point) {
      std::string element = pointElement(*stroke, *point);
      if (path.size() >= 5) element += ", \"" + path[4] + "\"";
      return element;
    }
    return strokeElement(*stroke) + (path.size() >= 3 ? ", \"" + path[2] + "\"" : "");
  }
  std::string pointer;
  for (const std::string& part : path) pointer = jsonPointerChild(pointer, part);
  return pointer;
}

Status parseFailure(const std::string& text, const std::string& source) {
  PathTracker tracker;
  json::sax_parse(text, &tracker);
  if (tracker.failure.empty()) return invalidInput("not valid JSON", {source, ""});
  const std::string element = describePath(tracker.path());
  return invalidInput("not valid JSON at byte " + std::to_string(tracker.failedAt) + ": " + tracker.failure,
                      {source, element.empty() ? "" : element});
}

struct Reader {
  std::string file;

  Status fail(const std::string& element, const std::string& message) const { return invalidInput(message, {file, element}); }

  Status keys(const json& node, const std::string& element, std::initializer_list<const char*> known) const {
    if (!node.is_object()) return fail(element, "must be an object");
    if (auto unknown = findUnknownKey(node, known)) return fail(element, unknown->message);
    return {};
  }
  // A member's number (JSON numbers are always finite), or `fallback` when it is missing.
  Result<double> number(const json& node, const char* key, const std::string& element, double fallback) const {
    if (!node.contains(key)) return fallback;
    if (!node[key].is_number()) return fail(element, std::string("\"") + key + "\" must be a number");
    return node[key].get<double>();
  }
  Result<Vec3d> vec3(const json& node, const char* key, const std::string& element, Vec3d fallback) const {
    if (!node.contains(key)) return fallback;
    const json& v = node[key];
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      return fail(element, std::string("\"") + key + "\" must be 3 numbers");
    return Vec3d{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
};

Result<StrokeStyle> readStyle(const Reader& r, const json& node, std::size_t index) {
  const std::string element = "style " + std::to_string(index);
  BAKE_RETURN_IF_ERROR(r.keys(node, element, {"name", "centreOpacity", "edgeOpacity", "volumeOpacity", "specular", "shininess",
                                              "ambient", "edgeSoftness"}));
  StrokeStyle s;
  s.name = "style" + std::to_string(index);
  if (node.contains("name")) {
    if (!node["name"].is_string()) return r.fail(element, "\"name\" must be a string");
    s.name = node["name"].get<std::string>();
  }
  BAKE_ASSIGN_OR_RETURN(s.centreOpacity, r.number(node, "centreOpacity", element, s.centreOpacity));
  BAKE_ASSIGN_OR_RETURN(s.edgeOpacity, r.number(node, "edgeOpacity", element, s.edgeOpacity));
  if (node.contains("volumeOpacity")) {
    const json& v = node["volumeOpacity"];
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      return r.fail(element, "\"volumeOpacity\" must be [across, along]");
    s.volumeAcross = v[0].get<double>();
    s.volumeAlong = v[1].get<double>();
  }
  BAKE_ASSIGN_OR_RETURN(s.specular, r.vec3(node, "specular", element, s.specular));
  BAKE_ASSIGN_OR_RETURN(s.shininess, r.number(node, "shininess", element, s.shininess));
  BAKE_ASSIGN_OR_RETURN(s.ambient, r.number(node, "ambient", element, s.ambient));
  BAKE_ASSIGN_OR_RETURN(s.edgeSoftness, r.number(node, "edgeSoftness", element, s.edgeSoftness));
  for (double v : {s.centreOpacity, s.edgeOpacity, s.volumeAcross, s.volumeAlong, s.specular[0], s.specular[1], s.specular[2], s.ambient})
    if (!(v >= 0 && v <= 1)) return r.fail(element, "opacities, specular and ambient must be within [0, 1]");
  if (!(s.shininess >= 0 && s.shininess <= 1e4)) return r.fail(element, "\"shininess\" must be within [0, 10000]");
  if (!(s.edgeSoftness >= 0 && s.edgeSoftness <= 64)) return r.fail(element, "\"edgeSoftness\" must be within [0, 64] pixels");
  return s;
}

Result<StrokePoint> readPoint(const Reader& r, const json& node, std::size_t stroke, std::size_t index) {
  const std::string element = pointElement(stroke, index);
  BAKE_RETURN_IF_ERROR(r.keys(node, element, {"p", "r", "colour", "opacity", "reflectance", "normal", "depth"}));
  if (!node.contains("p")) return r.fail(element, "\"p\" (the position) is missing");
  if (!node.contains("r")) return r.fail(element, "\"r\" (the radius) is missing");
  StrokePoint p;
  BAKE_ASSIGN_OR_RETURN(p.position, r.vec3(node, "p", element, p.position));
  BAKE_ASSIGN_OR_RETURN(p.radius, r.number(node, "r", element, p.radius));
  BAKE_ASSIGN_OR_RETURN(p.colour, r.vec3(node, "colour", element, p.colour));
  BAKE_ASSIGN_OR_RETURN(p.opacity, r.number(node, "opacity", element, p.opacity));
  BAKE_ASSIGN_OR_RETURN(p.reflectance, r.number(node, "reflectance", element, p.reflectance));
  BAKE_ASSIGN_OR_RETURN(p.globalNormal, r.vec3(node, "normal", element, p.globalNormal));
  BAKE_ASSIGN_OR_RETURN(p.depth, r.number(node, "depth", element, p.depth));
  return p;
}

Result<std::size_t> styleIndex(const Reader& r, const json& node, const StrokeSet& set, std::size_t stroke) {
  if (!node.contains("style")) return std::size_t(0);
  const json& style = node["style"];
  if (style.is_string()) {
    for (std::size_t k = 0; k < set.styles.size(); ++k)
      if (set.styles[k].name == style.get<std::string>()) return k;
    return r.fail(strokeElement(stroke), "style \"" + style.get<std::string>() + "\" is not defined");
  }
  if (!style.is_number_integer()) return r.fail(strokeElement(stroke), "\"style\" must be an index or a style name");
  if (style.get<std::int64_t>() < 0 || std::uint64_t(style.get<std::int64_t>()) >= set.styles.size())
    return r.fail(strokeElement(stroke), "style " + style.dump() + " does not exist (" + std::to_string(set.styles.size()) +
                                             " styles, indices from 0)");
  return std::size_t(style.get<std::int64_t>());
}

// The control points the document holds, counted before anything is built (the budget's check).
Status checkPointBudget(const Reader& r, const json& strokes) {
  std::uint64_t points = 0;
  for (const json& s : strokes)
    if (s.is_object() && s.contains("points") && s["points"].is_array()) points += s["points"].size();
  return checkBudget(Budget::ControlPoints, points, "control points", {r.file, "strokes"});
}

Status readStyles(const Reader& r, const json& doc, StrokeSet& set) {
  if (!doc.contains("styles")) {
    set.styles.emplace_back();
    return {};
  }
  const json& styles = doc["styles"];
  if (!styles.is_array() || styles.empty()) return r.fail("styles", "must be a non-empty list of styles");
  if (styles.size() > format::paintstrokes::kMaxStyles)
    return r.fail("styles", std::to_string(styles.size()) + " styles (at most " + std::to_string(format::paintstrokes::kMaxStyles) + ")");
  for (std::size_t k = 0; k < styles.size(); ++k) {
    BAKE_ASSIGN_OR_RETURN(StrokeStyle style, readStyle(r, styles[k], k));
    set.styles.push_back(std::move(style));
  }
  return {};
}

}  // namespace

std::string strokeElement(std::size_t stroke) { return "stroke " + std::to_string(stroke); }
std::string pointElement(std::size_t stroke, std::size_t point) {
  return strokeElement(stroke) + ", control point " + std::to_string(point);
}

Result<StrokeInput> parseStrokeJson(const std::string& text, const std::string& source) {
  BAKE_RETURN_IF_ERROR(checkJsonDepth(text, source));
  Result<json> parsed = parseJsonText(text, source);
  if (!parsed.isOk()) return parseFailure(text, source);  // names the stroke where parsing stopped
  json doc = std::move(parsed).value();
  const Reader r{source};
  BAKE_RETURN_IF_ERROR(r.keys(doc, "", {"$schema", "description", "version", "units", "styles", "strokes", "generators"}));
  if (!doc.contains("version") || !doc["version"].is_number_integer() || doc["version"].get<std::int64_t>() != 1)
    return r.fail("version", "must be 1");
  StrokeInput input;
  StrokeSet& set = input.set;
  if (doc.contains("units")) {
    if (!doc["units"].is_string()) return r.fail("units", "must be a string");
    set.units = doc["units"].get<std::string>();
  }
  BAKE_RETURN_IF_ERROR(readStyles(r, doc, set));
  if (doc.contains("generators")) {
    if (!doc["generators"].is_array()) return r.fail("generators", "must be a list");
    input.generators = doc["generators"];
  }
  if (!doc.contains("strokes") && input.generators.empty()) return r.fail("strokes", "is missing (and there are no generators)");
  const json& strokes = doc.contains("strokes") ? doc["strokes"] : json::array();
  if (!strokes.is_array()) return r.fail("strokes", "must be a list of strokes");
  BAKE_RETURN_IF_ERROR(checkPointBudget(r, strokes));
  set.strokes.reserve(strokes.size());
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    const json& node = strokes[s];
    BAKE_RETURN_IF_ERROR(r.keys(node, strokeElement(s), {"style", "points"}));
    Stroke stroke;
    BAKE_ASSIGN_OR_RETURN(stroke.style, styleIndex(r, node, set, s));
    if (!node.contains("points") || !node["points"].is_array())
      return r.fail(strokeElement(s), "\"points\" must be a list of control points");
    stroke.points.reserve(node["points"].size());
    for (std::size_t i = 0; i < node["points"].size(); ++i) {
      BAKE_ASSIGN_OR_RETURN(StrokePoint p, readPoint(r, node["points"][i], s, i));
      stroke.points.push_back(p);
    }
    set.strokes.push_back(std::move(stroke));
  }
  return input;
}

namespace {

enum Column { kStroke, kX, kY, kZ, kRadius, kR, kG, kB, kOpacity, kReflectance, kNx, kNy, kNz, kDepth, kStyle, kColumnCount };
constexpr const char* kColumnNames[kColumnCount] = {"stroke", "x",  "y",  "z",  "radius", "r",     "g",    "b",
                                                    "opacity", "reflectance", "nx", "ny", "nz", "depth", "style"};

}  // namespace

Result<StrokeInput> parseStrokeCsv(const std::string& text, const std::string& source) {
  const Reader r{source};
  const std::vector<CsvLine> lines = splitCsv(text, CsvComments::LineStart);
  std::size_t headerLine = 0;
  while (headerLine < lines.size() && lines[headerLine].fields.empty()) ++headerLine;
  if (headerLine >= lines.size()) return r.fail("", "no header row (expected at least stroke,x,y,z,radius)");
  std::array<int, kColumnCount> column;
  column.fill(-1);
  const std::vector<std::string>& header = lines[headerLine].fields;
  const std::string headerElement = "line " + std::to_string(lines[headerLine].number);
  for (std::size_t c = 0; c < header.size(); ++c) {
    const auto* name = std::find(std::begin(kColumnNames), std::end(kColumnNames), header[c]);
    if (name == std::end(kColumnNames)) return r.fail(headerElement, "unknown column \"" + header[c] + "\"");
    if (column[name - std::begin(kColumnNames)] >= 0) return r.fail(headerElement, "column \"" + header[c] + "\" appears twice");
    column[name - std::begin(kColumnNames)] = int(c);
  }
  for (int k : {kStroke, kX, kY, kZ, kRadius})
    if (column[k] < 0) return r.fail(headerElement, std::string("column \"") + kColumnNames[k] + "\" is missing");
  std::uint64_t rows = 0;
  for (std::size_t l = headerLine + 1; l < lines.size(); ++l) rows += !lines[l].fields.empty();
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::ControlPoints, rows, "control points", {source, ""}));

  StrokeInput input;
  StrokeSet& set = input.set;
  set.styles.emplace_back();
  std::map<std::string, std::size_t> seen;  // stroke id -> stroke index
  std::string currentId;
  for (std::size_t l = headerLine + 1; l < lines.size(); ++l) {
    const std::vector<std::string>& fields = lines[l].fields;
    if (fields.empty()) continue;
    const std::string lineElement = "line " + std::to_string(lines[l].number);
    if (fields.size() != header.size())
      return r.fail(lineElement, std::to_string(fields.size()) + " fields, the header names " + std::to_string(header.size()));
    const std::string& id = fields[column[kStroke]];
    if (id.empty()) return r.fail(lineElement, "empty stroke id");
    if (set.strokes.empty() || id != currentId) {
      if (seen.count(id))
        return r.fail(lineElement, "stroke id \"" + id + "\" appears again after other strokes (its rows must be consecutive)");
      seen[id] = set.strokes.size();
      set.strokes.emplace_back();
      currentId = id;
    }
    const std::size_t s = set.strokes.size() - 1, i = set.strokes.back().points.size();
    const std::string element = lineElement + " (" + pointElement(s, i) + ")";
    StrokePoint p;
    double values[kColumnCount] = {};
    for (int k = kX; k < kStyle; ++k) {
      if (column[k] < 0) continue;
      if (!parseCsvNumber(fields[column[k]], values[k]))
        return r.fail(element, std::string("column \"") + kColumnNames[k] + "\": \"" + fields[column[k]] + "\" is not a number");
    }
    p.position = {values[kX], values[kY], values[kZ]};
    p.radius = values[kRadius];
    if (column[kR] >= 0 || column[kG] >= 0 || column[kB] >= 0) {
      if (column[kR] < 0 || column[kG] < 0 || column[kB] < 0) return r.fail(lineElement, "columns r, g and b go together");
      p.colour = {values[kR], values[kG], values[kB]};
    }
    if (column[kOpacity] >= 0) p.opacity = values[kOpacity];
    if (column[kReflectance] >= 0) p.reflectance = values[kReflectance];
    if (column[kNx] >= 0 || column[kNy] >= 0 || column[kNz] >= 0) {
      if (column[kNx] < 0 || column[kNy] < 0 || column[kNz] < 0) return r.fail(lineElement, "columns nx, ny and nz go together");
      p.globalNormal = {values[kNx], values[kNy], values[kNz]};
    }
    if (column[kDepth] >= 0) p.depth = values[kDepth];
    if (column[kStyle] >= 0) {
      // A CSV defines no styles: a style column numbers default styles, created as they are named.
      double style = 0;
      if (!parseCsvNumber(fields[column[kStyle]], style) || style < 0 || style != std::floor(style) ||
          style >= format::paintstrokes::kMaxStyles)
        return r.fail(element, "style \"" + fields[column[kStyle]] + "\" is not an index from 0 to " +
                                   std::to_string(format::paintstrokes::kMaxStyles - 1));
      if (i > 0 && set.strokes.back().style != std::size_t(style))
        return r.fail(element, "the style changes within the stroke");
      set.strokes.back().style = std::size_t(style);
      while (set.styles.size() <= std::size_t(style)) {
        set.styles.emplace_back();
        set.styles.back().name = "style" + std::to_string(set.styles.size() - 1);
      }
    }
    set.strokes.back().points.push_back(p);
  }
  if (set.strokes.empty()) return r.fail("", "no control points after the header row");
  return input;
}

bool isStrokeList(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".json" || ext == ".csv";
}

Result<StrokeInput> readStrokeInput(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".json" && ext != ".csv") return unsupported("not a stroke list (.json or .csv)", {path.string(), ""});
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  if (bytes.empty()) return invalidInput("the file is empty", {path.string(), ""});
  const std::string text(withoutByteOrderMark({reinterpret_cast<const char*>(bytes.data()), bytes.size()}));
  Result<StrokeInput> input = ext == ".json" ? parseStrokeJson(text, path.string()) : parseStrokeCsv(text, path.string());
  if (input.isOk()) input->directory = path.parent_path();
  return input;
}

}  // namespace bake::paintstrokes
