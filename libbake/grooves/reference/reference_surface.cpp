// The exact height field of a groove scene and its ray queries (formats/groove-scene.md, "The surface a
// scene describes"), written independently of the seed's method (no grid.h, no joints or local frames
// of the shader code): it is the oracle that method is measured against.
//
// Each primitive (and, with wrap "repeat", each periodic copy of it) becomes a Component: its frame
// (foot point arc length s, signed offset b and their gradients), its two joint half-planes (mitre
// lines at joints, flat cuts at open ends) and its profile. With the profile segment k fixed, its
// height is h = slope_k (b - offset(s)) + intercept_k scale(s), smooth in x. H is the deepest cut plus
// the highest ridge over the components whose region holds x.
//
// Ray casting walks the ray's horizontal projection through a uniform grid of component bounds (2D
// DDA; periodic cell indices under wrap). In each cell the ray's parameter range is cut at events:
// joint-line crossings (linear in t), crossings of profile vertices by the normalised offset q (linear
// for straight unperturbed primitives, a quadratic for unperturbed arcs, found by Lipschitz-safe
// marching inside the groove's band for perturbed ones). Between events every active component is
// smooth, so H can jump (vertical walls) only at events. On a sub-interval where all active components are
// straight and unperturbed each height is linear in t: it is split again where two of them (or one
// and 0) cross, H is then linear and the first root of z(t) - H(t) is exact. Where one unperturbed
// arc alone is active its surface is a cone about the arc's axis: the root of a quadratic, also exact.
// Elsewhere (several arcs at once, perturbations) the root is bracketed by Lipschitz-bounded steps
// (never past a root a bound of |dH/dt| can hide, with a ceiling on the step and a floor of 1e-3 of the
// feature size: dense bracketing, so only tangential touches narrower than that floor can be missed)
// and narrowed by regula falsi (Illinois) to 1e-12 of the domain size. (Perturbed q crossings are
// found the same way, bisected when several vertices fall in one step.) A sub-interval that starts
// below the ray after a jump of H is a vertical wall: the hit normal is the horizontal normal of the
// event's line, turned to face the ray.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "bake/core/vec.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

using planar::add;
using planar::dot;
using planar::leftNormal;
using planar::length;
using planar::scaled;
using planar::sub;
Vec2 unit(Vec2 a) {
  const double n = length(a);
  return n > 0 ? scaled(1 / n, a) : Vec2{};
}

// A profile as segments: P(q) = slope[k] q + intercept[k] on [b[k], b[k+1]], 0 outside [b0, bLast].
struct ProfileTable {
  std::vector<double> b, h, slope, intercept;
  double wmax = 0;
  double heightRange = 0;  // max h - min h
};

ProfileTable tableOf(const Profile& profile) {
  ProfileTable t;
  for (const Vec2& p : profile.points) {
    t.b.push_back(p.u);
    t.h.push_back(p.v);
  }
  for (std::size_t k = 0; k + 1 < t.b.size(); ++k) {
    const double db = t.b[k + 1] - t.b[k];
    const double s = db > 0 ? (t.h[k + 1] - t.h[k]) / db : 0;  // vertical segments are never selected
    t.slope.push_back(s);
    t.intercept.push_back(t.h[k] - s * t.b[k]);
  }
  t.wmax = profile.wmax;
  t.heightRange = *std::max_element(t.h.begin(), t.h.end()) - *std::min_element(t.h.begin(), t.h.end());
  return t;
}

// The profile segment holding q (never a vertical one), or -1 outside the profile (height 0 there).
int segmentOf(const ProfileTable& p, double q) {
  if (!(q >= p.b.front()) || q >= p.b.back()) return -1;
  const auto above = std::upper_bound(p.b.begin(), p.b.end(), q);
  return static_cast<int>(above - p.b.begin()) - 1;
}

struct PlaneBounds {
  Vec2 lo{kInf, kInf}, hi{-kInf, -kInf};
  void take(Vec2 p) {
    lo = {std::min(lo.u, p.u), std::min(lo.v, p.v)};
    hi = {std::max(hi.u, p.u), std::max(hi.v, p.v)};
  }
};

// One primitive, or one periodic copy of it, ready to evaluate.
struct Component {
  std::size_t primitive = 0;  // ties of the material rule go to the earlier primitive
  std::size_t material = 0;
  const ProfileTable* profile = nullptr;
  Perturbation perturbation;
  bool arc = false;
  Vec2 start, tangent, normal;       // segment: start point, unit tangent, left normal
  Vec2 centre;                       // arc
  double radius = 0, turn = 1;       // arc: turn = +1 counter-clockwise, -1 clockwise
  double midAngle = 0;               // arc: angle of its middle point
  double arcStart = 0, length = 0;
  Vec2 joint0, mitre0, joint1, mitre1;  // region: (x - joint0).mitre0 >= 0 and (x - joint1).mitre1 <= 0
  double grooveWidth = 0;               // the groove's wmax, perturbation included
  double gradSMax = 1;                  // bound of |grad s| over the region
  PlaneBounds box;
  bool linear() const { return !arc && perturbation.kind == Perturbation::Kind::None; }
};

Component translated(Component c, Vec2 by) {
  c.start = add(c.start, by);
  c.centre = add(c.centre, by);
  c.joint0 = add(c.joint0, by);
  c.joint1 = add(c.joint1, by);
  c.box.lo = add(c.box.lo, by);
  c.box.hi = add(c.box.hi, by);
  return c;
}

// Arc length, offset and their gradients at x (formats/groove-scene.md "Frame").
struct Frame {
  double b = 0, s = 0;
  Vec2 gradB, gradS;
};

Frame frameAt(const Component& c, Vec2 x) {
  Frame f;
  if (!c.arc) {
    const Vec2 d = sub(x, c.start);
    f.b = dot(d, c.normal);
    f.s = c.arcStart + dot(d, c.tangent);
    f.gradB = c.normal;
    f.gradS = c.tangent;
    return f;
  }
  const Vec2 d = sub(x, c.centre);
  const double r = length(d);
  const Vec2 radial = r > 0 ? scaled(1 / r, d) : Vec2{1, 0};
  const double relative = std::remainder(std::atan2(d.v, d.u) - c.midAngle, 2 * kPi);
  f.b = c.turn * (c.radius - r);
  f.s = c.arcStart + 0.5 * c.length + c.turn * c.radius * relative;
  f.gradB = scaled(-c.turn, radial);
  f.gradS = r > 0 ? scaled(c.turn * c.radius / r, leftNormal(radial)) : Vec2{};
  return f;
}

// scale(s), offset(s) and their derivatives.
struct Perturbed {
  double scale = 1, scaleRate = 0, offset = 0, offsetRate = 0;
};

Perturbed perturbationAt(const Perturbation& p, double s) {
  Perturbed out;
  if (p.kind == Perturbation::Kind::None) return out;
  const double k = 2 * kPi / p.wavelength, phase = k * s + p.phase;
  if (p.kind == Perturbation::Kind::Scale) {
    out.scale = 1 + p.amplitude * std::sin(phase);
    out.scaleRate = p.amplitude * k * std::cos(phase);
  } else {
    out.offset = p.amplitude * std::sin(phase);
    out.offsetRate = p.amplitude * k * std::cos(phase);
  }
  return out;
}

double rateBound(const Perturbation& p) {
  return p.kind == Perturbation::Kind::None ? 0 : p.amplitude * 2 * kPi / p.wavelength;
}
double minScale(const Perturbation& p) { return p.kind == Perturbation::Kind::Scale ? 1 - p.amplitude : 1; }

bool inRegion(const Component& c, Vec2 x) {
  return dot(sub(x, c.joint0), c.mitre0) >= 0 && dot(sub(x, c.joint1), c.mitre1) <= 0;
}

// The normalised profile coordinate q = (b - offset) / scale and its gradient.
struct Coordinate {
  double q = 0;
  Vec2 gradQ;
  Frame frame;
  Perturbed pert;
};

Coordinate coordinateAt(const Component& c, Vec2 x) {
  Coordinate out;
  out.frame = frameAt(c, x);
  out.pert = perturbationAt(c.perturbation, out.frame.s);
  out.q = (out.frame.b - out.pert.offset) / out.pert.scale;
  const Vec2 shifted = sub(out.frame.gradB, scaled(out.pert.offsetRate, out.frame.gradS));
  const double scaleTerm = out.q * out.pert.scaleRate / out.pert.scale;
  out.gradQ = sub(scaled(1 / out.pert.scale, shifted), scaled(scaleTerm, out.frame.gradS));
  return out;
}

// A component in its region with its profile segment fixed: a smooth height.
struct Piece {
  const Component* c = nullptr;
  int segment = 0;
};

double pieceHeight(const Piece& p, Vec2 x) {
  const Frame f = frameAt(*p.c, x);
  const Perturbed g = perturbationAt(p.c->perturbation, f.s);
  return p.c->profile->slope[p.segment] * (f.b - g.offset) + p.c->profile->intercept[p.segment] * g.scale;
}

Vec2 pieceGradient(const Piece& p, Vec2 x) {
  const Frame f = frameAt(*p.c, x);
  const Perturbed g = perturbationAt(p.c->perturbation, f.s);
  const double slope = p.c->profile->slope[p.segment], intercept = p.c->profile->intercept[p.segment];
  const Vec2 alongB = sub(f.gradB, scaled(g.offsetRate, f.gradS));
  return add(scaled(slope, alongB), scaled(intercept * g.scaleRate, f.gradS));
}

// Bound of |grad h| of a piece over its region.
double pieceGradientBound(const Piece& p) {
  const Component& c = *p.c;
  const double rate = rateBound(c.perturbation), slope = std::abs(c.profile->slope[p.segment]);
  const double intercept = std::abs(c.profile->intercept[p.segment]);
  const double offsetRate = c.perturbation.kind == Perturbation::Kind::Offset ? rate : 0;
  const double scaleRate = c.perturbation.kind == Perturbation::Kind::Scale ? rate : 0;
  return slope * (1 + offsetRate * c.gradSMax) + intercept * scaleRate * c.gradSMax;
}

// H over a set of pieces, with the pieces giving its deepest cut and highest ridge.
struct HeightSample {
  double height = 0;
  int deepest = -1, highest = -1;
};

HeightSample sampleHeight(const std::vector<Piece>& pieces, Vec2 x) {
  HeightSample out;
  double low = 0, high = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const double h = pieceHeight(pieces[i], x);
    if (h < low) low = h, out.deepest = static_cast<int>(i);
    if (h > high) high = h, out.highest = static_cast<int>(i);
  }
  out.height = low + high;
  return out;
}

// The material rule: the piece with the largest |h| (the earlier primitive on a tie), else base.
std::size_t materialOf(const std::vector<Piece>& pieces, Vec2 x, std::size_t base) {
  double best = 0;
  std::size_t bestPrimitive = 0, material = base;
  for (const Piece& p : pieces) {
    const double h = std::abs(pieceHeight(p, x));
    if (h > best || (h == best && h > 0 && p.c->primitive < bestPrimitive)) {
      best = h;
      bestPrimitive = p.c->primitive;
      material = p.c->material;
    }
  }
  return material;
}

// The active pieces at x among candidate components.
void piecesAt(const std::vector<const Component*>& candidates, Vec2 x, std::vector<Piece>& out) {
  out.clear();
  for (const Component* c : candidates) {
    if (!inRegion(*c, x)) continue;
    const int k = segmentOf(*c->profile, coordinateAt(*c, x).q);
    if (k >= 0) out.push_back({c, k});
  }
}

// The mitre direction at a joint from the tangents on both sides (a flat cut when they fold back).
Vec2 mitreOf(Vec2 before, Vec2 after) {
  const Vec2 m = unit(add(before, after));
  return length(m) > 0.5 ? m : after;
}

// The uniform grid of component bounds; under wrap it covers one period and cells repeat.
struct Grid {
  Vec2 origin;
  double cellU = 1, cellV = 1;
  long nu = 1, nv = 1;
  std::vector<std::vector<const Component*>> cells;
  const std::vector<const Component*>& cell(long i, long j) const { return cells[std::size_t(j * nu + i)]; }
};

struct Event {
  double t = 0;
  Vec2 wallNormal;  // horizontal normal of the line crossed here
};

struct Ray {
  Vec2 origin, dir;  // horizontal parts (origin shifted into the grid's period for the current cell)
  double originW = 0, dirW = 0;
  Vec2 at(double t) const { return add(origin, scaled(t, dir)); }
  double z(double t) const { return originW + t * dirW; }
};

// Shrinks a sign-change bracket [a, b] of a continuous f to `tolerance` by the Illinois variant of
// regula falsi (superlinear, and the bracket always holds the root); returns the final bracket, whose
// first end keeps f(a)'s sign.
template <class F>
std::pair<double, double> narrowBracket(F f, double a, double b, double fa, double fb, double tolerance) {
  int kept = 0;  // which end stayed last time: halve its value when it stays again
  for (int i = 0; i < 200 && b - a > tolerance; ++i) {
    double c = fa != fb ? (fa * b - fb * a) / (fa - fb) : 0.5 * (a + b);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double fc = f(c);
    if (fc == 0) return {std::nextafter(c, a), c};
    if ((fc > 0) == (fa > 0)) {
      a = c, fa = fc;
      if (kept == 1) fb *= 0.5;
      kept = 1;
    } else {
      b = c, fb = fc;
      if (kept == -1) fa *= 0.5;
      kept = -1;
    }
  }
  return {a, b};
}

// The parts of [ta, tb] where the ray's projection is within the groove's width of the path's line
// or circle (|b| <= grooveWidth): one interval for a line, up to two for an annulus.
std::vector<std::pair<double, double>> bandIntervals(const Component& c, const Ray& ray, double ta, double tb) {
  std::vector<std::pair<double, double>> out;
  const auto keep = [&](double lo, double hi) {
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
    if (hi > lo) out.push_back({lo, hi});
  };
  const double w = c.grooveWidth * (1 + 1e-9);
  if (!c.arc) {
    const double b0 = dot(sub(ray.origin, c.start), c.normal), rate = dot(ray.dir, c.normal);
    if (rate == 0) {
      if (std::abs(b0) <= w) keep(ta, tb);
      return out;
    }
    const double t1 = (-w - b0) / rate, t2 = (w - b0) / rate;
    keep(std::min(t1, t2), std::max(t1, t2));
    return out;
  }
  // Chords of the outer and inner circles: [outer in, inner in] and [inner out, outer out].
  const auto chord = [&](double rho, double& t1, double& t2) {
    const Vec2 d = sub(ray.origin, c.centre);
    const double a = dot(ray.dir, ray.dir), half = dot(d, ray.dir), disc = half * half - a * (dot(d, d) - rho * rho);
    if (rho <= 0 || disc < 0) return false;
    t1 = (-half - std::sqrt(disc)) / a;
    t2 = (-half + std::sqrt(disc)) / a;
    return true;
  };
  double o1 = 0, o2 = 0, i1 = 0, i2 = 0;
  if (!chord(c.radius + w, o1, o2)) return out;
  if (!chord(c.radius - w, i1, i2)) {
    keep(o1, o2);
    return out;
  }
  keep(o1, i1);
  keep(i2, o2);
  return out;
}

}  // namespace

struct ReferenceSurface::Impl {
  std::vector<ProfileTable> profiles;
  std::vector<Component> components;
  Grid grid;
  bool wrap = false;
  double period[2] = {1, 1};
  double hmax = 0, dmax = 0;
  double domainSize = 1;
  double featureSize = 1;  // smallest groove width, the scale of marching floors
  std::size_t baseMaterial = 0;

  explicit Impl(const GrooveScene& scene);
  void buildComponents(const GrooveScene& scene);
  void buildGrid();
  const std::vector<const Component*>* cellAt(Vec2 x, Vec2& shift) const;
  double height(Vec2 x) const;
  bool intersect(const Vec3& origin, const Vec3& dir, Hit& hit) const;

  // Ray walk state carried from one sub-interval to the next.
  struct Walk {
    Ray ray;
    double leftHeight = std::numeric_limits<double>::quiet_NaN();
    std::size_t leftMaterial = 0;
  };
  bool walkRange(Walk& walk, double t0, double t1, Hit& hit) const;
  bool solveCell(Walk& walk, const std::vector<const Component*>& candidates, double ta, double tb, Hit& hit) const;
  void eventsOf(const Component& c, const Ray& ray, double ta, double tb, std::vector<Event>& events) const;
  void numericEvents(const Component& c, const Ray& ray, double ta, double tb, std::vector<Event>& events) const;
  bool solveLinear(const Ray& ray, const std::vector<Piece>& pieces, double lo, double hi, double& tHit) const;
  bool solveMarching(const Ray& ray, const std::vector<Piece>& pieces, double lo, double hi, double& tHit) const;
  bool solveCone(const Ray& ray, const Piece& piece, double lo, double hi, double& tHit, bool& found) const;
  void finishHit(const Walk& walk, const std::vector<Piece>& pieces, double t, Hit& hit) const;
};

ReferenceSurface::Impl::Impl(const GrooveScene& scene) {
  wrap = scene.wrapRepeat;
  period[0] = scene.domain[0];
  period[1] = scene.domain[1];
  hmax = scene.hmax;
  dmax = scene.dmax;
  domainSize = std::max(scene.domain[0], scene.domain[1]);
  baseMaterial = scene.baseMaterial;
  featureSize = domainSize;
  for (const Groove& g : scene.grooves) featureSize = std::min(featureSize, g.wmax);
  for (const Profile& p : scene.profiles) profiles.push_back(tableOf(p));
  buildComponents(scene);
  buildGrid();
}

void ReferenceSurface::Impl::buildComponents(const GrooveScene& scene) {
  std::vector<Component> base;
  for (const Groove& groove : scene.grooves) {
    const std::size_t first = groove.firstPrimitive, count = groove.primitiveCount;
    for (std::size_t i = 0; i < count; ++i) {
      const Primitive& p = scene.primitives[first + i];
      Component c;
      c.primitive = first + i;
      c.material = groove.material;
      c.profile = &profiles[groove.profile];
      c.perturbation = groove.perturbation;
      c.arc = p.kind == Primitive::Kind::Arc;
      c.arcStart = p.arcStart;
      c.length = p.length;
      c.grooveWidth = groove.wmax;
      c.start = p.a;
      c.tangent = unit(sub(p.b, p.a));
      c.normal = leftNormal(c.tangent);
      if (c.arc) {
        c.centre = p.centre;
        c.radius = p.radius;
        c.turn = p.sweep < 0 ? -1 : 1;
        c.midAngle = p.startAngle + 0.5 * p.sweep;
        c.gradSMax = p.radius / std::max(p.radius - groove.wmax, 0.05 * p.radius);
      }
      // Joint lines: mitres with the neighbours, flat cuts at open ends (closed grooves wrap around).
      const bool openStart = !groove.closed && i == 0, openEnd = !groove.closed && i + 1 == count;
      const Primitive& before = scene.primitives[first + (i + count - 1) % count];
      const Primitive& after = scene.primitives[first + (i + 1) % count];
      c.joint0 = p.a;
      c.mitre0 = openStart ? p.tangentAt(0) : mitreOf(before.tangentAt(1), p.tangentAt(0));
      // Both sides of a joint use the same line, bit for bit (the next piece's start point), so the
      // regions neither overlap nor leave a sliver of flat surface between them (a false wall).
      c.joint1 = openEnd ? p.b : after.a;
      c.mitre1 = openEnd ? p.tangentAt(1) : mitreOf(p.tangentAt(1), after.tangentAt(0));
      // Bounds: the path's box grown by the width, stretched by the mitres (w / cos of half the turn).
      // (Nearly folded-back corners reach far: bounded by the domain size, beyond which the grid ends.)
      const double cosine = std::min(dot(c.mitre0, p.tangentAt(0)), dot(c.mitre1, p.tangentAt(1)));
      const double grow = std::min(1.01 * groove.wmax / std::max(cosine, 1e-9), 2 * domainSize);
      PlaneBounds box;
      box.take(p.a);
      box.take(p.b);
      if (c.arc) {
        for (int k = -8; k <= 8; ++k) {  // axis-aligned extremes inside the sweep
          const double angle = k * 0.5 * kPi;
          const double rel = (angle - p.startAngle) / p.sweep;
          if (rel > 0 && rel < 1)
            box.take({p.centre.u + p.radius * std::cos(angle), p.centre.v + p.radius * std::sin(angle)});
        }
      }
      c.box.lo = {box.lo.u - grow, box.lo.v - grow};
      c.box.hi = {box.hi.u + grow, box.hi.v + grow};
      base.push_back(c);
    }
  }
  if (!wrap) {
    components = std::move(base);
    return;
  }
  // Periodic copies: every translate by whole periods whose bounds overlap the period cell.
  for (const Component& c : base) {
    const auto first = [&](int axis, double hi) { return static_cast<long>(std::floor(-hi / period[axis])); };
    const auto last = [&](int axis, double lo) {
      return static_cast<long>(std::ceil((period[axis] - lo) / period[axis]));
    };
    const long i0 = first(0, c.box.hi.u), i1 = last(0, c.box.lo.u);
    const long j0 = first(1, c.box.hi.v), j1 = last(1, c.box.lo.v);
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j) {
        Component copy = translated(c, {i * period[0], j * period[1]});
        if (copy.box.hi.u < 0 || copy.box.lo.u > period[0] || copy.box.hi.v < 0 || copy.box.lo.v > period[1]) continue;
        components.push_back(copy);
      }
  }
}

void ReferenceSurface::Impl::buildGrid() {
  PlaneBounds bounds;
  bounds.take({0, 0});
  bounds.take({period[0], period[1]});
  if (!wrap) {
    // Regions far outside the domain (only from nearly folded-back mitres) are not indexed.
    for (const Component& c : components) {
      bounds.take({std::max(c.box.lo.u, -domainSize), std::max(c.box.lo.v, -domainSize)});
      bounds.take({std::min(c.box.hi.u, period[0] + domainSize), std::min(c.box.hi.v, period[1] + domainSize)});
    }
  }
  const double width = bounds.hi.u - bounds.lo.u, height = bounds.hi.v - bounds.lo.v;
  double maxWidth = 0;
  for (const Component& c : components) maxWidth = std::max(maxWidth, c.grooveWidth);
  if (!(maxWidth > 0)) maxWidth = kInf;
  // About four components per cell when they are small; long paths (each crossing many cells) ask
  // for cells of a few groove widths instead. At most 256 x 256 cells.
  const double cell = std::min(std::sqrt(width * height / (4.0 * components.size() + 1)), 8 * maxWidth);
  grid.origin = bounds.lo;
  grid.nu = std::clamp(static_cast<long>(std::ceil(width / cell)), 1L, 256L);
  grid.nv = std::clamp(static_cast<long>(std::ceil(height / cell)), 1L, 256L);
  grid.cellU = width / grid.nu;
  grid.cellV = height / grid.nv;
  grid.cells.assign(std::size_t(grid.nu * grid.nv), {});
  for (const Component& c : components) {
    const auto index = [&](double x, double o, double size, long n) {
      return std::clamp(static_cast<long>(std::floor((x - o) / size)), 0L, n - 1);
    };
    const long i0 = index(c.box.lo.u, grid.origin.u, grid.cellU, grid.nu);
    const long i1 = index(c.box.hi.u, grid.origin.u, grid.cellU, grid.nu);
    const long j0 = index(c.box.lo.v, grid.origin.v, grid.cellV, grid.nv);
    const long j1 = index(c.box.hi.v, grid.origin.v, grid.cellV, grid.nv);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) grid.cells[std::size_t(j * grid.nu + i)].push_back(&c);
  }
}

// The candidates at x and the whole-period shift that maps x into the grid's period (wrap).
const std::vector<const Component*>* ReferenceSurface::Impl::cellAt(Vec2 x, Vec2& shift) const {
  shift = {};
  if (wrap) {
    shift = {std::floor(x.u / period[0]) * period[0], std::floor(x.v / period[1]) * period[1]};
    x = sub(x, shift);
  }
  const long i = static_cast<long>(std::floor((x.u - grid.origin.u) / grid.cellU));
  const long j = static_cast<long>(std::floor((x.v - grid.origin.v) / grid.cellV));
  if (wrap) return &grid.cell(std::clamp(i, 0L, grid.nu - 1), std::clamp(j, 0L, grid.nv - 1));
  if (i < 0 || j < 0 || i >= grid.nu || j >= grid.nv) return nullptr;
  return &grid.cell(i, j);
}

double ReferenceSurface::Impl::height(Vec2 x) const {
  Vec2 shift;
  const std::vector<const Component*>* candidates = cellAt(x, shift);
  if (!candidates) return 0;
  std::vector<Piece> pieces;
  const Vec2 local = sub(x, shift);
  piecesAt(*candidates, local, pieces);
  return sampleHeight(pieces, local).height;
}

// Events of one component on [ta, tb]: joint-line crossings and profile-vertex crossings of q.
void ReferenceSurface::Impl::eventsOf(const Component& c, const Ray& ray, double ta, double tb,
                                      std::vector<Event>& events) const {
  const auto push = [&](double t, Vec2 normal) {
    if (t >= ta && t < tb) events.push_back({t, normal});  // one at ta names a wall met there
  };
  for (int end = 0; end < 2; ++end) {
    const Vec2 joint = end ? c.joint1 : c.joint0, mitre = end ? c.mitre1 : c.mitre0;
    const double rate = dot(ray.dir, mitre);
    if (rate != 0) push(dot(sub(joint, ray.origin), mitre) / rate, mitre);
  }
  if (c.perturbation.kind != Perturbation::Kind::None) return numericEvents(c, ray, ta, tb, events);
  const std::vector<double>& vertices = c.profile->b;
  if (!c.arc) {
    const double b0 = dot(sub(ray.origin, c.start), c.normal), rate = dot(ray.dir, c.normal);
    if (rate != 0)
      for (double bk : vertices) push((bk - b0) / rate, c.normal);
    return;
  }
  // |origin + t dir - centre| = radius - turn b_k: a quadratic in t.
  const Vec2 d = sub(ray.origin, c.centre);
  const double a = dot(ray.dir, ray.dir), half = dot(d, ray.dir);
  if (a == 0) return;
  for (double bk : vertices) {
    const double rho = c.radius - c.turn * bk;
    if (rho <= 0) continue;
    const double disc = half * half - a * (dot(d, d) - rho * rho);
    if (disc < 0) continue;
    const double root = half >= 0 ? -half - std::sqrt(disc) : -half + std::sqrt(disc);  // no cancellation
    const double tA = root / a, tB = root != 0 ? (dot(d, d) - rho * rho) / root : tA;
    for (double t : {tA, tB}) push(t, unit(sub(ray.at(t), c.centre)));
  }
}

// Perturbed components: q is not linear in t; its profile-vertex crossings are bracketed by steps that
// a Lipschitz bound of dq/dt cannot skip past (with a floor and a ceiling on the step), then bisected.
void ReferenceSurface::Impl::numericEvents(const Component& c, const Ray& ray, double ta, double tb,
                                           std::vector<Event>& events) const {
  // Only inside the joint half-planes does the component matter.
  for (int end = 0; end < 2; ++end) {
    const Vec2 joint = end ? c.joint1 : c.joint0, mitre = end ? c.mitre1 : c.mitre0;
    const double rate = dot(ray.dir, mitre), side = dot(sub(ray.origin, joint), mitre);
    const double sign = end ? -1 : 1;  // start: (x - j).m >= 0; end: <= 0
    if (rate == 0) {
      if (sign * side < 0) return;
      continue;
    }
    const double t = -side / rate;
    if (sign * rate > 0) ta = std::max(ta, t);
    else tb = std::min(tb, t);
  }
  if (!(tb > ta)) return;
  const double horizontal = length(ray.dir);
  if (horizontal == 0) return;
  const Perturbation& p = c.perturbation;
  // Inside the band |b| <= the groove's width (outside it |q| > wmax: no vertex to cross), |q| is
  // bounded, and so is |dq/dt|.
  const double sMin = minScale(p), rate = rateBound(p), qReach = c.grooveWidth / sMin;
  const double gradQ = (1 + (p.kind == Perturbation::Kind::Offset ? rate : 0) * c.gradSMax) / sMin +
                       (p.kind == Perturbation::Kind::Scale ? qReach * rate * c.gradSMax / sMin : 0);
  const double feature = std::min({p.wavelength, c.grooveWidth, c.arc ? c.radius : kInf});
  const double maxStep = 0.125 * feature / horizontal, minStep = 1e-3 * feature / horizontal;
  const std::vector<double>& vertices = c.profile->b;
  const auto slot = [&](double q) { return std::upper_bound(vertices.begin(), vertices.end(), q) - vertices.begin(); };
  const auto distance = [&](double q) {
    double best = kInf;
    for (double bk : vertices) best = std::min(best, std::abs(q - bk));
    return best;
  };
  for (const auto& [from, to] : bandIntervals(c, ray, ta, tb)) {
    double t = from;
    double q = coordinateAt(c, ray.at(t)).q;
    for (int guard = 0; guard < 1000000 && t < to; ++guard) {
      const double step = std::clamp(distance(q) / (horizontal * gradQ), minStep, maxStep);
      const double tn = std::min(to, t + step);
      const double qn = coordinateAt(c, ray.at(tn)).q;
      const auto slotLo = slot(q), slotHi = slot(qn);
      if (slotHi != slotLo) {
        // The vertex crossed; several distinct ones in one step (only at the step floor) are split
        // by bisection first.
        const auto first = std::min(slotLo, slotHi), last = std::max(slotLo, slotHi) - 1;
        double lo = t, hi = tn;
        if (vertices[std::size_t(first)] != vertices[std::size_t(last)]) {
          while (hi - lo > 1e-12 * domainSize) {
            const double mid = 0.5 * (lo + hi);
            (slot(coordinateAt(c, ray.at(mid)).q) == slotLo ? lo : hi) = mid;
          }
        } else {
          const double vertex = vertices[std::size_t(first)];
          const auto offsetFromVertex = [&](double at) { return coordinateAt(c, ray.at(at)).q - vertex; };
          std::tie(lo, hi) = narrowBracket(offsetFromVertex, lo, hi, q - vertex, qn - vertex, 1e-12 * domainSize);
        }
        if (hi > ta && hi < tb) events.push_back({hi, unit(coordinateAt(c, ray.at(hi)).gradQ)});
        t = hi;
        q = coordinateAt(c, ray.at(t)).q;
        continue;
      }
      t = tn;
      q = qn;
    }
  }
}

// All pieces straight and unperturbed: each height is linear in t; split where two heights (or one
// and 0) cross, then H is linear on each part and its first root is exact.
bool ReferenceSurface::Impl::solveLinear(const Ray& ray, const std::vector<Piece>& pieces, double lo, double hi,
                                         double& tHit) const {
  std::vector<double> at0(pieces.size()), at1(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    at0[i] = pieceHeight(pieces[i], ray.at(lo));
    at1[i] = pieceHeight(pieces[i], ray.at(hi));
  }
  std::vector<double> cuts{lo, hi};
  const auto crossing = [&](double d0, double d1) {  // root of a linear difference on [lo, hi]
    if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) cuts.push_back(lo + d0 / (d0 - d1) * (hi - lo));
  };
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    crossing(at0[i], at1[i]);
    for (std::size_t j = i + 1; j < pieces.size(); ++j) crossing(at0[i] - at0[j], at1[i] - at1[j]);
  }
  std::sort(cuts.begin(), cuts.end());
  const auto heightAt = [&](double t) {  // exact on [lo, hi]: the pieces are linear there
    const double w = (t - lo) / (hi - lo);
    double low = 0, high = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const double h = at0[i] + w * (at1[i] - at0[i]);
      low = std::min(low, h);
      high = std::max(high, h);
    }
    return low + high;
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double l = cuts[k], r = cuts[k + 1];
    if (!(r > l)) continue;
    const double gl = ray.z(l) - heightAt(l), gr = ray.z(r) - heightAt(r);
    if (gl <= 0) {
      tHit = l;
      return true;
    }
    if (gr <= 0) {
      tHit = l + gl / (gl - gr) * (r - l);
      return true;
    }
  }
  return false;
}

// One unperturbed arc piece alone: its surface is a cone about the arc's axis, h = slope b + intercept
// with b = turn (radius - r). z(t) = h(t) means r(t) = rho0 + rho1 t, a quadratic in t once squared:
// exact roots. Returns false (undecided: march instead) when the roots do not check out numerically.
bool ReferenceSurface::Impl::solveCone(const Ray& ray, const Piece& piece, double lo, double hi, double& tHit,
                                       bool& found) const {
  const Component& c = *piece.c;
  const double slope = c.profile->slope[piece.segment], intercept = c.profile->intercept[piece.segment];
  const auto gap = [&](double t) { return ray.z(t) - pieceHeight(piece, ray.at(t)); };
  const double scale = hmax + dmax + featureSize, tolerance = 1e-9 * scale;
  std::vector<double> roots;
  if (slope == 0) {  // a flat floor at height intercept
    if (ray.dirW != 0) roots.push_back((intercept - ray.originW) / ray.dirW);
  } else {
    // r = radius - (z - intercept) / (turn slope) = rho0 + rho1 t.
    const double k = 1 / (c.turn * slope);
    const double rho0 = c.radius - (ray.originW - intercept) * k, rho1 = -ray.dirW * k;
    const Vec2 d = sub(ray.origin, c.centre);
    const double a = dot(ray.dir, ray.dir) - rho1 * rho1, half = dot(d, ray.dir) - rho0 * rho1;
    const double constant = dot(d, d) - rho0 * rho0;
    if (std::abs(a) <= 1e-12 * (dot(ray.dir, ray.dir) + rho1 * rho1)) {
      if (half != 0) roots.push_back(-constant / (2 * half));
    } else {
      const double disc = half * half - a * constant;
      if (disc >= 0) {
        const double q = half >= 0 ? -half - std::sqrt(disc) : -half + std::sqrt(disc);
        roots.push_back(q / a);
        if (q != 0) roots.push_back(constant / q);
      }
    }
    // Squaring admits r = -rho: keep roots on the cone itself.
    std::erase_if(roots, [&](double t) { return rho0 + rho1 * t < 0; });
  }
  std::sort(roots.begin(), roots.end());
  for (double t : roots) {
    if (t < lo || t > hi) continue;
    if (std::abs(gap(t)) > tolerance) return false;
    tHit = t;
    found = true;
    return true;
  }
  found = false;
  return gap(hi) > -tolerance;  // no root: the ray must still be above at the end
}

// Arcs or perturbations: march with steps a Lipschitz bound of d(z - H)/dt cannot hide a root in,
// between a floor and a ceiling, then bisect the first bracket to 1e-12 of the domain size.
bool ReferenceSurface::Impl::solveMarching(const Ray& ray, const std::vector<Piece>& pieces, double lo, double hi,
                                           double& tHit) const {
  const double horizontal = length(ray.dir);
  double bound = 0, feature = kInf, depth = 0;
  for (const Piece& p : pieces) {
    bound = std::max(bound, pieceGradientBound(p));
    const Component& c = *p.c;
    feature = std::min({feature, c.grooveWidth, c.arc ? c.radius : kInf,
                        c.perturbation.kind != Perturbation::Kind::None ? c.perturbation.wavelength : kInf});
    depth = std::max(depth, c.profile->heightRange * (2 - minScale(c.perturbation)));
  }
  const double lipschitz = std::abs(ray.dirW) + horizontal * bound;
  const double stepScale = std::min(horizontal > 0 ? feature / horizontal : kInf,
                                    ray.dirW != 0 ? depth / std::abs(ray.dirW) : kInf);
  const double maxStep = std::isfinite(stepScale) ? 0.125 * stepScale : hi - lo;
  const double minStep = std::isfinite(stepScale) ? 1e-3 * stepScale : hi - lo;
  const auto gap = [&](double t) { return ray.z(t) - sampleHeight(pieces, ray.at(t)).height; };
  double t = lo, g = gap(lo);
  if (g <= 0) {
    tHit = lo;
    return true;
  }
  for (int guard = 0; guard < 1000000 && t < hi; ++guard) {
    const double step = std::clamp(lipschitz > 0 ? g / lipschitz : kInf, minStep, maxStep);
    const double tn = std::min(hi, t + step), gn = gap(tn);
    if (gn <= 0) {
      tHit = narrowBracket(gap, t, tn, g, gn, 1e-12 * domainSize).first;  // the side above the surface
      return true;
    }
    t = tn;
    g = gn;
  }
  return false;
}

void ReferenceSurface::Impl::finishHit(const Walk& walk, const std::vector<Piece>& pieces, double t, Hit& hit) const {
  const Vec2 x = walk.ray.at(t);
  const HeightSample sample = sampleHeight(pieces, x);
  Vec2 gradient;
  if (sample.deepest >= 0) gradient = add(gradient, pieceGradient(pieces[std::size_t(sample.deepest)], x));
  if (sample.highest >= 0) gradient = add(gradient, pieceGradient(pieces[std::size_t(sample.highest)], x));
  const double n = std::sqrt(1 + dot(gradient, gradient));
  hit.t = t;
  hit.point = {x.u, x.v, walk.ray.z(t)};
  hit.normal = {-gradient.u / n, -gradient.v / n, 1 / n};
  hit.material = materialOf(pieces, x, baseMaterial);
}

// One grid cell's stretch [ta, tb] of the ray: events, then each smooth sub-interval in turn.
bool ReferenceSurface::Impl::solveCell(Walk& walk, const std::vector<const Component*>& candidates, double ta,
                                       double tb, Hit& hit) const {
  const Ray& ray = walk.ray;
  std::vector<Event> events{{ta, {}}};
  for (const Component* c : candidates) eventsOf(*c, ray, ta, tb, events);
  std::sort(events.begin() + 1, events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
  events.push_back({tb, {}});
  const double jumpTolerance = 1e-9 * (hmax + dmax) + 1e-300;
  std::vector<Piece> pieces;
  for (std::size_t e = 0; e + 1 < events.size(); ++e) {
    const double lo = events[e].t, hi = events[e + 1].t;
    if (!(hi > lo)) continue;
    piecesAt(candidates, ray.at(0.5 * (lo + hi)), pieces);
    const double rightHeight = sampleHeight(pieces, ray.at(lo)).height;
    if (ray.z(lo) - rightHeight <= 0) {
      finishHit(walk, pieces, lo, hit);
      if (!std::isnan(walk.leftHeight) && rightHeight - walk.leftHeight > jumpTolerance) {
        // A vertical wall: horizontal normal of the crossed line, facing the ray.
        Vec2 normal = events[e].wallNormal;
        if (length(normal) == 0) normal = unit(ray.dir);
        if (dot(normal, ray.dir) > 0) normal = scaled(-1, normal);
        hit.normal = {normal.u, normal.v, 0};
        if (std::abs(walk.leftHeight) > std::abs(rightHeight)) hit.material = walk.leftMaterial;
      }
      return true;
    }
    const bool linear = std::all_of(pieces.begin(), pieces.end(), [](const Piece& p) { return p.c->linear(); });
    const bool cone =
        pieces.size() == 1 && pieces[0].c->arc && pieces[0].c->perturbation.kind == Perturbation::Kind::None;
    double tHit = 0;
    bool found = false;
    if (linear) found = solveLinear(ray, pieces, lo, hi, tHit);
    else if (!cone || !solveCone(ray, pieces[0], lo, hi, tHit, found)) found = solveMarching(ray, pieces, lo, hi, tHit);
    if (found) {
      finishHit(walk, pieces, tHit, hit);
      return true;
    }
    walk.leftHeight = sampleHeight(pieces, ray.at(hi)).height;
    walk.leftMaterial = materialOf(pieces, ray.at(hi), baseMaterial);
  }
  return false;
}

// Walks [t0, t1] through the grid cells the ray's projection crosses (2D DDA).
bool ReferenceSurface::Impl::walkRange(Walk& walk, double t0, double t1, Hit& hit) const {
  static const std::vector<const Component*> none;
  Ray& ray = walk.ray;
  const Vec2 unshifted = ray.origin;
  const Vec2 start = ray.at(t0 + 1e-9 * (t1 - t0));
  long i = static_cast<long>(std::floor((start.u - grid.origin.u) / grid.cellU));
  long j = static_cast<long>(std::floor((start.v - grid.origin.v) / grid.cellV));
  if (!wrap) {
    i = std::clamp(i, 0L, grid.nu - 1);
    j = std::clamp(j, 0L, grid.nv - 1);
  }
  const long stepI = ray.dir.u > 0 ? 1 : -1, stepJ = ray.dir.v > 0 ? 1 : -1;
  const auto boundary = [&](long index, long step, double origin, double cell, double o, double d) {
    if (d == 0) return kInf;
    return (origin + (index + (step > 0 ? 1 : 0)) * cell - o) / d;
  };
  double t = t0;
  for (long guard = 0; guard < 10000000; ++guard) {
    const double nextU = boundary(i, stepI, grid.origin.u, grid.cellU, unshifted.u, ray.dir.u);
    const double nextV = boundary(j, stepJ, grid.origin.v, grid.cellV, unshifted.v, ray.dir.v);
    const double tNext = std::min({nextU, nextV, t1});
    const long si = wrap ? ((i % grid.nu) + grid.nu) % grid.nu : i, sj = wrap ? ((j % grid.nv) + grid.nv) % grid.nv : j;
    const bool inside = si >= 0 && sj >= 0 && si < grid.nu && sj < grid.nv;
    const Vec2 shift =
        wrap ? Vec2{double((i - si) / grid.nu) * period[0], double((j - sj) / grid.nv) * period[1]} : Vec2{};
    ray.origin = sub(unshifted, shift);
    if (tNext > t) {
      if (solveCell(walk, inside ? grid.cell(si, sj) : none, t, tNext, hit)) {
        hit.point.u += shift.u;
        hit.point.v += shift.v;
        ray.origin = unshifted;
        return true;
      }
    }
    ray.origin = unshifted;
    if (tNext >= t1) return false;
    t = tNext;
    if (nextU <= nextV) i += stepI;
    else j += stepJ;
    if (!wrap && (i < 0 || j < 0 || i >= grid.nu || j >= grid.nv)) return false;
  }
  return false;
}

bool ReferenceSurface::Impl::intersect(const Vec3& origin, const Vec3& direction, Hit& hit) const {
  const double norm = std::sqrt(direction.u * direction.u + direction.v * direction.v + direction.w * direction.w);
  if (!(norm > 0)) return false;
  Walk walk;
  walk.ray.origin = {origin.u, origin.v};
  walk.ray.originW = origin.w;
  walk.ray.dir = {direction.u / norm, direction.v / norm};
  walk.ray.dirW = direction.w / norm;
  const Ray& ray = walk.ray;
  // Only where z lies within [-dmax, hmax] can the ray meet the surface (with a small margin).
  const double margin = 1e-9 * (hmax + dmax + featureSize);
  const double top = hmax + margin, bottom = -dmax - margin;
  double t0 = 0, t1 = kInf;
  if (ray.dirW > 0) {
    if (origin.w > top) return false;
    t1 = (top - origin.w) / ray.dirW;
  } else if (ray.dirW < 0) {
    t0 = std::max(0.0, (top - origin.w) / ray.dirW);
    t1 = (bottom - origin.w) / ray.dirW;
  } else if (origin.w > top) {
    return false;
  }
  if (length(ray.dir) == 0 && ray.dirW == 0) return false;
  // The grid's extent along the ray (outside it the surface is the plane h = 0, or repeats).
  if (!wrap) {
    double g0 = -kInf, g1 = kInf;
    const double lo[2] = {grid.origin.u, grid.origin.v};
    const double hi[2] = {grid.origin.u + grid.nu * grid.cellU, grid.origin.v + grid.nv * grid.cellV};
    const double o[2] = {ray.origin.u, ray.origin.v}, d[2] = {ray.dir.u, ray.dir.v};
    for (int axis = 0; axis < 2; ++axis) {
      if (d[axis] == 0) {
        if (o[axis] < lo[axis] || o[axis] > hi[axis]) g0 = kInf, g1 = -kInf;
        continue;
      }
      const double a = (lo[axis] - o[axis]) / d[axis], b = (hi[axis] - o[axis]) / d[axis];
      g0 = std::max(g0, std::min(a, b));
      g1 = std::min(g1, std::max(a, b));
    }
    if (!std::isfinite(t1)) t1 = std::isfinite(g1) ? std::max(g1, t0) + 1 : t0 + 1;
    // Before the grid, inside it, after it (the flat plane outside).
    const double cutA = std::clamp(g0, t0, t1), cutB = std::clamp(g1, cutA, t1);
    static const std::vector<const Component*> none;
    const bool found = (cutA > t0 && solveCell(walk, none, t0, cutA, hit)) ||
                       (cutB > cutA && walkRange(walk, cutA, cutB, hit)) ||
                       (t1 > cutB && solveCell(walk, none, cutB, t1, hit));
    hit.t /= norm;  // back to the caller's parameter
    return found;
  }
  // Under wrap a horizontal ray inside the slab never leaves it: it is followed 1000 periods.
  if (!std::isfinite(t1)) t1 = t0 + 1e3 * domainSize / length(ray.dir);
  const bool found = walkRange(walk, t0, t1, hit);
  hit.t /= norm;
  return found;
}

ReferenceSurface::ReferenceSurface(const GrooveScene& scene) : impl_(new Impl(scene)) {}
ReferenceSurface::~ReferenceSurface() { delete impl_; }
double ReferenceSurface::height(Vec2 x) const { return impl_->height(x); }
bool ReferenceSurface::intersect(const Vec3& origin, const Vec3& dir, Hit& hit) const {
  return impl_->intersect(origin, dir, hit);
}

}  // namespace bake::grooves
