// A small tree of paintstrokes: seed 002 names "fine branches" among the phenomena paintstrokes
// model, and its self-shadowing "can also be applied to other models, such as trees".
//
// Recursive branching in the manner of Honda's and Aono-Kunii's models (a branch ends where its
// children start, each child turned away from the parent's end direction by a spread angle, the
// children spaced evenly around it with a random twist): the trunk grows along +y from `origin`, and
// every branch of level l < depth carries `branching` children of level l + 1. A branch is one stroke
// of `pointsPerStroke` points along a circular arc of small random curvature (a gently curved limb,
// not a polyline of kinks). Lengths shrink by `lengthRatio` and radii by `radiusRatio` per level; a
// branch's radius runs linearly from its level's radius to the next level's, so a child starts with
// exactly its parent's end radius and position (the joints are continuous). Colour runs from bark to
// twig with (level + position along the branch) / (depth + 1), continuous at the joints too.
//
// Self-shadowing (seed 002's paragraph on global normal and depth): the crown is every branch but the
// trunk; its bounding sphere (centre of the bounding box, radius to the farthest point) gives each
// point the global normal pointing away from the centre and the depth 1 - distance / radius (1 at the
// centre, 0 on the sphere, clamped for the trunk's foot outside it).
//
// Strokes come out breadth first: stroke i's children are strokes i b + 1 .. i b + b (b = branching),
// drawn from one std::mt19937_64 seeded by `seed` in that order, so a seed gives the same tree everywhere.
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

#include "bake/paintstrokes/generators.h"
#include "bake_formats/paintstrokes.h"
#include "paintstrokes/input/generator_math.h"

namespace bake::paintstrokes {
namespace {

using namespace detail;

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kMaxCurveDegrees = 25;  // total turn of one branch's arc, at most
constexpr double kLengthJitter = 0.15;   // relative random variation of a branch's length
constexpr double kUpwardPull = 0.15;     // children lean this much towards +y (branches reach for light)
const Vec3d kUp{0, 1, 0};

struct PendingBranch {
  Vec3d start, direction;
  int level = 0;
};

// One branch as a stroke; returns the direction at its end (where its children start).
Vec3d growBranch(const TreeSettings& s, const PendingBranch& branch, Random& random, Stroke& stroke) {
  const double length = s.height * std::pow(s.lengthRatio, branch.level) * (1 + kLengthJitter * random.uniform(-1, 1));
  const double r0 = s.trunkRadius * std::pow(s.radiusRatio, branch.level);
  const double r1 = r0 * s.radiusRatio;
  const Vec3d axis = rotate(anyOrthogonal(branch.direction), branch.direction, random.uniform(0, 2 * std::numbers::pi));
  const double turn = random.uniform(0, kMaxCurveDegrees * kDegree);
  const int n = s.pointsPerStroke;
  const double segment = length / (n - 1);
  stroke.style = s.style;
  stroke.points.resize(std::size_t(n));
  Vec3d position = branch.start;
  for (int k = 0; k < n; ++k) {
    const double u = double(k) / (n - 1);
    if (k > 0) {
      // The chord of each arc segment points along the tangent at the segment's middle.
      position = add(position, scale(rotate(branch.direction, axis, turn * (k - 0.5) / (n - 1)), segment));
    }
    StrokePoint& p = stroke.points[std::size_t(k)];
    p.position = position;
    p.radius = r0 + (r1 - r0) * u;
    p.colour = lerp(s.barkColour, s.twigColour, (branch.level + u) / (s.depth + 1));
  }
  return rotate(branch.direction, axis, turn);
}

}  // namespace

std::uint64_t treeStrokeCount(const TreeSettings& s) {
  std::uint64_t total = 0, level = 1;
  for (int l = 0; l <= s.depth; ++l) {
    total += level;
    if (total > kMaxGeneratedStrokes) return kMaxGeneratedStrokes + 1;  // saturate: no overflow
    level *= std::uint64_t(std::max(s.branching, 1));
  }
  return total;
}

Status checkTreeSettings(const TreeSettings& s) {
  if (s.depth < 0 || s.depth > 20) return badSetting("depth", "must be within 0 .. 20");
  if (s.branching < 1 || s.branching > 16) return badSetting("branching", "must be within 1 .. 16");
  if (treeStrokeCount(s) > kMaxGeneratedStrokes) {
    return badSetting("depth", "a tree of depth " + std::to_string(s.depth) + " with branching " +
                                   std::to_string(s.branching) + " would exceed " + std::to_string(kMaxGeneratedStrokes) +
                                   " strokes");
  }
  if (!(s.height > 0) || !std::isfinite(s.height)) return badSetting("height", "must be a finite number > 0");
  if (!(s.trunkRadius > 0) || !std::isfinite(s.trunkRadius)) return badSetting("trunkRadius", "must be a finite number > 0");
  if (!(s.lengthRatio > 0) || !(s.lengthRatio <= 1.5)) return badSetting("lengthRatio", "must be within (0, 1.5]");
  // Below 1: radii must shrink towards the twigs (and a tree of depth 20 must not explode).
  if (!(s.radiusRatio > 0) || !(s.radiusRatio < 1)) return badSetting("radiusRatio", "must be within (0, 1)");
  if (!(s.spreadDegrees >= 0) || !(s.spreadDegrees <= 180)) return badSetting("spreadDegrees", "must be within [0, 180]");
  if (s.pointsPerStroke < 2 || s.pointsPerStroke > 64) return badSetting("pointsPerStroke", "must be within 2 .. 64");
  if (!isUnit(s.barkColour)) return badSetting("barkColour", "every component must be within [0, 1]");
  if (!isUnit(s.twigColour)) return badSetting("twigColour", "every component must be within [0, 1]");
  if (!std::all_of(s.origin.begin(), s.origin.end(), [](double x) { return std::isfinite(x); })) {
    return badSetting("origin", "every component must be finite");
  }
  if (s.style >= format::paintstrokes::kMaxStyles) {
    return badSetting("style", "must be a style index below " + std::to_string(format::paintstrokes::kMaxStyles));
  }
  return Status::ok();
}

StrokeSet growTree(const TreeSettings& s) {
  StrokeSet set;
  set.styles.resize(s.style + 1);  // a complete set on its own; runGenerator keeps only the strokes
  set.strokes.reserve(treeStrokeCount(s));
  Random random(s.seed);
  std::deque<PendingBranch> queue{{s.origin, kUp, 0}};
  while (!queue.empty()) {
    const PendingBranch branch = queue.front();
    queue.pop_front();
    Stroke stroke;
    const Vec3d end = growBranch(s, branch, random, stroke);
    const Vec3d tip = stroke.points.back().position;
    set.strokes.push_back(std::move(stroke));
    if (branch.level == s.depth) continue;
    const Vec3d first = anyOrthogonal(end);
    const double twist = random.uniform(0, 2 * std::numbers::pi);
    for (int j = 0; j < s.branching; ++j) {
      const double azimuth = twist + 2 * std::numbers::pi * j / s.branching;
      const double spread = s.spreadDegrees * kDegree * random.uniform(0.7, 1.3);
      const Vec3d axis = rotate(first, end, azimuth);
      const Vec3d direction = normalized(add(rotate(end, axis, spread), scale(kUp, kUpwardPull)), end);
      queue.push_back({tip, direction, branch.level + 1});
    }
  }

  // The crown's bounding sphere: global normals and depths for the self-shadowing.
  const std::size_t firstCrown = set.strokes.size() > 1 ? 1 : 0;
  Vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = firstCrown; i < set.strokes.size(); ++i) {
    for (const StrokePoint& p : set.strokes[i].points) {
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p.position[c]), hi[c] = std::max(hi[c], p.position[c]);
    }
  }
  const Vec3d centre = scale(add(lo, hi), 0.5);
  double radius = 0;
  for (std::size_t i = firstCrown; i < set.strokes.size(); ++i) {
    for (const StrokePoint& p : set.strokes[i].points) radius = std::max(radius, length(sub(p.position, centre)));
  }
  for (Stroke& stroke : set.strokes) {
    for (StrokePoint& p : stroke.points) {
      const Vec3d away = sub(p.position, centre);
      p.globalNormal = normalized(away, kUp);
      p.depth = radius > 0 ? std::clamp(1 - length(away) / radius, 0.0, 1.0) : 0.0;
    }
  }
  return set;
}

}  // namespace bake::paintstrokes
