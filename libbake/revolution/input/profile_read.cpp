// Profile readers for JSON and CSV (profile.h; formats/revolution.md). Both give contours of points
// with an optional bulge on the piece leaving each point (0: straight; tan(sweep / 4) of a circular
// arc, counter-clockwise positive). JSON: {"contours": [{"closed": bool, "points": [[r, h], ...],
// "bulges": [...]}]} or a bare list of points (one open contour). CSV (split as every CSV we read,
// core/csv_read.h): "r,h[,bulge]" per line, a blank line starts a new contour, '#' starts a comment
// anywhere on a line; a contour whose last point repeats the first is closed. Readers only parse: validateProfile checks the geometry.
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "bake/revolution/profile.h"
#include "core/csv_read.h"
#include "core/json_keys.h"
#include "core/json_read.h"

namespace bake::revolution {
namespace {

std::string contourPoint(std::size_t c, std::size_t i) {
  return "contour " + std::to_string(c) + ", point " + std::to_string(i);
}

// Pieces between consecutive points (and back to the first when closed).
Contour contourFrom(const std::vector<Point2>& points, const std::vector<double>& bulges, bool closed) {
  Contour contour;
  contour.closed = closed;
  const std::size_t n = points.size();
  const std::size_t pieces = n < 2 ? 0 : (closed ? n : n - 1);
  for (std::size_t i = 0; i < pieces; ++i) {
    Segment s;
    s.a = points[i];
    s.b = points[(i + 1) % n];
    s.bulge = i < bulges.size() ? bulges[i] : 0.0;
    contour.segments.push_back(s);
  }
  return contour;
}

double jsonNumber(const nlohmann::json& value) {
  if (value.is_number()) return value.get<double>();
  return std::numeric_limits<double>::quiet_NaN();  // reported as not finite by the caller
}

Status readJsonContour(const nlohmann::json& node, std::size_t c, const std::string& path, Profile& profile) {
  const nlohmann::json* pointsNode = &node;
  bool closed = false;
  std::vector<double> bulges;
  if (node.is_object()) {
    if (!node.contains("points") || !node["points"].is_array())
      return invalidInput("contour needs a \"points\" array", {path, "contour " + std::to_string(c)});
    if (const auto unknown = findUnknownKey(node, {"points", "closed", "bulges"}))
      return invalidInput(unknown->message, {path, "contour " + std::to_string(c)});
    pointsNode = &node["points"];
    if (node.contains("closed")) {
      if (!node["closed"].is_boolean())
        return invalidInput("\"closed\" must be true or false", {path, "contour " + std::to_string(c)});
      closed = node["closed"].get<bool>();
    }
    if (node.contains("bulges")) {
      if (!node["bulges"].is_array())
        return invalidInput("\"bulges\" must be an array", {path, "contour " + std::to_string(c)});
      for (std::size_t i = 0; i < node["bulges"].size(); ++i) {
        const double b = jsonNumber(node["bulges"][i]);
        if (!std::isfinite(b))
          return invalidInput("bulge is not a finite number", {path, contourPoint(c, i)});
        bulges.push_back(b);
      }
    }
  } else if (!node.is_array()) {
    return invalidInput("contour must be an object or a list of points", {path, "contour " + std::to_string(c)});
  }
  std::vector<Point2> points;
  for (std::size_t i = 0; i < pointsNode->size(); ++i) {
    const nlohmann::json& p = (*pointsNode)[i];
    if (!p.is_array() || p.size() != 2)
      return invalidInput("point must be [r, h]", {path, contourPoint(c, i)});
    const Point2 point{jsonNumber(p[0]), jsonNumber(p[1])};
    if (!std::isfinite(point.r) || !std::isfinite(point.h))
      return invalidInput("coordinate is not a finite number", {path, contourPoint(c, i)});
    points.push_back(point);
  }
  if (points.size() < 2) return invalidInput("contour needs at least two points", {path, "contour " + std::to_string(c)});
  const std::size_t pieces = closed ? points.size() : points.size() - 1;
  if (bulges.size() > points.size())
    return invalidInput("more bulges (" + std::to_string(bulges.size()) + ") than points", {path, "contour " + std::to_string(c)});
  if (!closed && bulges.size() == points.size() && bulges.back() != 0)
    return invalidInput("open contour: the last point starts no piece, its bulge must be 0",
                        {path, contourPoint(c, points.size() - 1)});
  (void)pieces;
  profile.contours.push_back(contourFrom(points, bulges, closed));
  return Status::ok();
}

}  // namespace

Result<Profile> readProfileJson(const std::string& path) {
  // readFileBytes refuses a directory (an ifstream on one fails with an exception or reads nothing).
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  BAKE_ASSIGN_OR_RETURN(nlohmann::json document, parseJsonText(text, path));
  Profile profile;
  profile.source = path;
  if (document.is_array() && (document.empty() || document[0].is_array())) {
    BAKE_RETURN_IF_ERROR(readJsonContour(document, 0, path, profile));
    return profile;
  }
  if (!document.is_object() || !document.contains("contours") || !document["contours"].is_array())
    return invalidInput("expected {\"contours\": [...]} or a list of [r, h] points", {path, ""});
  // Strict keys: a misspelt key would otherwise be ignored silently.
  if (const auto unknown = findUnknownKey(document, {"$schema", "description", "contours"}))
    return invalidInput(unknown->message, {path, ""});
  const nlohmann::json& contours = document["contours"];
  if (contours.empty()) return invalidInput("no contours", {path, "contours"});
  for (std::size_t c = 0; c < contours.size(); ++c) BAKE_RETURN_IF_ERROR(readJsonContour(contours[c], c, path, profile));
  return profile;
}

Result<Profile> readProfileCsv(const std::string& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::string_view text = withoutByteOrderMark({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
  Profile profile;
  profile.source = path;
  std::vector<Point2> points;
  std::vector<double> bulges;
  auto finishContour = [&] {
    if (points.size() >= 2) {
      const bool closed = points.size() >= 3 && points.front().r == points.back().r &&
                          points.front().h == points.back().h;
      if (closed) points.pop_back();
      profile.contours.push_back(contourFrom(points, bulges, closed));
    }
    points.clear();
    bulges.clear();
  };
  for (const CsvLine& line : splitCsv(text, CsvComments::Anywhere)) {
    if (line.fields.empty()) {
      if (!line.comment) finishContour();  // a comment line does not split a contour
      continue;
    }
    std::vector<double> values;
    bool bad = false;
    for (const std::string& field : line.fields) {
      double value = 0;
      if (!parseCsvNumber(field, value)) {
        bad = true;
        break;
      }
      values.push_back(value);
    }
    const std::string where = contourPoint(profile.contours.size(), points.size()) + " (line " +
                              std::to_string(line.number) + ")";
    if (bad || values.size() < 2 || values.size() > 3)
      return invalidInput("expected \"r,h\" or \"r,h,bulge\"", {path, where});
    for (double v : values)
      if (!std::isfinite(v)) return invalidInput("value is not a finite number", {path, where});
    points.push_back({values[0], values[1]});
    bulges.push_back(values.size() == 3 ? values[2] : 0.0);
  }
  finishContour();
  if (profile.contours.empty()) return invalidInput("no contour with two or more points", {path, ""});
  return profile;
}

}  // namespace bake::revolution
