// The shader's ray march on the CPU, step for step (formats/revolution.md, "Sampling and marching";
// seed 001 "Ray tracing", Eq. 2-3): the ray starts where it enters the proxy bands (or the shape box),
// each iteration maps the point to (r, h) = (|xz|, y), takes one bilinear fetch of the shape map,
// subtracts the safety margin, and either reports a hit (distance below the hit epsilon) or steps on.
// Steps are over-relaxed sphere tracing (Keinert et al. 2014, "Enhanced sphere tracing", section 3.1):
// t advances by omega * d; when the sphere at the new point does not overlap the previous one
// (|d| + dPrevious < step) the step may have jumped over the surface, so the march falls back to the
// previous point, steps plainly by dPrevious from there, and keeps omega = 1 for the rest of the ray.
// A negative sample after an over-relaxed step counts as such a failure too, even when the spheres
// overlap: the step went past the surface, and the hit test (d < epsilon) would accept a point inside
// the solid (measured: up to 2 texels deep on a sphere). Plain steps never overshoot, since the margin
// makes every sample a lower bound of the true distance. The failure test comes before the hit test,
// and every sample (the undone one too) is an iteration. An over-relaxed step that leaves the march
// interval is undone the same way (without a sample): the exit, unlike a far plane, hugs the solid,
// and a relaxed step can jump over a thin part of it (a ring's tube) into the open.
// The march covers the shape box, narrowed to the hull of the proxy bands (first entry to last exit),
// as shaders/revolution/shape_march.glsl does.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bake_formats/revolution.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {

// Ray parameters inside the shape box: x, z in [-R, R], y in the grid's h range.
std::optional<std::array<double, 2>> enterShapeBox(const Ray& ray, const ShapeGrid& grid) {
  const double radius = grid.width * grid.texelSize;
  if (!(radius > 0) || grid.height <= 0) return std::nullopt;
  const double lo[3] = {-radius, grid.hMin, -radius};
  const double hi[3] = {radius, grid.hMin + grid.height * grid.texelSize, radius};
  double tIn = 0, tOut = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0) {
      if (o < lo[axis] || o > hi[axis]) return std::nullopt;
      continue;
    }
    double t0 = (lo[axis] - o) / d, t1 = (hi[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    tIn = std::max(tIn, t0);
    tOut = std::min(tOut, t1);
  }
  if (!(tIn <= tOut)) return std::nullopt;
  return std::array<double, 2>{tIn, tOut};
}

namespace {


double hitEpsilonOf(const MarchSettings& settings, const ShapeGrid& grid) {
  return settings.hitEpsilon > 0 ? settings.hitEpsilon : format::revolution::kHitEpsilonTexels * grid.texelSize;
}

}  // namespace

MarchResult marchRay(const Ray& ray, const EncodedShapeMap& encoded, const ShapeGrid& grid,
                     const std::vector<ProxyBand>& bands, const MarchSettings& settings) {
  MarchResult result;
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(ray.origin[c]) || !std::isfinite(ray.direction[c])) return result;
  auto span = enterShapeBox(ray, grid);
  if (span && settings.useProxy) {
    const auto hull = enterBands(ray, bands);
    if (hull) span = std::array<double, 2>{std::max((*span)[0], (*hull)[0]), std::min((*span)[1], (*hull)[1])};
    else span.reset();
  }
  if (!span || (*span)[0] > (*span)[1]) return result;
  const double epsilon = hitEpsilonOf(settings, grid);
  double omega = std::max(settings.overRelaxation, 1.0);
  double t = (*span)[0];
  const double tExit = (*span)[1];
  double tPrevious = t, dPrevious = 0, step = 0;
  for (int iteration = 0; iteration < settings.maxIterations; ++iteration) {
    if (t > tExit) {
      // An over-relaxed step past the exit may have jumped over the solid (the exit hugs it, unlike
      // a far plane): take the plain step from the previous point instead. Past the exit: miss.
      if (!(omega > 1 && step > dPrevious)) break;
      omega = 1;
      step = dPrevious;
      t = tPrevious + step;
      if (t > tExit) break;
    }
    const double x = ray.origin[0] + t * ray.direction[0];
    const double y = ray.origin[1] + t * ray.direction[1];
    const double z = ray.origin[2] + t * ray.direction[2];
    const double d = sampleDistance(encoded, grid, std::hypot(x, z), y) - settings.safetyMargin;
    ++result.fetches;
    result.iterations = iteration + 1;
    const bool overRelaxed = omega > 1 && step > 0;
    if (overRelaxed && (d < 0 || std::abs(d) + dPrevious < step)) {
      // Back to the previous point, whose sphere (radius dPrevious) is known empty.
      omega = 1;
      step = dPrevious;
      t = tPrevious + step;
      continue;
    }
    if (d < epsilon) {
      result.hit = true;
      result.t = t;
      return result;
    }
    tPrevious = t;
    dPrevious = d;
    step = omega * d;
    t += step;
  }
  return result;
}

}  // namespace bake::revolution
