// SVG 1.1 path data (https://www.w3.org/TR/SVG11/paths.html#PathData) in the caller's units: M/m L/l
// H/h V/v C/c S/s Q/q T/t A/a Z/z. Arcs must be circular (rx == ry; the rotation is then
// irrelevant); their centre follows the endpoint-to-centre conversion of SVG 1.1 appendix F.6.5, with
// a too-small radius scaled up as F.6.6 says. Every subpath becomes its own list of pieces; Z closes it.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "io/svg_path.h"

namespace bake::svg {
namespace {

struct Tokens {
  const std::string& s;
  std::size_t i = 0;

  void skip() {
    while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',')) ++i;
  }
  bool atNumber() {
    skip();
    return i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '-' || s[i] == '+' || s[i] == '.');
  }
  std::string problem = {};  // why the last number failed, for the message
  bool number(double& out) {
    if (!atNumber()) return expected();
    const char* begin = s.c_str() + i;
    char* end = nullptr;
    out = std::strtod(begin, &end);
    if (end == begin) return expected();
    if (!std::isfinite(out)) {
      problem = "the number at character " + std::to_string(i) + " is not finite";
      return false;
    }
    i += std::size_t(end - begin);
    return true;
  }
  bool expected() {
    problem = i < s.size() ? "expected a number at character " + std::to_string(i) : "the path data ends early";
    return false;
  }
  bool flag(bool& out) {
    skip();
    if (i < s.size() && (s[i] == '0' || s[i] == '1')) {
      out = s[i++] == '1';
      return true;
    }
    return false;
  }
};

std::string showPoint(Vec2 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g)", p.u, p.v);
  return text;
}

}  // namespace

Result<std::vector<std::vector<PathPiece>>> parsePathData(const std::string& data, const std::string& source,
                                                          const std::string& where) {
  std::vector<std::vector<PathPiece>> subpaths;
  std::vector<PathPiece> current;
  Tokens t{data};
  Vec2 cur, start, lastControl;
  char lastCommand = 0;
  std::size_t commandIndex = 0;
  bool started = false;
  auto finish = [&] {
    if (!current.empty()) subpaths.push_back(current);
    current.clear();
  };
  auto fail = [&](const std::string& message) {
    const std::string why = t.problem.empty() ? "" : " (" + t.problem + ")";
    return invalidInput("svg path command " + std::to_string(commandIndex) + " at " + showPoint(cur) + ": " + message + why,
                        {source, where});
  };
  auto line = [&](Vec2 to) {
    PathPiece p;
    p.p[0] = cur;
    p.p[1] = to;
    current.push_back(p);
    cur = to;
  };
  t.skip();
  char command = 0;
  while (true) {
    t.skip();
    if (t.i >= data.size()) break;
    if (std::isalpha(static_cast<unsigned char>(data[t.i]))) {
      command = data[t.i++];
    } else if (command == 0 || command == 'Z' || command == 'z') {
      return fail("expected a command letter");
    } else if (command == 'M') {
      command = 'L';  // coordinates after a moveto are implicit linetos
    } else if (command == 'm') {
      command = 'l';
    }
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const char upper = char(std::toupper(static_cast<unsigned char>(command)));
    if (!started && upper != 'M') return fail("path data must start with M or m");
    auto read = [&](double& x) { return t.number(x); };
    auto readPoint = [&](Vec2& p) {
      if (!read(p.u) || !read(p.v)) return false;
      if (rel) p = {p.u + cur.u, p.v + cur.v};
      return true;
    };
    switch (upper) {
      case 'M': {
        Vec2 p;
        if (!readPoint(p)) return fail("M needs a point");
        finish();
        cur = start = p;
        started = true;
        break;
      }
      case 'Z':
        if (cur.u != start.u || cur.v != start.v) line(start);
        finish();
        cur = start;
        break;
      case 'L': {
        Vec2 p;
        if (!readPoint(p)) return fail("L needs a point");
        line(p);
        break;
      }
      case 'H': {
        double x;
        if (!read(x)) return fail("H needs a number");
        line({rel ? cur.u + x : x, cur.v});
        break;
      }
      case 'V': {
        double y;
        if (!read(y)) return fail("V needs a number");
        line({cur.u, rel ? cur.v + y : y});
        break;
      }
      case 'C':
      case 'S': {
        PathPiece p;
        p.kind = PathPiece::Kind::Cubic;
        p.p[0] = cur;
        if (upper == 'C') {
          if (!readPoint(p.p[1])) return fail("C needs three points");
        } else {
          const char lu = char(std::toupper(static_cast<unsigned char>(lastCommand)));
          p.p[1] = (lu == 'C' || lu == 'S') ? Vec2{2 * cur.u - lastControl.u, 2 * cur.v - lastControl.v} : cur;
        }
        if (!readPoint(p.p[2]) || !readPoint(p.p[3])) return fail(std::string(1, upper) + " needs more points");
        lastControl = p.p[2];
        current.push_back(p);
        cur = p.p[3];
        break;
      }
      case 'Q':
      case 'T': {
        PathPiece p;
        p.kind = PathPiece::Kind::Quadratic;
        p.p[0] = cur;
        if (upper == 'Q') {
          if (!readPoint(p.p[1])) return fail("Q needs two points");
        } else {
          const char lu = char(std::toupper(static_cast<unsigned char>(lastCommand)));
          p.p[1] = (lu == 'Q' || lu == 'T') ? Vec2{2 * cur.u - lastControl.u, 2 * cur.v - lastControl.v} : cur;
        }
        if (!readPoint(p.p[2])) return fail(std::string(1, upper) + " needs an end point");
        lastControl = p.p[1];
        current.push_back(p);
        cur = p.p[2];
        break;
      }
      case 'A': {
        double rx, ry, rotation;
        bool large, sweep;
        Vec2 to;
        if (!read(rx) || !read(ry) || !read(rotation) || !t.flag(large) || !t.flag(sweep) || !readPoint(to))
          return fail("A needs rx ry rotation large-arc-flag sweep-flag x y");
        rx = std::abs(rx);
        ry = std::abs(ry);
        if (std::abs(rx - ry) > 1e-12 * std::max(rx, ry)) return fail("elliptical arc (rx != ry): only circular arcs are supported");
        if (to.u == cur.u && to.v == cur.v) break;  // F.6.2: the arc is omitted
        if (rx == 0) {
          line(to);
          break;
        }
        // F.6.5 with rx == ry == r: the centre lies on the chord's bisector.
        const double hx = 0.5 * (cur.u - to.u), hy = 0.5 * (cur.v - to.v);
        const double d2 = hx * hx + hy * hy;
        double r = rx;
        if (r * r < d2) r = std::sqrt(d2);  // F.6.6
        // A half-chord equal to the radius (up to rounding) is a half circle: the centre is the midpoint.
        const double k = (r * r - d2 <= 1e-12 * r * r) ? 0.0 : (large != sweep ? 1.0 : -1.0) * std::sqrt((r * r - d2) / d2);
        PathPiece p;
        p.kind = PathPiece::Kind::Arc;
        p.centre = {k * hy + 0.5 * (cur.u + to.u), -k * hx + 0.5 * (cur.v + to.v)};
        p.radius = r;
        p.startAngle = std::atan2(cur.v - p.centre.v, cur.u - p.centre.u);
        double delta = std::atan2(to.v - p.centre.v, to.u - p.centre.u) - p.startAngle;
        if (sweep && delta < 0) delta += 2 * std::numbers::pi;
        if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
        p.sweep = delta;
        p.p[0] = cur;
        p.p[1] = to;
        current.push_back(p);
        cur = to;  // exactly the given end point
        break;
      }
      default:
        return fail(std::string("unknown command '") + command + "'");
    }
    lastCommand = command;
    ++commandIndex;
  }
  finish();
  if (subpaths.empty()) return invalidInput("svg path data draws nothing", {source, where});
  return subpaths;
}

}  // namespace bake::svg
