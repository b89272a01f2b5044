// Candidate strokes of a tonal art map (Praun, Hoppe, Webb, Finkelstein, "Real-time hatching",
// SIGGRAPH 2001, section 3.2: "we select the best of several random candidate strokes"). A candidate
// is drawn from the style's ranges: centre uniform over the tile, direction = the style's angle plus
// a uniform jitter (cross-hatching: from tone `crossFrom` on, each candidate takes the crossing
// direction angle + crossAngle with probability 1/2, so the choice by progress balances the two),
// length uniform in the length range (fraction of the tile; a stipple dot is a round dot, a stroke of
// zero length with no taper, which the rasterizer draws as a disc of its width at every level),
// width uniform in the width range (pixels, the same at every level),
// a slight bend through a middle control point displaced sideways by up to curvature x length, and
// the style's taper and breadthwise opacity. Image strokes are straight and carry the stroke image.
// Random numbers come from a counter-based generator keyed by (seed, tone, level, step, candidate),
// so the strokes do not depend on the thread count.
#include <cmath>
#include <numbers>

#include "hatching/bake/build_stages.h"

namespace bake::hatching::detail {
namespace {

std::uint64_t mix(std::uint64_t z) {  // SplitMix64 finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;

}  // namespace

StrokeRandom::StrokeRandom(std::uint64_t seed, int tone, int level, std::int64_t step, int candidate) {
  std::uint64_t h = mix(seed + kGolden);
  h = mix(h ^ (std::uint64_t(std::uint32_t(tone)) + kGolden));
  h = mix(h ^ (std::uint64_t(std::uint32_t(level)) * 3 + kGolden));
  h = mix(h ^ (std::uint64_t(step) * 5 + kGolden));
  h = mix(h ^ (std::uint64_t(std::uint32_t(candidate)) * 7 + kGolden));
  state_ = h;
}

std::uint64_t StrokeRandom::next() {
  state_ += kGolden;
  return mix(state_);
}

double StrokeRandom::uniform() { return double(next() >> 11) * 0x1.0p-53; }

double StrokeRandom::uniform(double low, double high) { return low + (high - low) * uniform(); }

stroke::Paintstroke candidateStroke(const Style& style, int tone, StrokeRandom& random) {
  const StrokeStyle& s = style.stroke;
  constexpr double kDegree = std::numbers::pi / 180.0;
  // Every candidate draws the same count of numbers in the same order, whatever its kind.
  const double crossDraw = random.uniform();
  const double jitter = random.uniform(-s.angleJitterDegrees, s.angleJitterDegrees);
  const double cx = random.uniform(), cy = random.uniform();
  const double width = random.uniform(s.width.min, s.width.max);
  const double lengthDraw = random.uniform(s.length.min, s.length.max);
  const double bendDraw = random.uniform(-1.0, 1.0);

  double angle = s.angleDegrees;
  const bool crossing = s.kind == StrokeKind::CrossHatching && s.crossFrom >= 0 && tone >= s.crossFrom;
  if (crossing && crossDraw < 0.5) angle += s.crossAngleDegrees;
  angle = (angle + jitter) * kDegree;
  const double dx = std::cos(angle), dy = std::sin(angle);

  double length = lengthDraw;
  if (s.kind == StrokeKind::Stippling) length = 0;
  const double bend = (s.kind == StrokeKind::Hatching || s.kind == StrokeKind::CrossHatching)
                          ? s.curvature * length * bendDraw
                          : 0.0;

  stroke::ControlPoint point;
  point.radius = 0.5 * width;
  point.opacity = s.opacity;
  point.colour = s.colour;
  stroke::Paintstroke result;
  result.centreOpacity = s.centreOpacity;
  result.edgeOpacity = s.edgeOpacity;
  result.taper = s.kind == StrokeKind::Stippling ? 0.0 : s.taper;
  point.x = cx - 0.5 * length * dx;
  point.y = cy - 0.5 * length * dy;
  result.points.push_back(point);
  if (bend != 0.0) {
    point.x = cx - bend * dy;
    point.y = cy + bend * dx;
    result.points.push_back(point);
  }
  point.x = cx + 0.5 * length * dx;
  point.y = cy + 0.5 * length * dy;
  result.points.push_back(point);
  return result;
}

}  // namespace bake::hatching::detail
