// SVG profile reader (profile.h): the `d` attribute of the file's first <path>, or of the one with
// the given id, parsed by hand (SVG 1.1, "Paths", section 8.3): M L H V Z as straight pieces, A as a
// bulge arc when rx == ry (elliptical arcs are refused), C S Q T flattened by recursive de
// Casteljau subdivision until the control points lie within 1e-4 of the chord (the curve lies in
// their convex hull, so it is then within 1e-4 of the chord too). Each subpath is a contour; Z
// closes it. SVG's y grows downwards, so h = -y, which also turns SVG's positive-angle sweep
// (clockwise on screen) into a clockwise arc in (r, h): a negative bulge.
// The XML is read by a small scanner: tags and their quoted attributes, nothing else.
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/atomic_file.h"
#include "revolution/profile.h"

namespace bake::revolution {
namespace {

constexpr double kCurveTolerance = 1e-4;

struct Vec {
  double x = 0, y = 0;
};

// Attributes of the tag starting at `open` (just after "<path").
bool readAttributes(const std::string& text, std::size_t from, std::vector<std::pair<std::string, std::string>>& out) {
  std::size_t k = from;
  while (k < text.size()) {
    while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
    if (k >= text.size()) return false;
    if (text[k] == '>' || text[k] == '/') return true;
    const std::size_t nameStart = k;
    while (k < text.size() && text[k] != '=' && !std::isspace(static_cast<unsigned char>(text[k])) && text[k] != '>') ++k;
    const std::string name = text.substr(nameStart, k - nameStart);
    while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
    if (k >= text.size() || text[k] != '=') {
      out.push_back({name, ""});
      continue;
    }
    ++k;
    while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
    if (k >= text.size() || (text[k] != '"' && text[k] != '\'')) return false;
    const char quote = text[k++];
    const std::size_t end = text.find(quote, k);
    if (end == std::string::npos) return false;
    out.push_back({name, text.substr(k, end - k)});
    k = end + 1;
  }
  return false;
}

class PathParser {
 public:
  PathParser(const std::string& d, std::string path, std::string element)
      : d_(d), path_(std::move(path)), element_(std::move(element)) {}

  Result<Profile> parse() {
    Profile profile;
    profile.source = path_;
    char command = 0;
    while (true) {
      skipSeparators();
      if (k_ >= d_.size()) break;
      if (std::isalpha(static_cast<unsigned char>(d_[k_]))) {
        command = d_[k_++];
        ++commandIndex_;
      } else if (command == 0) {
        return error("path data must start with a command");
      } else if (command == 'M') {
        command = 'L';  // extra pairs after a moveto are linetos
      } else if (command == 'm') {
        command = 'l';
      } else if (command == 'Z' || command == 'z') {
        return error("numbers after Z");
      }
      BAKE_RETURN_IF_ERROR(apply(command));
    }
    finishSubpath(false);
    profile.contours = std::move(contours_);
    if (profile.contours.empty()) return invalidInput("path draws nothing", {path_, element_});
    return profile;
  }

 private:
  Status error(const std::string& message) const {
    return invalidInput(message, {path_, element_ + ", command " + std::to_string(commandIndex_) + " (character " +
                                             std::to_string(k_) + ")"});
  }

  void skipSeparators() {
    while (k_ < d_.size() && (std::isspace(static_cast<unsigned char>(d_[k_])) || d_[k_] == ',')) ++k_;
  }

  Status number(double& value) {
    skipSeparators();
    const std::size_t start = k_;
    if (k_ < d_.size() && (d_[k_] == '+' || d_[k_] == '-')) ++k_;
    bool digits = false, dot = false;
    while (k_ < d_.size() && (std::isdigit(static_cast<unsigned char>(d_[k_])) || (d_[k_] == '.' && !dot))) {
      if (d_[k_] == '.') dot = true;
      else digits = true;
      ++k_;
    }
    if (digits && k_ < d_.size() && (d_[k_] == 'e' || d_[k_] == 'E')) {
      std::size_t e = k_ + 1;
      if (e < d_.size() && (d_[e] == '+' || d_[e] == '-')) ++e;
      if (e < d_.size() && std::isdigit(static_cast<unsigned char>(d_[e]))) {
        k_ = e;
        while (k_ < d_.size() && std::isdigit(static_cast<unsigned char>(d_[k_]))) ++k_;
      }
    }
    if (!digits) {
      k_ = start;
      return error("expected a number");
    }
    value = std::strtod(d_.substr(start, k_ - start).c_str(), nullptr);
    if (!std::isfinite(value)) return error("number is not finite");
    return Status::ok();
  }

  Status flag(bool& value) {
    skipSeparators();
    if (k_ >= d_.size() || (d_[k_] != '0' && d_[k_] != '1')) return error("expected an arc flag 0 or 1");
    value = d_[k_++] == '1';
    return Status::ok();
  }

  Status point(bool relative, Vec& p) {
    BAKE_RETURN_IF_ERROR(number(p.x));
    BAKE_RETURN_IF_ERROR(number(p.y));
    if (relative) {
      p.x += current_.x;
      p.y += current_.y;
    }
    return Status::ok();
  }

  static Point2 toProfile(Vec p) { return {p.x, -p.y}; }

  void addPiece(Vec to, double bulge) {
    if (!open_) startSubpath(current_);
    Segment s;
    s.a = toProfile(current_);
    s.b = toProfile(to);
    s.bulge = bulge;
    pieces_.push_back(s);
    current_ = to;
  }

  void startSubpath(Vec at) {
    finishSubpath(false);
    open_ = true;
    start_ = at;
    current_ = at;
  }

  void finishSubpath(bool closed) {
    if (open_ && !pieces_.empty()) {
      Contour contour;
      contour.segments = std::move(pieces_);
      contour.closed = closed;
      contours_.push_back(std::move(contour));
    }
    pieces_.clear();
    open_ = false;
  }

  // Cubic Bezier flattened by halving until flat.
  void cubic(Vec p0, Vec p1, Vec p2, Vec p3, int depth) {
    const double cx = p3.x - p0.x, cy = p3.y - p0.y, chord = std::hypot(cx, cy);
    auto off = [&](Vec q) {
      if (chord == 0) return std::hypot(q.x - p0.x, q.y - p0.y);
      return std::abs((q.x - p0.x) * cy - (q.y - p0.y) * cx) / chord;
    };
    // Within the chord's span too, so a control point far along the line still splits.
    auto along = [&](Vec q) {
      if (chord == 0) return true;
      const double t = ((q.x - p0.x) * cx + (q.y - p0.y) * cy) / (chord * chord);
      return t >= -kCurveTolerance / chord && t <= 1 + kCurveTolerance / chord;
    };
    if (depth >= 24 || (off(p1) <= kCurveTolerance && off(p2) <= kCurveTolerance && along(p1) && along(p2))) {
      addPiece(p3, 0.0);
      return;
    }
    auto mid = [](Vec a, Vec b) { return Vec{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; };
    const Vec a = mid(p0, p1), b = mid(p1, p2), c = mid(p2, p3);
    const Vec ab = mid(a, b), bc = mid(b, c), m = mid(ab, bc);
    cubic(p0, a, ab, m, depth + 1);
    cubic(m, bc, c, p3, depth + 1);
  }

  Status arc(bool relative) {
    double rx, ry, rotation;
    bool large, sweep;
    Vec to;
    BAKE_RETURN_IF_ERROR(number(rx));
    BAKE_RETURN_IF_ERROR(number(ry));
    BAKE_RETURN_IF_ERROR(number(rotation));
    BAKE_RETURN_IF_ERROR(flag(large));
    BAKE_RETURN_IF_ERROR(flag(sweep));
    BAKE_RETURN_IF_ERROR(point(relative, to));
    rx = std::abs(rx);
    ry = std::abs(ry);
    const double chord = std::hypot(to.x - current_.x, to.y - current_.y);
    if (chord == 0) return Status::ok();  // SVG: an arc to the current point is omitted
    if (rx == 0 || ry == 0) {
      addPiece(to, 0.0);  // SVG: a zero radius draws a line
      return Status::ok();
    }
    if (std::abs(rx - ry) > 1e-9 * std::max(rx, ry))
      return unsupported("elliptical arcs are not supported (rx " + std::to_string(rx) + " != ry " +
                             std::to_string(ry) + ")",
                         {path_, element_ + ", command " + std::to_string(commandIndex_)});
    // Too small a radius is scaled up until the chord fits (SVG implementation notes, F.6.6).
    const double radius = std::max(rx, 0.5 * chord);
    const double minor = 2.0 * std::asin(std::min(1.0, chord / (2.0 * radius)));
    const double angle = large ? 2.0 * std::numbers::pi - minor : minor;
    const double bulge = std::tan(angle / 4.0);
    addPiece(to, sweep ? -bulge : bulge);
    return Status::ok();
  }

  Status apply(char command) {
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    Vec p;
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M':
        BAKE_RETURN_IF_ERROR(point(relative, p));
        startSubpath(p);
        lastControl_ = p;
        return Status::ok();
      case 'L':
        BAKE_RETURN_IF_ERROR(point(relative, p));
        addPiece(p, 0.0);
        break;
      case 'H': {
        double x;
        BAKE_RETURN_IF_ERROR(number(x));
        addPiece({relative ? current_.x + x : x, current_.y}, 0.0);
        break;
      }
      case 'V': {
        double y;
        BAKE_RETURN_IF_ERROR(number(y));
        addPiece({current_.x, relative ? current_.y + y : y}, 0.0);
        break;
      }
      case 'Z':
        if (open_) {
          if (current_.x != start_.x || current_.y != start_.y) addPiece(start_, 0.0);
          const Vec start = start_;
          finishSubpath(true);
          current_ = start;
        }
        lastControl_ = current_;
        return Status::ok();
      case 'A':
        BAKE_RETURN_IF_ERROR(arc(relative));
        break;
      case 'C': case 'S': {
        Vec c1, c2, end;
        const char upper = char(std::toupper(static_cast<unsigned char>(command)));
        if (upper == 'C') BAKE_RETURN_IF_ERROR(point(relative, c1));
        else c1 = previousCubic_ ? Vec{2 * current_.x - lastControl_.x, 2 * current_.y - lastControl_.y} : current_;
        BAKE_RETURN_IF_ERROR(point(relative, c2));
        BAKE_RETURN_IF_ERROR(point(relative, end));
        cubic(current_, c1, c2, end, 0);
        lastControl_ = c2;
        previousCubic_ = true;
        previousQuadratic_ = false;
        return Status::ok();
      }
      case 'Q': case 'T': {
        Vec q, end;
        const char upper = char(std::toupper(static_cast<unsigned char>(command)));
        if (upper == 'Q') BAKE_RETURN_IF_ERROR(point(relative, q));
        else q = previousQuadratic_ ? Vec{2 * current_.x - lastControl_.x, 2 * current_.y - lastControl_.y} : current_;
        BAKE_RETURN_IF_ERROR(point(relative, end));
        const Vec start = current_;
        // The same curve as a cubic: controls two thirds of the way to the quadratic's control.
        const Vec c1{start.x + 2.0 / 3.0 * (q.x - start.x), start.y + 2.0 / 3.0 * (q.y - start.y)};
        const Vec c2{end.x + 2.0 / 3.0 * (q.x - end.x), end.y + 2.0 / 3.0 * (q.y - end.y)};
        cubic(start, c1, c2, end, 0);
        lastControl_ = q;
        previousQuadratic_ = true;
        previousCubic_ = false;
        return Status::ok();
      }
      default:
        return error(std::string("unknown path command '") + command + "'");
    }
    previousCubic_ = previousQuadratic_ = false;
    lastControl_ = current_;
    return Status::ok();
  }

  const std::string& d_;
  std::string path_, element_;
  std::size_t k_ = 0;
  int commandIndex_ = -1;
  Vec current_, start_, lastControl_;
  bool open_ = false, previousCubic_ = false, previousQuadratic_ = false;
  std::vector<Segment> pieces_;
  std::vector<Contour> contours_;
};

}  // namespace

Result<Profile> readProfileSvg(const std::string& path, const std::string& pathId) {
  // readFileBytes refuses a directory (an ifstream reads one as an empty file).
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::string text(bytes.begin(), bytes.end());
  std::size_t at = 0;
  while ((at = text.find("<path", at)) != std::string::npos) {
    const std::size_t after = at + 5;
    at = after;
    if (after < text.size() && !std::isspace(static_cast<unsigned char>(text[after])) && text[after] != '/' &&
        text[after] != '>')
      continue;  // another tag name that starts with "path"
    std::vector<std::pair<std::string, std::string>> attributes;
    if (!readAttributes(text, after, attributes))
      return invalidInput("malformed <path> tag", {path, "character " + std::to_string(after)});
    std::string id, d;
    bool hasD = false;
    for (const auto& [name, value] : attributes) {
      if (name == "id") id = value;
      if (name == "d") {
        d = value;
        hasD = true;
      }
    }
    if (!pathId.empty() && id != pathId) continue;
    const std::string element = id.empty() ? "path" : "path '" + id + "'";
    if (!hasD) return invalidInput("<path> has no d attribute", {path, element});
    return PathParser(d, path, element).parse();
  }
  if (!pathId.empty()) return invalidInput("no <path> with id '" + pathId + "'", {path, ""});
  return invalidInput("no <path> element", {path, ""});
}

}  // namespace bake::revolution
