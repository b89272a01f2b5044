// The combined cross-section of parallel grooves (seed 000 §5; the surface rule of
// formats/groove-scene.md): every groove under the footprint is a straight band here (LocalGroove), so
// the surface along the common binormal B is one function of b. Each groove's profile, shifted to where
// its centre line crosses B, is a piecewise linear function on its band; the surface is
// H = min(0, min cuts) + max(0, max ridges). Between consecutive profile breakpoints (of all grooves)
// every groove is linear, so H is linear except where two pieces cross (or a piece crosses 0): those
// crossings split the interval, which makes the combination exact. Where a groove's profile has a
// vertical segment, H jumps: the polyline gets a vertical wall there.
//
// Materials: a piece takes the material of the groove with the largest |h| (the earlier primitive on a
// tie; base where every h is 0); a wall, that of its side with the larger |H|. Splitting also where
// h_i = -h_j keeps the largest |h| constant on each piece.
#include <algorithm>
#include <cmath>

#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

// A groove's profile in section coordinates, b ascending.
struct PlacedProfile {
  const SectionGroove* groove = nullptr;
  std::size_t first = 0, count = 0;  // into the shared point list
};

// One groove's linear piece over the current interval.
struct Piece {
  double left = 0, right = 0;  // h at the interval's two ends
  std::size_t material = 0;
  std::uint32_t primitive = 0;
  double at(double t) const { return t >= 1 ? right : left + t * (right - left); }
};

// h of segment [p, q] at x, exact at the end points (so neighbouring intervals agree bit for bit).
double heightOn(const SectionPoint& p, const SectionPoint& q, double x) {
  if (x <= p.b) return p.h;
  if (x >= q.b) return q.h;
  return p.h + (x - p.b) / (q.b - p.b) * (q.h - p.h);
}

double surfaceAt(const std::vector<Piece>& pieces, double t) {
  double cut = 0, ridge = 0;
  for (const Piece& piece : pieces) {
    const double h = piece.at(t);
    cut = std::min(cut, h);
    ridge = std::max(ridge, h);
  }
  return cut + ridge;
}

std::size_t materialAt(const std::vector<Piece>& pieces, double t, std::size_t base) {
  double largest = 0;
  std::size_t material = base;
  std::uint32_t primitive = 0;
  for (const Piece& piece : pieces) {
    const double size = std::abs(piece.at(t));
    if (size > largest || (size == largest && size > 0 && piece.primitive < primitive)) {
      largest = size;
      material = piece.material;
      primitive = piece.primitive;
    }
  }
  return material;
}

// Where f(t) = a + t (b - a) and g cross strictly inside (0, 1).
void addCrossing(double fa, double fb, double ga, double gb, std::vector<double>& splits) {
  const double d0 = fa - ga, d1 = fb - gb;
  if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
    const double t = d0 / (d0 - d1);
    if (t > 0 && t < 1) splits.push_back(t);
  }
}

// Appends a point; a facet (with its material) joins it to the previous point unless they coincide.
void appendPoint(CrossSection& out, double b, double h, std::size_t material) {
  if (!out.points.empty()) {
    const SectionPoint& last = out.points.back();
    if (last.b == b && last.h == h) return;
    out.material.push_back(material);
  }
  out.points.push_back({b, h});
}

constexpr std::size_t kWall = static_cast<std::size_t>(-1);  // resolved after the sweep

// The common cases of appendInterval without its general split list: no groove (the flat base), or
// one, which only splits where it crosses h = 0. The same points and materials as the general case.
void appendFlat(CrossSection& out, double x0, double x1, std::size_t base) {
  appendPoint(out, x0, 0, kWall);
  appendPoint(out, x1, 0, base);
}

void appendOnePiece(CrossSection& out, const Piece& piece, double x0, double x1, std::size_t base) {
  double ts[3] = {0, 1, 1};
  int count = 2;
  const double d0 = piece.left, d1 = piece.right;
  if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
    const double t = d0 / (d0 - d1);
    if (t > 0 && t < 1) ts[1] = t, count = 3;
  }
  // H = min(0, h) + max(0, h), as surfaceAt computes it (so -0 becomes +0 alike).
  auto surface = [&](double t) {
    const double h = piece.at(t);
    return std::min(0.0, h) + std::max(0.0, h);
  };
  for (int k = 0; k + 1 < count; ++k) {
    const double ta = ts[k], tb = ts[k + 1];
    const double xa = k == 0 ? x0 : x0 + ta * (x1 - x0);
    const double xb = k + 2 == count ? x1 : x0 + tb * (x1 - x0);
    const std::size_t material = std::abs(piece.at(0.5 * (ta + tb))) > 0 ? piece.material : base;
    appendPoint(out, xa, surface(ta), kWall);
    appendPoint(out, xb, surface(tb), material);
  }
}

// Appends H over [x0, x1] for the given pieces, split at their crossings.
void appendInterval(CrossSection& out, const std::vector<Piece>& pieces, double x0, double x1, std::size_t base,
                    std::vector<double>& splits) {
  if (pieces.empty()) return appendFlat(out, x0, x1, base);
  if (pieces.size() == 1) return appendOnePiece(out, pieces.front(), x0, x1, base);
  splits.clear();
  splits.push_back(0);
  splits.push_back(1);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    addCrossing(pieces[i].left, pieces[i].right, 0, 0, splits);
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      addCrossing(pieces[i].left, pieces[i].right, pieces[j].left, pieces[j].right, splits);
      addCrossing(pieces[i].left, pieces[i].right, -pieces[j].left, -pieces[j].right, splits);
    }
  }
  std::sort(splits.begin(), splits.end());
  splits.erase(std::unique(splits.begin(), splits.end()), splits.end());
  for (std::size_t k = 0; k + 1 < splits.size(); ++k) {
    const double ta = splits[k], tb = splits[k + 1];
    const double xa = k == 0 ? x0 : x0 + ta * (x1 - x0);
    const double xb = k + 2 == splits.size() ? x1 : x0 + tb * (x1 - x0);
    const std::size_t material = materialAt(pieces, 0.5 * (ta + tb), base);
    appendPoint(out, xa, surfaceAt(pieces, ta), kWall);  // a jump at xa is a wall
    appendPoint(out, xb, surfaceAt(pieces, tb), material);
  }
}

// A wall takes the material of its side with the larger |H| (the left side on a tie).
void resolveWalls(CrossSection& out, std::size_t base) {
  const std::size_t facets = out.material.size();
  for (std::size_t i = 0; i < facets; ++i) {
    if (out.material[i] != kWall) continue;
    const bool leftDeeper = std::abs(out.points[i].h) >= std::abs(out.points[i + 1].h);
    std::size_t side = kWall;
    if (leftDeeper && i > 0) side = out.material[i - 1];
    if (side == kWall && i + 1 < facets) side = out.material[i + 1];
    if (side == kWall && i > 0) side = out.material[i - 1];
    out.material[i] = side == kWall ? base : side;
  }
}

// Profile p's piece over [x0, x1], its segment `j` moved on to the one under the interval (past
// vertical segments too).
Piece pieceOver(const PlacedProfile& p, const std::vector<SectionPoint>& placed, std::size_t& j, double x0, double x1) {
  const SectionPoint* pts = &placed[p.first];
  while (j + 2 < p.count && pts[j + 1].b <= x0) ++j;
  const LocalGroove& g = *p.groove->groove;
  return {heightOn(pts[j], pts[j + 1], x0), heightOn(pts[j], pts[j + 1], x1), g.material, g.primitive};
}

// Each band ends where or before the next one starts, and runs with b (the common case: parallel
// grooves apart from each other). Then at most one groove lies over any interval.
bool disjointBands(const std::vector<PlacedProfile>& profiles, const std::vector<SectionPoint>& placed) {
  for (std::size_t k = 0; k < profiles.size(); ++k) {
    const SectionPoint* pts = &placed[profiles[k].first];
    for (std::size_t i = 0; i + 1 < profiles[k].count; ++i)
      if (pts[i + 1].b < pts[i].b) return false;
    if (k + 1 < profiles.size() && pts[profiles[k].count - 1].b > placed[profiles[k + 1].first].b) return false;
  }
  return true;
}

// The sweep of sweepOverlapping for disjoint bands: the one groove over the interval (if any) is the
// first band not ended yet, if it has started; no active set, no piece list. The same intervals and
// pieces, so the same points, bit for bit.
void sweepDisjoint(const std::vector<PlacedProfile>& profiles, const std::vector<SectionPoint>& placed,
                   const std::vector<double>& breaks, std::size_t base, CrossSection& out) {
  std::size_t current = 0, j = 0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double x0 = breaks[k], x1 = breaks[k + 1];
    while (current < profiles.size() && placed[profiles[current].first + profiles[current].count - 1].b <= x0) {
      ++current;
      j = 0;
    }
    if (current == profiles.size() || placed[profiles[current].first].b > x0) {
      appendFlat(out, x0, x1, base);
      continue;
    }
    appendOnePiece(out, pieceOver(profiles[current], placed, j, x0, x1), x0, x1, base);
  }
}

// The general sweep: grooves enter the active set at their first b and leave it after their last.
void sweepOverlapping(const std::vector<PlacedProfile>& profiles, const std::vector<SectionPoint>& placed,
                      const std::vector<double>& breaks, std::size_t base, CrossSection& out) {
  thread_local std::vector<std::size_t> active;  // indices into profiles
  thread_local std::vector<std::size_t> cursor;  // the segment of each profile under the interval
  thread_local std::vector<Piece> pieces;
  thread_local std::vector<double> splits;
  active.clear();
  cursor.assign(profiles.size(), 0);
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double x0 = breaks[k], x1 = breaks[k + 1];
    while (next < profiles.size() && placed[profiles[next].first].b <= x0) active.push_back(next++);
    pieces.clear();
    std::size_t keep = 0;
    for (std::size_t a : active) {
      const PlacedProfile& p = profiles[a];
      const SectionPoint* pts = &placed[p.first];
      if (pts[p.count - 1].b <= x0) continue;  // the band ended: drop it
      active[keep++] = a;
      pieces.push_back(pieceOver(p, placed, cursor[a], x0, x1));
    }
    active.resize(keep);
    appendInterval(out, pieces, x0, x1, base, splits);
  }
}

}  // namespace

void buildCrossSection(const GrooveScene& scene, const std::vector<SectionGroove>& grooves, double lo, double hi,
                       CrossSection& out) {
  out.points.clear();
  out.material.clear();
  const std::size_t base = scene.baseMaterial;

  // Every profile in section coordinates, b ascending (a reversed groove is mirrored).
  // Working arrays, reused between calls on a thread (the shader's are fixed-size).
  thread_local std::vector<SectionPoint> placed;
  thread_local std::vector<PlacedProfile> profiles;
  thread_local std::vector<double> breaks;
  placed.clear();
  profiles.clear();
  for (const SectionGroove& g : grooves) {
    const std::size_t n = g.groove->profile->points.size();
    PlacedProfile p{&g, placed.size(), n};
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = g.reversed ? n - 1 - k : k;
      const double b = g.reversed ? g.centre - g.groove->profileB(j) : g.centre + g.groove->profileB(j);
      placed.push_back({b, g.groove->profileH(j)});
    }
    profiles.push_back(p);
  }
  // Sweep: grooves enter in order of their first b. Grooves found in index order often lie in order
  // across the section (a set of parallel lines), forwards or backwards: then no sort is needed, and
  // the breaks, gathered profile after profile, come out sorted too when the bands do not overlap.
  const auto firstB = [&](const PlacedProfile& a, const PlacedProfile& b) {
    return placed[a.first].b < placed[b.first].b;
  };
  if (std::is_sorted(profiles.rbegin(), profiles.rend(), firstB)) std::reverse(profiles.begin(), profiles.end());
  if (!std::is_sorted(profiles.begin(), profiles.end(), firstB)) std::sort(profiles.begin(), profiles.end(), firstB);
  breaks.clear();
  for (const PlacedProfile& p : profiles)
    for (std::size_t k = 0; k < p.count; ++k) breaks.push_back(placed[p.first + k].b);
  if (!std::is_sorted(breaks.begin(), breaks.end())) std::sort(breaks.begin(), breaks.end());
  breaks.insert(std::lower_bound(breaks.begin(), breaks.end(), lo), lo);
  breaks.insert(std::upper_bound(breaks.begin(), breaks.end(), hi), hi);
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  // The polyline starts and ends on the base (h = 0), so a profile starting or ending with a vertical
  // wall at the outermost break keeps that wall.
  appendPoint(out, breaks.front(), 0, kWall);
  if (disjointBands(profiles, placed)) {
    sweepDisjoint(profiles, placed, breaks, base, out);
  } else {
    sweepOverlapping(profiles, placed, breaks, base, out);
  }
  appendPoint(out, breaks.back(), 0, kWall);
  resolveWalls(out, base);
}

namespace {

// The band's edges hold within this fraction of the groove's width: a rim placed on the section at
// centre + profileB comes back from (b - centre) within rounding, and must keep its rates (its
// facets' tilt and the footprint's density there would jump otherwise).
constexpr double kBandSlack = 1e-4;

// The groove's own height at its offset x, or false outside its band (a vertical wall gives the
// height of its first point, where the band starts or the wall's top or foot alike).
bool grooveHeightAt(const LocalGroove& g, double x, double& h) {
  const std::size_t n = g.profile->points.size();
  const double slack = kBandSlack * (g.profileB(n - 1) - g.profileB(0));
  if (!(x >= g.profileB(0) - slack && x <= g.profileB(n - 1) + slack)) return false;
  x = std::clamp(x, g.profileB(0), g.profileB(n - 1));
  std::size_t k = 0;
  while (k + 2 < n && g.profileB(k + 1) < x) ++k;
  const double b0 = g.profileB(k), b1 = g.profileB(k + 1);
  h = b1 > b0 ? g.profileH(k) + (x - b0) / (b1 - b0) * (g.profileH(k + 1) - g.profileH(k)) : g.profileH(k);
  return true;
}

}  // namespace

void setSectionRates(CrossSection& section, const std::vector<SectionGroove>& grooves) {
  // Every point of a band gets its rates, the rims too: they do not move along a line (its travel is
  // 0 at h = 0), but a facet's tilt comes from both its ends.
  for (SectionPoint& p : section.points) p.rateB = 0, p.rateH = 0, p.accelB = 0;
  // Unperturbed grooves (the common case) leave every rate 0: the search below, each point against
  // every groove, is quadratic in a footprint over many grooves.
  const bool anyRate = std::any_of(grooves.begin(), grooves.end(), [](const SectionGroove& g) {
    return g.groove->scaleRate != 0 || g.groove->offsetRate != 0 || g.groove->scaleAccel != 0 || g.groove->offsetAccel != 0;
  });
  if (!anyRate) return;
  for (SectionPoint& p : section.points) {
    // The groove shaping the surface here: the one whose own height is nearest the point's.
    const SectionGroove* shaping = nullptr;
    double nearest = 0;
    for (const SectionGroove& g : grooves) {
      const double sign = g.reversed ? -1 : 1;
      double h = 0;
      if (!grooveHeightAt(*g.groove, sign * (p.b - g.centre), h)) continue;
      if (!shaping || std::abs(h - p.h) < nearest) shaping = &g, nearest = std::abs(h - p.h);
    }
    if (!shaping) continue;
    const LocalGroove& g = *shaping->groove;
    if (g.scaleRate == 0 && g.offsetRate == 0 && g.scaleAccel == 0 && g.offsetAccel == 0) continue;
    // Travel along T is travel along the groove's path, reversed when the groove runs against T; the
    // offset x then runs against b as well, so db/dT = dx/ds either way and dh/dT = sign dh/ds.
    const double sign = shaping->reversed ? -1 : 1;
    const double q = (sign * (p.b - shaping->centre) - g.offset) / g.scale;
    p.rateB = g.offsetRate + g.scaleRate * q;
    p.rateH = sign * g.scaleRate * p.h / g.scale;
    p.accelB = sign * (g.offsetAccel + g.scaleAccel * q);  // d/dT of dx/ds = sign d2x/ds2
  }
}

}  // namespace bake::grooves
