// The SVG reader of svg_drawing.h. libxml2 parses the document (no network, no entity substitution,
// no DTD loading: a drawing is untrusted input); we walk its elements, turn each shape into SVG path
// data (SVG 1.1 §9 gives every basic shape as an equivalent path), parse that with the path-data reader
// (svg_path.cpp) in the element's user space, and map the pieces through the element's current
// transformation matrix and the caller's placement. Lines and Béziers map exactly under any affine
// map; a circular arc stays circular only under a similarity, so anything else (a non-uniform scale,
// a skew) applied to an arc is an error rather than a silent approximation.
#include "io/svg_drawing.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <optional>

#include <libxml/parser.h>
#include <libxml/tree.h>

#include "bake/core/atomic_file.h"
#include "io/svg_path.h"

namespace bake::svg {
namespace {

struct Document {
  std::string file;
  std::string where;  // the scene's JSON pointer
};

std::string attribute(xmlNode* node, const char* name) {
  xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!value) return {};
  std::string out(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return out;
}

bool hasAttribute(xmlNode* node, const char* name) { return xmlHasProp(node, reinterpret_cast<const xmlChar*>(name)) != nullptr; }

std::string tagOf(xmlNode* node) { return reinterpret_cast<const char*>(node->name); }

// "<path id="logo"> (line 12)", for messages.
std::string describeElement(xmlNode* node) {
  std::string text = "<" + tagOf(node);
  const std::string id = attribute(node, "id");
  if (!id.empty()) text += " id=\"" + id + "\"";
  return text + "> (line " + std::to_string(xmlGetLineNo(node)) + ")";
}

Status elementError(const Document& doc, xmlNode* node, const std::string& message) {
  return invalidInput(describeElement(node) + ": " + message, {doc.file, doc.where});
}

// A length of the root: a number with an optional absolute unit.
std::optional<Length> rootLength(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(value)) return std::nullopt;
  std::string unit(end);
  while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.back()))) unit.pop_back();
  for (const char* known : {"", "px", "mm", "cm", "in", "pt", "pc"})
    if (unit == known) return Length{value, unit};
  return std::nullopt;
}

// A number, optionally followed by "px" (user units); other units need a viewBox to mean anything.
std::optional<double> userLength(const std::string& text) {
  const std::optional<Length> length = rootLength(text);
  if (!length || !(length->unit.empty() || length->unit == "px")) return std::nullopt;
  return length->value;
}

Result<double> lengthAttribute(const Document& doc, xmlNode* node, const char* name, double fallback) {
  if (!hasAttribute(node, name)) return fallback;
  const std::optional<double> value = userLength(attribute(node, name));
  if (!value) return elementError(doc, node, std::string("attribute ") + name + " is not a number in user units");
  return *value;
}

// The numbers of a list ("1,2 3 4"), or nothing when one is malformed.
std::optional<std::vector<double>> numberList(const std::string& text) {
  std::vector<double> out;
  const char* s = text.c_str();
  while (*s) {
    while (*s && (std::isspace(static_cast<unsigned char>(*s)) || *s == ',')) ++s;
    if (!*s) break;
    char* end = nullptr;
    const double value = std::strtod(s, &end);
    if (end == s || !std::isfinite(value)) return std::nullopt;
    out.push_back(value);
    s = end;
  }
  return out;
}

// The transform attribute: a list of matrix/translate/scale/rotate/skewX/skewY, applied right to left.
Result<Affine> parseTransform(const Document& doc, xmlNode* node, const std::string& text) {
  Affine total;
  std::size_t i = 0;
  constexpr double kDegree = 3.14159265358979323846 / 180;
  while (true) {
    while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
    if (i >= text.size()) break;
    const std::size_t open = text.find('(', i), close = text.find(')', i);
    if (open == std::string::npos || close == std::string::npos || close < open)
      return elementError(doc, node, "transform \"" + text + "\" is malformed");
    std::string name = text.substr(i, open - i);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    const std::optional<std::vector<double>> args = numberList(text.substr(open + 1, close - open - 1));
    if (!args) return elementError(doc, node, "transform \"" + text + "\": the arguments of " + name + " are not numbers");
    const std::vector<double>& v = *args;
    const std::size_t n = v.size();
    Affine t;
    bool ok = true;
    if (name == "matrix" && n == 6) t = {v[0], v[1], v[2], v[3], v[4], v[5]};
    else if (name == "translate" && (n == 1 || n == 2)) t = {1, 0, 0, 1, v[0], n == 2 ? v[1] : 0};
    else if (name == "scale" && (n == 1 || n == 2)) t = {v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0};
    else if (name == "rotate" && (n == 1 || n == 3)) {
      const double cs = std::cos(v[0] * kDegree), sn = std::sin(v[0] * kDegree);
      const double cx = n == 3 ? v[1] : 0, cy = n == 3 ? v[2] : 0;
      t = {cs, sn, -sn, cs, cx - cs * cx + sn * cy, cy - sn * cx - cs * cy};
    } else if (name == "skewX" && n == 1) t = {1, 0, std::tan(v[0] * kDegree), 1, 0, 0};
    else if (name == "skewY" && n == 1) t = {1, std::tan(v[0] * kDegree), 0, 1, 0, 0};
    else ok = false;
    if (!ok) return elementError(doc, node, "transform \"" + text + "\": " + name + " with " + std::to_string(n) + " arguments is not an SVG transform");
    total = t.then(total);  // the list applies right to left: total = total ∘ t
    i = close + 1;
  }
  return total;
}

std::string pointText(double x, double y) {
  char text[80];
  std::snprintf(text, sizeof text, "%.17g %.17g ", x, y);
  return text;
}

// SVG 1.1 §9: each basic shape as path data. Empty: the element draws nothing (zero size).
Result<std::string> shapePathData(const Document& doc, xmlNode* node) {
  const std::string tag = tagOf(node);
  if (tag == "path") return attribute(node, "d");
  if (tag == "line") {
    BAKE_ASSIGN_OR_RETURN(const double x1, lengthAttribute(doc, node, "x1", 0));
    BAKE_ASSIGN_OR_RETURN(const double y1, lengthAttribute(doc, node, "y1", 0));
    BAKE_ASSIGN_OR_RETURN(const double x2, lengthAttribute(doc, node, "x2", 0));
    BAKE_ASSIGN_OR_RETURN(const double y2, lengthAttribute(doc, node, "y2", 0));
    return "M " + pointText(x1, y1) + "L " + pointText(x2, y2);
  }
  if (tag == "polyline" || tag == "polygon") {
    const std::optional<std::vector<double>> v = numberList(attribute(node, "points"));
    if (!v || v->size() % 2 != 0) return elementError(doc, node, "points must be pairs of numbers");
    if (v->size() < 4) return elementError(doc, node, "points needs at least 2 points");
    std::string d = "M " + pointText((*v)[0], (*v)[1]);
    for (std::size_t k = 2; k < v->size(); k += 2) d += "L " + pointText((*v)[k], (*v)[k + 1]);
    return tag == "polygon" ? d + "Z" : d;
  }
  if (tag == "circle" || tag == "ellipse") {
    BAKE_ASSIGN_OR_RETURN(const double cx, lengthAttribute(doc, node, "cx", 0));
    BAKE_ASSIGN_OR_RETURN(const double cy, lengthAttribute(doc, node, "cy", 0));
    double r = 0;
    if (tag == "circle") {
      BAKE_ASSIGN_OR_RETURN(r, lengthAttribute(doc, node, "r", 0));
    } else {
      BAKE_ASSIGN_OR_RETURN(const double rx, lengthAttribute(doc, node, "rx", 0));
      BAKE_ASSIGN_OR_RETURN(const double ry, lengthAttribute(doc, node, "ry", 0));
      if (std::abs(rx - ry) > 1e-12 * std::max(std::abs(rx), std::abs(ry)))
        return elementError(doc, node, "an ellipse with rx != ry: only lines and circular arcs are followed");
      r = rx;
    }
    if (r < 0) return elementError(doc, node, "a negative radius");
    if (r == 0) return std::string();
    const std::string radius = pointText(r, r);
    return "M " + pointText(cx + r, cy) + "A " + radius + "0 1 1 " + pointText(cx - r, cy) + "A " + radius + "0 1 1 " +
           pointText(cx + r, cy) + "Z";
  }
  if (tag == "rect") {
    BAKE_ASSIGN_OR_RETURN(const double x, lengthAttribute(doc, node, "x", 0));
    BAKE_ASSIGN_OR_RETURN(const double y, lengthAttribute(doc, node, "y", 0));
    BAKE_ASSIGN_OR_RETURN(const double w, lengthAttribute(doc, node, "width", 0));
    BAKE_ASSIGN_OR_RETURN(const double h, lengthAttribute(doc, node, "height", 0));
    if (w < 0 || h < 0) return elementError(doc, node, "a negative width or height");
    if (w == 0 || h == 0) return std::string();
    // SVG 1.1 §9.2: a missing rx or ry takes the other's value; both are clamped to half the side.
    double rx = -1, ry = -1;
    if (hasAttribute(node, "rx")) { BAKE_ASSIGN_OR_RETURN(rx, lengthAttribute(doc, node, "rx", 0)); }
    if (hasAttribute(node, "ry")) { BAKE_ASSIGN_OR_RETURN(ry, lengthAttribute(doc, node, "ry", 0)); }
    if (rx < 0) rx = ry;
    if (ry < 0) ry = rx;
    rx = std::clamp(rx, 0.0, w / 2);
    ry = std::clamp(ry, 0.0, h / 2);
    if (rx == 0 || ry == 0)
      return "M " + pointText(x, y) + "L " + pointText(x + w, y) + "L " + pointText(x + w, y + h) + "L " +
             pointText(x, y + h) + "Z";
    if (std::abs(rx - ry) > 1e-12 * std::max(rx, ry))
      return elementError(doc, node, "rounded corners with rx != ry are elliptical: only circular arcs are followed");
    const std::string radius = pointText(rx, rx) + "0 0 1 ";
    return "M " + pointText(x + rx, y) + "L " + pointText(x + w - rx, y) + "A " + radius + pointText(x + w, y + rx) +
           "L " + pointText(x + w, y + h - rx) + "A " + radius + pointText(x + w - rx, y + h) + "L " +
           pointText(x + rx, y + h) + "A " + radius + pointText(x, y + h - rx) + "L " + pointText(x, y + rx) + "A " +
           radius + pointText(x + rx, y) + "Z";
  }
  return elementError(doc, node, "internal: not a shape");
}

// Maps pieces through `m`. Arcs need a similarity (a uniform scale with a rotation and perhaps a
// reflection, which reverses the sweep).
Status transformPieces(const Document& doc, xmlNode* node, const Affine& m, std::vector<PathPiece>& pieces) {
  const double sx = std::hypot(m.a, m.b), sy = std::hypot(m.c, m.d);
  const bool similarity = std::abs(sx - sy) <= 1e-9 * std::max(sx, sy) &&
                          std::abs(m.a * m.c + m.b * m.d) <= 1e-9 * sx * sy && sx > 0;
  for (PathPiece& piece : pieces) {
    switch (piece.kind) {
      case PathPiece::Kind::Line:
      case PathPiece::Kind::Quadratic:
      case PathPiece::Kind::Cubic:
        for (Vec2& p : piece.p) p = m.apply(p);
        break;
      case PathPiece::Kind::Arc: {
        if (!similarity) return elementError(doc, node, "a transform that is not a similarity (a non-uniform scale or a skew) would turn a circular arc into an ellipse");
        const Vec2 direction = m.applyLinear({std::cos(piece.startAngle), std::sin(piece.startAngle)});
        piece.centre = m.apply(piece.centre);
        piece.radius *= sx;
        piece.startAngle = std::atan2(direction.v, direction.u);
        if (m.determinant() < 0) piece.sweep = -piece.sweep;
        for (Vec2& p : piece.p) p = m.apply(p);
        break;
      }
      case PathPiece::Kind::Spiral:
        return elementError(doc, node, "internal: SVG path data has no spirals");
    }
  }
  return Status::ok();
}

bool isShape(const std::string& tag) {
  return tag == "path" || tag == "line" || tag == "polyline" || tag == "polygon" || tag == "circle" || tag == "ellipse" ||
         tag == "rect";
}

// Elements that draw nothing or are not geometry we follow.
bool isSkipped(const std::string& tag) {
  return tag == "defs" || tag == "title" || tag == "desc" || tag == "metadata" || tag == "style" || tag == "symbol" ||
         tag == "clipPath" || tag == "mask" || tag == "pattern" || tag == "marker" || tag == "linearGradient" ||
         tag == "radialGradient" || tag == "filter" || tag == "script";
}

// An element of another namespace (an editor's metadata such as sodipodi:namedview): SVG renderers
// do not draw it, so neither do we.
bool isForeign(xmlNode* node) {
  return node->ns && node->ns->href &&
         std::string(reinterpret_cast<const char*>(node->ns->href)) != "http://www.w3.org/2000/svg";
}

Status walk(const Document& doc, xmlNode* parent, const Affine& parentMatrix, std::vector<Shape>& out) {
  for (xmlNode* node = parent->children; node; node = node->next) {
    if (node->type != XML_ELEMENT_NODE) continue;
    const std::string tag = tagOf(node);
    if (isSkipped(tag) || isForeign(node)) continue;
    Affine matrix = parentMatrix;
    if (hasAttribute(node, "transform")) {
      BAKE_ASSIGN_OR_RETURN(const Affine local, parseTransform(doc, node, attribute(node, "transform")));
      matrix = local.then(parentMatrix);
    }
    if (tag == "g" || tag == "a" || tag == "switch") {
      BAKE_RETURN_IF_ERROR(walk(doc, node, matrix, out));
    } else if (isShape(tag)) {
      BAKE_ASSIGN_OR_RETURN(const std::string data, shapePathData(doc, node));
      if (data.empty()) continue;
      Result<std::vector<std::vector<PathPiece>>> parsed = parsePathData(data, doc.file, doc.where);
      if (!parsed.isOk()) {
        const Status& status = parsed.status();
        return Status(status.code(), describeElement(node) + ": " + status.message(), status.where());
      }
      Shape shape{tag, attribute(node, "id"), describeElement(node), {}};
      for (std::vector<PathPiece>& pieces : parsed.value()) {
        BAKE_RETURN_IF_ERROR(transformPieces(doc, node, matrix, pieces));
        shape.subpaths.push_back(std::move(pieces));
      }
      out.push_back(std::move(shape));
    } else {
      return elementError(doc, node, "<" + tag + "> is not supported (convert it to paths)");
    }
  }
  return Status::ok();
}

Result<Frame> frameOf(const Document& doc, xmlNode* root) {
  Frame frame;
  frame.rootElement = describeElement(root);
  if (hasAttribute(root, "viewBox")) {
    const std::optional<std::vector<double>> v = numberList(attribute(root, "viewBox"));
    if (!v || v->size() != 4 || !((*v)[2] > 0) || !((*v)[3] > 0))
      return elementError(doc, root, "viewBox must be four numbers: min-x min-y width height, with width and height > 0");
    frame.viewBox = std::array<double, 4>{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
  }
  frame.widthText = attribute(root, "width");
  frame.heightText = attribute(root, "height");
  if (const std::optional<Length> width = rootLength(frame.widthText); width && width->value > 0) frame.width = width;
  if (const std::optional<Length> height = rootLength(frame.heightText); height && height->value > 0) frame.height = height;
  frame.preserveAspectRatio = attribute(root, "preserveAspectRatio");
  return frame;
}

// libxml2's global state is set up once, before any thread parses (its documentation asks for it).
void initialiseParser() {
  static std::once_flag once;
  std::call_once(once, [] { xmlInitParser(); });
}

}  // namespace

Result<std::vector<Shape>> readDrawing(const std::filesystem::path& file, const std::string& where, const Placement& placement) {
  const Document doc{file.string(), where};
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(file));
  if (bytes.empty()) return invalidInput("the SVG file is empty", {doc.file, where});
  initialiseParser();
  // No network, no entity substitution, no external DTD: an SVG file is untrusted input.
  xmlDoc* parsed = xmlReadMemory(reinterpret_cast<const char*>(bytes.data()), int(std::min<std::size_t>(bytes.size(), INT32_MAX)),
                                 doc.file.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  if (!parsed) {
    const xmlError* error = xmlGetLastError();
    std::string message = "not well-formed XML";
    if (error && error->message) {
      std::string text = error->message;
      while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
      message += " (line " + std::to_string(error->line) + ": " + text + ")";
    }
    return invalidInput(message, {doc.file, where});
  }
  std::unique_ptr<xmlDoc, void (*)(xmlDoc*)> owner(parsed, xmlFreeDoc);
  xmlNode* root = xmlDocGetRootElement(parsed);
  if (!root || tagOf(root) != "svg") return invalidInput("the root element is not <svg>", {doc.file, where});
  BAKE_ASSIGN_OR_RETURN(const Frame frame, frameOf(doc, root));
  BAKE_ASSIGN_OR_RETURN(const Affine placed, placement(frame));
  Affine rootMatrix = placed;
  if (hasAttribute(root, "transform")) {
    BAKE_ASSIGN_OR_RETURN(const Affine local, parseTransform(doc, root, attribute(root, "transform")));
    rootMatrix = local.then(placed);
  }
  std::vector<Shape> shapes;
  BAKE_RETURN_IF_ERROR(walk(doc, root, rootMatrix, shapes));
  return shapes;
}

}  // namespace bake::svg
