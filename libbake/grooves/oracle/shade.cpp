// The seed's method per pixel (seed 000 §4): find the grooves that can affect the footprint, detect
// special cases, and shade by line sampling (§5, line_sampling.cpp) or area sampling (§6,
// area_sampling.cpp).
//
// Finding grooves (§4.1): the bounding box of the footprint parallelogram, enlarged by the scene's wmax
// (bands whose path lies outside the box), and by hmax and dmax projected along the view and along the
// light: a ridge of height hmax seen (or casting a shadow) through the footprint stands up to
// hmax |E_uv| / E_w towards the viewer (the light), a cavity point of depth dmax up to dmax |E_uv| / E_w
// away from it. The light's reach is capped at kMaxReach heights (a light at or below the horizon
// would need an unbounded box; ridges further away are not found, so their shadows are missed).
// Special cases (§4.2): a special-case record of the grid whose box meets the footprint's box swept
// along view and light (not grown by wmax: a record's box holds its bands) sends the pixel to area
// sampling. No groove: the flat base. A footprint near the centre of an arc (within 1.5 times its
// half-extent) is line sampled as 3 x 3 sub-footprints (nearArcCentre; not in the seed).
#include "grooves/oracle/shade.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "bake_formats/grooves.h"
#include "core/parallel.h"
#include "grooves/oracle/line_sampling_section.h"

namespace bake::grooves {
namespace {

constexpr double kMaxReach = format::grooves::kMaxReach;  // |D_uv| / D_w at most

struct Box {
  Vec2 lower, upper;
  void include(Vec2 p) {
    lower = {std::min(lower.u, p.u), std::min(lower.v, p.v)};
    upper = {std::max(upper.u, p.u), std::max(upper.v, p.v)};
  }
};

// Shifts the box by the projections of a ridge (towards the direction) and a cavity (away from it).
void enlargeAlong(Box& box, const Box& core, const Vec3& d, double hmax, double dmax) {
  const double horizontal = std::sqrt(d.u * d.u + d.v * d.v);  // d is a unit direction: no overflow
  if (horizontal == 0) return;
  const double reach = travelPerDepth(d);
  const Vec2 unit{d.u / horizontal, d.v / horizontal};
  for (double along : {hmax * reach, -dmax * reach}) {
    box.include({core.lower.u + along * unit.u, core.lower.v + along * unit.v});
    box.include({core.upper.u + along * unit.u, core.upper.v + along * unit.v});
  }
}

// The footprint's box grown by `width` (wmax to find the bands that reach it, 0 for the special-case
// records, whose boxes hold their bands already) and swept along the view and the light.
Box queryBox(const GrooveScene& scene, const Footprint& f, const Vec3& toViewer, const Vec3& toLight, double width) {
  const double eu = 0.5 * (std::abs(f.axis1.u) + std::abs(f.axis2.u)) + width;
  const double ev = 0.5 * (std::abs(f.axis1.v) + std::abs(f.axis2.v)) + width;
  const Box core{{f.centre.u - eu, f.centre.v - ev}, {f.centre.u + eu, f.centre.v + ev}};
  Box box = core;
  enlargeAlong(box, core, toViewer, scene.hmax, scene.dmax);
  // Towards the light, a shadow ray from a cavity point of depth dmax climbs dmax before it clears
  // the base plane: its occluders (a ridge, or the far wall of a crossing cavity) lie up to
  // (hmax + dmax) |L_uv| / L_w away.
  enlargeAlong(box, core, toLight, scene.hmax + scene.dmax, scene.dmax);
  return box;
}

// Squared distance from x to the primitive (to compare copies of x).
double squaredDistanceToPrimitive(const Primitive& p, Vec2 x) {
  auto squared = [](double du, double dv) { return du * du + dv * dv; };
  if (p.kind == Primitive::Kind::Segment) {
    const double du = p.b.u - p.a.u, dv = p.b.v - p.a.v;
    const double length2 = du * du + dv * dv;
    const double t = length2 > 0 ? std::clamp(((x.u - p.a.u) * du + (x.v - p.a.v) * dv) / length2, 0.0, 1.0) : 0;
    return squared(x.u - p.a.u - t * du, x.v - p.a.v - t * dv);
  }
  const double angle = std::atan2(x.v - p.centre.v, x.u - p.centre.u);
  const double fromMiddle = std::remainder(angle - (p.startAngle + 0.5 * p.sweep), 2 * std::numbers::pi);
  if (std::abs(fromMiddle) <= 0.5 * std::abs(p.sweep)) {
    const double off = std::sqrt(squared(x.u - p.centre.u, x.v - p.centre.v)) - p.radius;
    return off * off;
  }
  return std::min(squared(x.u - p.a.u, x.v - p.a.v), squared(x.u - p.b.u, x.v - p.b.v));
}

// The copy of the footprint centre nearest the primitive (the scene may repeat).
Vec2 nearestCopy(const GrooveScene& scene, const Primitive& p, Vec2 centre) {
  if (!scene.wrapRepeat) return centre;
  Vec2 best = centre;
  double bestDistance = squaredDistanceToPrimitive(p, centre);
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      const Vec2 copy{centre.u + i * scene.domain[0], centre.v + j * scene.domain[1]};
      const double d = squaredDistanceToPrimitive(p, copy);
      if (d < bestDistance) {
        bestDistance = d;
        best = copy;
      }
    }
  return best;
}

bool boxesMeet(const Box& a, Vec2 lower, Vec2 upper) {
  return a.lower.u <= upper.u && lower.u <= a.upper.u && a.lower.v <= upper.v && lower.v <= a.upper.v;
}

// Does a record's box meet the query box (or one of its copies, when the scene repeats)?
bool meetsRecord(const GrooveScene& scene, const Box& box, const SpecialRecord& record) {
  const int copies = scene.wrapRepeat ? 1 : 0;
  for (int i = -copies; i <= copies; ++i)
    for (int j = -copies; j <= copies; ++j) {
      const Vec2 shift{i * scene.domain[0], j * scene.domain[1]};
      const Box moved{{box.lower.u + shift.u, box.lower.v + shift.v}, {box.upper.u + shift.u, box.upper.v + shift.v}};
      if (boxesMeet(moved, record.lower, record.upper)) return true;
    }
  return false;
}

// Footprint boxes wider than this many cells in both directions read only the cells on the box's
// boundary (§4.1: "paths are rarely shorter than a pixel footprint, interior cells can be omitted"),
// so the cost of a far-away pixel over thousands of grooves grows with its perimeter, not its area.
// Grooves lying wholly inside such a footprint are missed.
constexpr double kBoundaryOnlyCells = 8;

// A thread's last gather, for the shader that made it: the boxes of neighbouring pixels mostly meet
// the same cells (their spans are equal), and then list the same primitives (records).
struct GatherMemo {
  std::uint64_t shader = 0;  // 0: nothing remembered (serials start at 1)
  CellSpan span;
  std::vector<std::uint32_t> found;
};

enum class Gather { Primitives, Records };

const std::vector<std::uint32_t>& gatherInBox(GatherMemo& memo, std::uint64_t shader, const GrooveGrid& grid,
                                              const Box& box, Gather what) {
  const bool valid = box.lower.u <= box.upper.u && box.lower.v <= box.upper.v;  // not NaN
  const CellSpan span = valid ? grid.cellSpan(box.lower, box.upper) : CellSpan{};
  if (valid && memo.shader == shader && memo.span == span) return memo.found;
  if (what == Gather::Primitives)
    grid.primitivesInBox(box.lower, box.upper, memo.found);
  else
    grid.recordsInBox(box.lower, box.upper, memo.found);
  memo.shader = valid ? shader : 0;
  memo.span = span;
  return memo.found;
}

const std::vector<std::uint32_t>& gatherPrimitives(const GrooveGrid& grid, std::uint64_t shader, const Box& box) {
  thread_local GatherMemo memo;
  thread_local std::vector<std::uint32_t> out;
  const double cellsU = (box.upper.u - box.lower.u) / grid.cellSize.u;
  const double cellsV = (box.upper.v - box.lower.v) / grid.cellSize.v;
  if (!(cellsU > kBoundaryOnlyCells && cellsV > kBoundaryOnlyCells))
    return gatherInBox(memo, shader, grid, box, Gather::Primitives);
  const Vec2 corners[4] = {box.lower, {box.upper.u, box.lower.v}, box.upper, {box.lower.u, box.upper.v}};
  GridBox edges[4];
  for (int k = 0; k < 4; ++k) {
    const Vec2 a = corners[k], b = corners[(k + 1) % 4];
    edges[k] = {{std::min(a.u, b.u), std::min(a.v, b.v)}, {std::max(a.u, b.u), std::max(a.v, b.v)}};
  }
  grid.primitivesInBoxes(edges, 4, out);
  return out;
}

// Curved sections (SeedSettings::curvedSections) shade a footprint on one section, turned with the
// circle to first order across the footprint (line_sampling.cpp). Near an arc's centre the footprint
// spans a wide fan of the arc's directions and that fails (the turning rates grow as 1 / distance):
// a footprint whose centre lies within 1.5 half-extents of an arc's centre is shaded as
// kCentreSplit x kCentreSplit sub-footprints, each with its own foot points. Not in the seed.
constexpr int kCentreSplit = 3;
constexpr double kNearCentre = 1.5;  // footprint half-extents

bool nearArcCentre(const GrooveScene& scene, const std::vector<std::uint32_t>& found, const Footprint& f) {
  const double extent = 0.5 * (std::hypot(f.axis1.u, f.axis1.v) + std::hypot(f.axis2.u, f.axis2.v));
  for (std::uint32_t p : found) {
    const Primitive& arc = scene.primitives[p];
    if (arc.kind != Primitive::Kind::Arc) continue;
    Vec2 d{f.centre.u - arc.centre.u, f.centre.v - arc.centre.v};
    if (scene.wrapRepeat) {
      d.u -= scene.domain[0] * std::round(d.u / scene.domain[0]);
      d.v -= scene.domain[1] * std::round(d.v / scene.domain[1]);
    }
    if (std::hypot(d.u, d.v) < kNearCentre * extent) return true;
  }
  return false;
}

}  // namespace

double travelPerDepth(const Vec3& d) {
  const double horizontal = std::sqrt(d.u * d.u + d.v * d.v);
  return d.w > horizontal / kMaxReach ? horizontal / d.w : kMaxReach;
}

SeedShader::SeedShader(const GrooveScene& scene, const GrooveGrid& grid, const SeedSettings& settings)
    : scene_(scene), grid_(grid), settings_(settings) {
  static std::atomic<std::uint64_t> shaders{0};
  serial_ = ++shaders;
}

Rgb SeedShader::shade(const Footprint& footprint, const Vec3& toViewer, const Lighting& lighting,
                      ShadeStats* stats) const {
  const Box box = queryBox(scene_, footprint, toViewer, lighting.toLight, scene_.wmax);
  thread_local std::vector<LocalGroove> grooves;
  const std::vector<std::uint32_t>& found = gatherPrimitives(grid_, serial_, box);
  if (stats) *stats = {false, std::uint32_t(found.size())};
  if (found.empty()) return flatBaseRadiance(scene_.materials[scene_.baseMaterial], toViewer, lighting);
  // A footprint wider than the period of a repeating pattern: the grooves, straightened at their copy
  // nearest F, would each be counted once; the far level counts every copy (whole periods exactly).
  const bool beyondPeriod =
      scene_.wrapRepeat && (std::abs(footprint.axis1.u) + std::abs(footprint.axis2.u) > scene_.domain[0] ||
                            std::abs(footprint.axis1.v) + std::abs(footprint.axis2.v) > scene_.domain[1]);
  const bool overCap = settings_.foundCap > 0 && found.size() > settings_.foundCap;
  if ((beyondPeriod || overCap) && !grid_.far.empty()) {
    if (stats) stats->far = true;
    return shadeFromFarLevel(scene_, grid_, footprint, toViewer, lighting, settings_);
  }

  // The primitives found, straightened at the footprint centred at `centre`.
  const bool jointsKnown = grid_.joints.size() == scene_.primitives.size();
  auto straightenAt = [&](Vec2 centre) {
    grooves.clear();
    for (std::uint32_t p : found) {
      const Vec2 at = nearestCopy(scene_, scene_.primitives[p], centre);
      grooves.push_back(jointsKnown ? localGroove(scene_, p, at, grid_.joints[p]) : localGroove(scene_, p, at));
    }
  };
  straightenAt(footprint.centre);
  // §4.2: a special case is an intersection or an end inside the box. A record's box already holds
  // the bands around its point (the overlap of two regions, an end's cut and walls, a mitre), so it
  // is met against the footprint's box swept along view and light, not grown by wmax again.
  // Records anywhere under the box count (an intersection inside a wide footprint is still one);
  // when the box covers more cells than there are records, testing every record is cheaper.
  const Box recordBox = queryBox(scene_, footprint, toViewer, lighting.toLight, 0);
  const double boxCells = (recordBox.upper.u - recordBox.lower.u) / grid_.cellSize.u *
                          ((recordBox.upper.v - recordBox.lower.v) / grid_.cellSize.v);
  bool special = false;
  if (boxCells > double(grid_.records.size())) {
    special = std::any_of(grid_.records.begin(), grid_.records.end(),
                          [&](const SpecialRecord& record) { return meetsRecord(scene_, recordBox, record); });
  } else {
    thread_local GatherMemo memo;
    const std::vector<std::uint32_t>& records = gatherInBox(memo, serial_, grid_, recordBox, Gather::Records);
    special = std::any_of(records.begin(), records.end(),
                          [&](std::uint32_t r) { return meetsRecord(scene_, recordBox, grid_.records[r]); });
  }
  if (stats) stats->special = special;
  if (special) return areaSample(scene_, grooves, footprint, toViewer, lighting, settings_.areaReflections);
  if (!settings_.curvedSections || !nearArcCentre(scene_, found, footprint))
    return lineSampleWith(scene_, grooves, footprint, toViewer, lighting, settings_);
  constexpr int n = kCentreSplit;
  const Vec2 a1{footprint.axis1.u / n, footprint.axis1.v / n}, a2{footprint.axis2.u / n, footprint.axis2.v / n};
  Rgb sum{0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double s1 = i + 0.5 - 0.5 * n, s2 = j + 0.5 - 0.5 * n;
      const Footprint sub{{footprint.centre.u + s1 * a1.u + s2 * a2.u, footprint.centre.v + s1 * a1.v + s2 * a2.v},
                          a1, a2};
      straightenAt(sub.centre);
      const Rgb v = lineSampleWith(scene_, grooves, sub, toViewer, lighting, settings_);
      for (int c = 0; c < 3; ++c) sum[c] += v[c] / (n * n);
    }
  return sum;
}

Image renderSeed(const GrooveScene& scene, const GrooveGrid& grid, const View& view, const Lighting& lighting,
                    int threads, const SeedSettings& settings) {
  Image image = rgbImage(view.width, view.height);
  const SeedShader shader(scene, grid, settings);
  parallelFor(
      std::size_t(std::max(0, view.height)), resolveThreadCount(unsigned(std::max(0, threads))),
      [&](std::size_t y) {
        for (int x = 0; x < view.width; ++x)
          setRgb(image, x, int(y), shader.shade(view.pixel(x, int(y)), view.toViewer, lighting));
      },
      1);
  return image;
}

}  // namespace bake::grooves
