// Validation and normalisation of a profile (profile.h). Seed 001 revolves a 2D shape about the
// axis, so the solid is what the contours enclose once open contours are closed along r = 0; the
// pieces on the axis bound the section but are not surface. Checks, in order: finite numbers and
// r >= 0 (tiny negative r from round-off is snapped to the axis), zero-length pieces dropped,
// consecutive pieces joined, open contours closed along the axis, no two pieces crossing (a sweep
// over their boxes, then exact line / circle intersections). Finally every contour is oriented by
// its nesting depth (outer counter-clockwise, holes clockwise), so the winding number equals the
// even-odd inside test everywhere: area-coverage rasterisation relies on that.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "bake/revolution/profile.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {
namespace {

std::string pointText(Point2 p) {
  std::ostringstream text;
  text.precision(9);
  text << "(" << p.r << ", " << p.h << ")";
  return text.str();
}

double distance(Point2 a, Point2 b) { return std::hypot(a.r - b.r, a.h - b.h); }

// A piece plus where it came from, for messages.
struct Located {
  const Segment* segment;
  int contour;
  int index;  // piece index in the normalised contour
  Point2 lo, hi;
};

double profileScale(const Profile& profile) {
  double scale = 0;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments)
      scale = std::max({scale, std::abs(s.a.r), std::abs(s.a.h), std::abs(s.b.r), std::abs(s.b.h)});
  return scale > 0 ? scale : 1.0;
}

Status checkNumbers(Profile& profile, double tol) {
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    auto& segments = profile.contours[c].segments;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      Segment& s = segments[i];
      // Segment i runs from point i to point i + 1 (the first point again for a closing segment).
      const std::size_t pointCount = profile.contours[c].closed ? segments.size() : segments.size() + 1;
      auto where = [&](std::size_t point) {
        return "contour " + std::to_string(c) + ", point " + std::to_string(point % pointCount);
      };
      if (!std::isfinite(s.a.r) || !std::isfinite(s.a.h))
        return invalidInput("coordinate is not a finite number", {profile.source, where(i)});
      if (!std::isfinite(s.b.r) || !std::isfinite(s.b.h))
        return invalidInput("coordinate is not a finite number", {profile.source, where(i + 1)});
      if (!std::isfinite(s.bulge)) return invalidInput("bulge is not a finite number", {profile.source, where(i)});
      for (int end = 0; end < 2; ++end) {
        Point2* p = end == 0 ? &s.a : &s.b;
        if (p->r < -tol)
          return invalidInput("negative radius r = " + std::to_string(p->r) + " (the profile must lie in r >= 0)",
                              {profile.source, where(i + std::size_t(end))});
        if (p->r < tol) p->r = 0;  // round-off onto the axis
      }
    }
  }
  return Status::ok();
}

// Drops zero-length pieces and makes consecutive pieces meet exactly.
Status joinPieces(Profile& profile, double tol, std::vector<std::string>& warnings) {
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    auto& segments = profile.contours[c].segments;
    std::vector<Segment> kept;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      if (distance(segments[i].a, segments[i].b) <= tol) {
        warnings.push_back(profile.source + ": contour " + std::to_string(c) + ", point " + std::to_string(i) +
                           ": zero-length segment dropped");
        continue;
      }
      if (!kept.empty()) {
        const double gap = distance(kept.back().b, segments[i].a);
        if (gap > tol * 1e3)
          return invalidInput("segment starts at " + pointText(segments[i].a) + " but the previous one ends at " +
                                  pointText(kept.back().b),
                              {profile.source, "contour " + std::to_string(c) + ", point " + std::to_string(i)});
        segments[i].a = kept.back().b;
      }
      kept.push_back(segments[i]);
    }
    segments = std::move(kept);
  }
  return Status::ok();
}

Segment straight(Point2 a, Point2 b) {
  Segment s;
  s.a = a;
  s.b = b;
  return s;
}

// Open contours end on the axis or get a horizontal run to it; the axis closes them.
void closeContours(Profile& profile, double tol, std::vector<std::string>& warnings) {
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    Contour& contour = profile.contours[c];
    if (contour.segments.empty()) continue;
    const Point2 start = contour.segments.front().a, end = contour.segments.back().b;
    if (distance(start, end) <= tol) {
      contour.segments.back().b = start;
      contour.closed = true;
      continue;
    }
    if (contour.closed) {
      warnings.push_back(profile.source + ": contour " + std::to_string(c) +
                         ": closed contour does not end where it starts; joined by a straight segment");
      contour.segments.push_back(straight(end, start));
      continue;
    }
    std::vector<Segment>& pieces = contour.segments;
    if (end.r > 0) {
      warnings.push_back(profile.source + ": contour " + std::to_string(c) +
                         ": open contour ends off the axis; closed by a horizontal run to it");
      pieces.push_back(straight(end, {0, end.h}));
    }
    if (end.h != start.h) pieces.push_back(straight({0, end.h}, {0, start.h}));
    if (start.r > 0) {
      warnings.push_back(profile.source + ": contour " + std::to_string(c) +
                         ": open contour starts off the axis; closed by a horizontal run to it");
      pieces.push_back(straight({0, start.h}, start));
    }
    contour.closed = true;
  }
}

bool sharesEnd(const Segment& s, const Segment& t, Point2 p, double tol) {
  for (Point2 e : {s.a, s.b})
    if ((distance(e, t.a) <= tol || distance(e, t.b) <= tol) && distance(e, p) <= tol) return true;
  return false;
}

Status checkCrossings(const Profile& profile, double tol) {
  std::vector<Located> pieces;
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    const auto& segments = profile.contours[c].segments;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      Located l{&segments[i], int(c), int(i), {}, {}};
      segmentBox(segments[i], l.lo, l.hi);
      pieces.push_back(l);
    }
  }
  std::sort(pieces.begin(), pieces.end(), [](const Located& x, const Located& y) { return x.lo.h < y.lo.h; });
  // Touching at a common end is how pieces join; anything else is a crossing. Ends may be shared by
  // pieces that are not neighbours (two contours meeting at a point); that is allowed too.
  const double touch = tol * 1e3;
  for (std::size_t x = 0; x < pieces.size(); ++x) {
    for (std::size_t y = x + 1; y < pieces.size() && pieces[y].lo.h <= pieces[x].hi.h + touch; ++y) {
      const Located& p = pieces[x];
      const Located& q = pieces[y];
      if (q.lo.r > p.hi.r + touch || q.hi.r < p.lo.r - touch) continue;
      const PieceIntersections hits = intersectPieces(*p.segment, *q.segment, touch);
      const Located& first = p.contour < q.contour || (p.contour == q.contour && p.index < q.index) ? p : q;
      const Located& second = &first == &p ? q : p;
      const std::string where = "contour " + std::to_string(first.contour) + " segment " +
                                std::to_string(first.index) + " and contour " + std::to_string(second.contour) +
                                " segment " + std::to_string(second.index);
      if (hits.overlap)
        return invalidInput("profile overlaps itself near " + pointText(hits.overlapPoint), {profile.source, where});
      for (Point2 hit : hits.points)
        if (!sharesEnd(*p.segment, *q.segment, hit, touch))
          return invalidInput("profile crosses itself at " + pointText(hit), {profile.source, where});
    }
  }
  return Status::ok();
}

double contourArea(const Contour& contour) {
  double area = 0;
  for (const Segment& s : contour.segments) area += areaTerm(s);
  return area;
}

void reverse(Contour& contour) {
  std::reverse(contour.segments.begin(), contour.segments.end());
  for (Segment& s : contour.segments) {
    std::swap(s.a, s.b);
    s.bulge = -s.bulge;
  }
}

// Outer contours counter-clockwise, holes clockwise, by how many other contours enclose each one.
void orientByNesting(Profile& profile) {
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    const Point2 probe = pointAt(profile.contours[c].segments.front(), 0.5);
    int depth = 0;
    for (std::size_t o = 0; o < profile.contours.size(); ++o) {
      if (o == c) continue;
      Profile single;
      single.contours.push_back(profile.contours[o]);
      depth += insideProfile(single, probe) ? 1 : 0;
    }
    const bool wantCounterClockwise = depth % 2 == 0;
    if ((contourArea(profile.contours[c]) > 0) != wantCounterClockwise) reverse(profile.contours[c]);
  }
}

}  // namespace

Status validateProfile(Profile& profile, std::vector<std::string>& warnings) {
  const double scale = profileScale(profile);
  const double tol = 1e-9 * scale;
  BAKE_RETURN_IF_ERROR(checkNumbers(profile, tol));
  BAKE_RETURN_IF_ERROR(joinPieces(profile, tol, warnings));
  for (std::size_t c = 0; c < profile.contours.size(); ++c)
    if (profile.contours[c].segments.empty())
      warnings.push_back(profile.source + ": contour " + std::to_string(c) + ": no segments left; dropped");
  std::erase_if(profile.contours, [](const Contour& contour) { return contour.segments.empty(); });
  if (profile.contours.empty()) return invalidInput("profile has no segments", {profile.source, "contours"});
  closeContours(profile, tol, warnings);
  for (std::size_t c = 0; c < profile.contours.size(); ++c)
    for (std::size_t i = 0; i < profile.contours[c].segments.size(); ++i) {
      Point2 lo, hi;
      segmentBox(profile.contours[c].segments[i], lo, hi);
      if (lo.r < -tol)
        return invalidInput("arc reaches negative radius r = " + std::to_string(lo.r),
                            {profile.source, "contour " + std::to_string(c) + " segment " + std::to_string(i)});
    }
  for (Contour& contour : profile.contours)
    for (Segment& s : contour.segments) s.onAxis = s.bulge == 0 && s.a.r == 0 && s.b.r == 0;
  BAKE_RETURN_IF_ERROR(checkCrossings(profile, tol));
  for (std::size_t c = 0; c < profile.contours.size(); ++c) {
    const double area = contourArea(profile.contours[c]);
    if (std::abs(area) <= tol * scale)
      return invalidInput("contour encloses no area", {profile.source, "contour " + std::to_string(c)});
  }
  orientByNesting(profile);
  return Status::ok();
}

Bounds2 profileBounds(const Profile& profile) {
  Bounds2 bounds;
  bool first = true;
  for (const Contour& contour : profile.contours)
    for (const Segment& s : contour.segments) {
      Point2 lo, hi;
      segmentBox(s, lo, hi);
      if (first) {
        bounds = {hi.r, lo.h, hi.h};
        first = false;
      }
      bounds.rMax = std::max(bounds.rMax, hi.r);
      bounds.hMin = std::min(bounds.hMin, lo.h);
      bounds.hMax = std::max(bounds.hMax, hi.h);
    }
  return bounds;
}

}  // namespace bake::revolution
