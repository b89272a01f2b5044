// Validation and repair of a stroke set (paintstrokes/input/validate.h).
//
// Refused (invalid input, naming stroke and control point): a stroke with fewer than 2 control points
// (no path to interpolate), a radius that is not > 0, any value that is NaN or infinite, positions or
// radii beyond 1e30 (the package's fp32 boxes), colour, opacity, reflectance or depth outside [0, 1], a
// style index that does not exist. Repaired, deterministically: a control point at the same place as
// the one before it (closer than 1e-9 x the stroke's extent, or exactly equal) is dropped, the later
// one, with a warning; a Catmull-Rom segment of zero length has no tangent, so the runtime's
// view-dependent tessellation (seed 002) could not orient it. If fewer than 2 points remain, the stroke
// is refused. A global normal that is not unit is normalised; a zero normal stays zero and means "no
// self-shadowing" for that point (shadow.cpp).
#include "paintstrokes/input/validate.h"
#include "bake/core/vector_text.h"

#include <cmath>
#include <sstream>

#include "paintstrokes/input/input.h"

namespace bake::paintstrokes {
namespace {

// Warnings per kind printed one by one; the rest are summed up in one line.
constexpr std::size_t kWarningsShown = 10;

bool finite3(const Vec3d& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

Status checkPoint(const StrokePoint& p, const std::string& file, std::size_t s, std::size_t i) {
  auto fail = [&](const std::string& message) { return invalidInput(message, {file, pointElement(s, i)}); };
  if (!finite3(p.position))
    return fail("position is (" + numberText(p.position[0]) + ", " + numberText(p.position[1]) + ", " + numberText(p.position[2]) + ") (must be finite)");
  for (double x : p.position)
    if (std::abs(x) > kLargestValue) return fail("position coordinate " + numberText(x) + " is beyond +-1e30");
  if (!std::isfinite(p.radius) || !(p.radius > 0)) return fail("radius is " + numberText(p.radius) + " (must be > 0)");
  if (p.radius > kLargestValue) return fail("radius is " + numberText(p.radius) + " (beyond 1e30)");
  for (int k = 0; k < 3; ++k)
    if (!(p.colour[k] >= 0 && p.colour[k] <= 1))
      return fail("colour is (" + numberText(p.colour[0]) + ", " + numberText(p.colour[1]) + ", " + numberText(p.colour[2]) + ") (must be within [0, 1])");
  if (!(p.opacity >= 0 && p.opacity <= 1)) return fail("opacity is " + numberText(p.opacity) + " (must be within [0, 1])");
  if (!(p.reflectance >= 0 && p.reflectance <= 1)) return fail("reflectance is " + numberText(p.reflectance) + " (must be within [0, 1])");
  if (!finite3(p.globalNormal)) return fail("normal is not finite");
  if (!(p.depth >= 0 && p.depth <= 1)) return fail("depth is " + numberText(p.depth) + " (must be within [0, 1])");
  return {};
}

double extentOf(const Stroke& stroke) {
  Vec3d lo = stroke.points.front().position, hi = lo;
  for (const StrokePoint& p : stroke.points)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p.position[k]);
      hi[k] = std::max(hi[k], p.position[k]);
    }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// Drops each point coincident with the last point kept; returns the dropped indices (input numbering).
std::vector<std::size_t> dropCoincident(Stroke& stroke) {
  const double tolerance = kCoincidentRelative * extentOf(stroke);
  std::vector<StrokePoint> kept{stroke.points.front()};
  std::vector<std::size_t> dropped;
  for (std::size_t i = 1; i < stroke.points.size(); ++i) {
    const Vec3d &a = kept.back().position, &b = stroke.points[i].position;
    const double d = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    if (a == b || d < tolerance) dropped.push_back(i);
    else kept.push_back(stroke.points[i]);
  }
  stroke.points = std::move(kept);
  return dropped;
}

}  // namespace

Result<ValidationCounts> validateStrokes(StrokeSet& set, const std::string& file, Diagnostics& diagnostics) {
  std::uint64_t total = 0;
  for (const Stroke& s : set.strokes) total += s.points.size();
  BAKE_RETURN_IF_ERROR(checkBudget(Budget::ControlPoints, total, "control points", {file, "strokes"}));
  if (set.strokes.empty()) return invalidInput("no strokes", {file, "strokes"});
  if (set.styles.empty()) set.styles.emplace_back();
  ValidationCounts counts;
  for (std::size_t s = 0; s < set.strokes.size(); ++s) {
    Stroke& stroke = set.strokes[s];
    if (stroke.points.size() < 2)
      return invalidInput(std::to_string(stroke.points.size()) + " control point" + (stroke.points.size() == 1 ? "" : "s") +
                              " (a stroke needs at least 2)",
                          {file, strokeElement(s)});
    if (stroke.style >= set.styles.size())
      return invalidInput("style " + std::to_string(stroke.style) + " does not exist (" + std::to_string(set.styles.size()) + " styles)",
                          {file, strokeElement(s)});
    for (std::size_t i = 0; i < stroke.points.size(); ++i) BAKE_RETURN_IF_ERROR(checkPoint(stroke.points[i], file, s, i));
    for (std::size_t i : dropCoincident(stroke)) {
      if (++counts.droppedPoints <= kWarningsShown)
        diagnostics.warning("coincident-control-points", file + ": " + pointElement(s, i) +
                                                              ": at the same place as the point before it: dropped");
    }
    if (stroke.points.size() < 2)
      return invalidInput("every control point is at the same place (fewer than 2 remain after dropping coincident ones)",
                          {file, strokeElement(s)});
    for (StrokePoint& p : stroke.points) {
      Vec3d& n = p.globalNormal;
      const double length = std::hypot(n[0], n[1], n[2]);
      if (length == 0 || std::abs(length - 1) <= 1e-9) continue;
      for (double& c : n) c /= length;
      ++counts.normalisedNormals;
    }
  }
  if (counts.droppedPoints > kWarningsShown)
    diagnostics.warning("coincident-control-points", file + ": " + std::to_string(counts.droppedPoints - kWarningsShown) +
                                                          " more coincident control points dropped");
  if (counts.normalisedNormals)
    diagnostics.warning("normalised-normals", file + ": " + std::to_string(counts.normalisedNormals) +
                                                   " global normals were not unit vectors: normalised");
  return counts;
}

std::vector<std::string> unusedStyles(const StrokeSet& set) {
  std::vector<bool> used(set.styles.size(), false);
  for (const Stroke& stroke : set.strokes)
    if (stroke.style < used.size()) used[stroke.style] = true;
  std::vector<std::string> names;
  for (std::size_t s = 0; s < set.styles.size(); ++s)
    if (!used[s]) names.push_back(set.styles[s].name);
  return names;
}

std::vector<std::string> dropUnusedStyles(StrokeSet& set) {
  std::vector<std::size_t> renumbered(set.styles.size(), set.styles.size());
  for (const Stroke& stroke : set.strokes)
    if (stroke.style < renumbered.size()) renumbered[stroke.style] = 0;
  if (set.strokes.empty() && !set.styles.empty()) renumbered[0] = 0;
  std::vector<StrokeStyle> kept;
  std::vector<std::string> dropped;
  for (std::size_t s = 0; s < set.styles.size(); ++s) {
    if (renumbered[s] == set.styles.size()) {
      dropped.push_back(set.styles[s].name);
      continue;
    }
    renumbered[s] = kept.size();
    kept.push_back(std::move(set.styles[s]));
  }
  set.styles = std::move(kept);
  for (Stroke& stroke : set.strokes) stroke.style = renumbered[stroke.style];
  return dropped;
}

}  // namespace bake::paintstrokes
