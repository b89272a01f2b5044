// SVG profile reader (profile.h) over the library's SVG reader (io/svg_drawing.h): the shape with the
// given id, or else the first <path> (or the first shape when there is no path), with every element
// transform applied and the root's viewBox mapped to its width and height (SVG 1.1 §7.7, default
// xMidYMid meet), so the profile is in the unit of the root's width and height (user units when it
// has none). SVG's y grows downwards, so h = -y; the map reverses the sense of arcs, which the reader
// turns into the sign of the bulge. Lines and arcs are kept exactly; quadratic and cubic Béziers are
// flattened by halving (de Casteljau) until the control points lie within 1e-4 of the chord and over
// its span (the curve lies in their convex hull, so it is then within 1e-4 of the chord too). Each
// subpath is a contour, closed when it ends where it started.
#include <cmath>

#include "bake/revolution/profile.h"
#include "io/svg_drawing.h"

namespace bake::revolution {
namespace {

using svg::PathPiece;
using svg::Vec2;

constexpr double kCurveTolerance = 1e-4;

// The root's user space to the viewport: the viewBox scaled uniformly to fit width x height and
// centred (the default preserveAspectRatio), then y flipped.
Result<svg::Affine> profilePlacement(const svg::Frame& frame, const std::string& path) {
  const svg::Affine flip{1, 0, 0, -1, 0, 0};
  const Location at{path, frame.rootElement};
  for (const std::string* text : {&frame.widthText, &frame.heightText})
    if (!text->empty() && text->back() != '%' && !(text == &frame.widthText ? frame.width : frame.height))
      return unsupported("the root's width or height \"" + *text + "\" is not a positive length in px, mm, cm, in, pt or pc", at);
  if (!frame.viewBox || !frame.width || !frame.height) return flip;
  if (frame.width->unit != frame.height->unit)
    return unsupported("the root's width and height use different units (" + frame.width->unit + ", " + frame.height->unit + ")", at);
  const std::string& aspect = frame.preserveAspectRatio;
  if (!aspect.empty() && aspect != "xMidYMid" && aspect != "xMidYMid meet")
    return unsupported("preserveAspectRatio=\"" + aspect + "\" is not supported (only the default, xMidYMid meet)", at);
  const auto& box = *frame.viewBox;
  const double scale = std::min(frame.width->value / box[2], frame.height->value / box[3]);
  const double tx = 0.5 * (frame.width->value - scale * box[2]) - scale * box[0];
  const double ty = 0.5 * (frame.height->value - scale * box[3]) - scale * box[1];
  return svg::Affine{scale, 0, 0, scale, tx, ty}.then(flip);
}

Point2 toProfile(Vec2 p) { return {p.u, p.v}; }

class ContourBuilder {
 public:
  void line(Vec2 to, double bulge = 0) {
    Segment s;
    s.a = toProfile(current_);
    s.b = toProfile(to);
    s.bulge = bulge;
    segments_.push_back(s);
    current_ = to;
  }

  // Cubic Bézier flattened by halving until flat.
  void cubic(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, int depth) {
    const double cx = p3.u - p0.u, cy = p3.v - p0.v, chord = std::hypot(cx, cy);
    auto off = [&](Vec2 q) {
      if (chord == 0) return std::hypot(q.u - p0.u, q.v - p0.v);
      return std::abs((q.u - p0.u) * cy - (q.v - p0.v) * cx) / chord;
    };
    // Within the chord's span too, so a control point far along the line still splits.
    auto along = [&](Vec2 q) {
      if (chord == 0) return true;
      const double t = ((q.u - p0.u) * cx + (q.v - p0.v) * cy) / (chord * chord);
      return t >= -kCurveTolerance / chord && t <= 1 + kCurveTolerance / chord;
    };
    if (depth >= 24 || (off(p1) <= kCurveTolerance && off(p2) <= kCurveTolerance && along(p1) && along(p2))) {
      line(p3);
      return;
    }
    auto mid = [](Vec2 a, Vec2 b) { return Vec2{0.5 * (a.u + b.u), 0.5 * (a.v + b.v)}; };
    const Vec2 a = mid(p0, p1), b = mid(p1, p2), c = mid(p2, p3);
    const Vec2 ab = mid(a, b), bc = mid(b, c), m = mid(ab, bc);
    cubic(p0, a, ab, m, depth + 1);
    cubic(m, bc, c, p3, depth + 1);
  }

  void piece(const PathPiece& p) {
    switch (p.kind) {
      case PathPiece::Kind::Line: line(p.p[1]); break;
      // bulge = tan(sweep / 4), positive counter-clockwise in (r, h): the sweep after the map.
      case PathPiece::Kind::Arc: line(p.p[1], std::tan(p.sweep / 4)); break;
      case PathPiece::Kind::Quadratic: {
        // The same curve as a cubic: controls two thirds of the way to the quadratic's control.
        const Vec2 s = p.p[0], q = p.p[1], e = p.p[2];
        cubic(s, {s.u + 2.0 / 3.0 * (q.u - s.u), s.v + 2.0 / 3.0 * (q.v - s.v)},
              {e.u + 2.0 / 3.0 * (q.u - e.u), e.v + 2.0 / 3.0 * (q.v - e.v)}, e, 0);
        break;
      }
      case PathPiece::Kind::Cubic: cubic(p.p[0], p.p[1], p.p[2], p.p[3], 0); break;
      case PathPiece::Kind::Spiral: break;  // SVG path data has none
    }
  }

  Contour contour(const std::vector<PathPiece>& pieces) {
    segments_.clear();
    current_ = pieces.front().p[0];
    const Vec2 start = current_;
    for (const PathPiece& p : pieces) piece(p);
    Contour contour;
    contour.closed = current_.u == start.u && current_.v == start.v;
    contour.segments = std::move(segments_);
    return contour;
  }

 private:
  Vec2 current_;
  std::vector<Segment> segments_;
};

const svg::Shape* chooseShape(const std::vector<svg::Shape>& shapes, const std::string& id) {
  for (const svg::Shape& shape : shapes)
    if (id.empty() ? shape.tag == "path" : shape.id == id) return &shape;
  return id.empty() && !shapes.empty() ? &shapes.front() : nullptr;
}

}  // namespace

Result<Profile> readProfileSvg(const std::string& path, const std::string& pathId) {
  auto place = [&](const svg::Frame& frame) { return profilePlacement(frame, path); };
  BAKE_ASSIGN_OR_RETURN(const std::vector<svg::Shape> shapes, svg::readDrawing(path, "", place));
  const svg::Shape* shape = chooseShape(shapes, pathId);
  if (!shape) {
    if (!pathId.empty()) return invalidInput("no shape with id '" + pathId + "'", {path, ""});
    return invalidInput("the drawing has no shape to read a profile from", {path, ""});
  }
  Profile profile;
  profile.source = path;
  ContourBuilder builder;
  for (const std::vector<PathPiece>& pieces : shape->subpaths)
    if (!pieces.empty()) profile.contours.push_back(builder.contour(pieces));
  if (profile.contours.empty()) return invalidInput(shape->element + " draws nothing", {path, ""});
  return profile;
}

}  // namespace bake::revolution
