// The paintstroke's centreline (seed 002, Neulander & van de Panne 1998, "Rendering generalized
// cylinders with paintstrokes", section 3: "Catmull-Rom spline interpolants for the path and radius
// components, and linear interpolants for the others"). The spline is the uniform Catmull-Rom spline
// through the control points with the first and last points doubled, so it passes through every
// control point and starts and ends at the end points. The rasterizer works on a polyline: each spline
// segment is cut into equal parameter steps, enough of them that no piece is longer than the asked
// length (the segment's length is estimated from a finer polyline), and the arc length is accumulated
// along it. The ends taper by arc length: the radius is multiplied by a smoothstep that goes from 0 at
// each end to 1 at `taper` x length from it, so a tapered end keeps on average half its ink.
#include <algorithm>
#include <cmath>

#include "bake/stroke/paintstroke.h"
#include "stroke/stroke_stages.h"

namespace bake::stroke {
namespace {

// Uniform Catmull-Rom between p1 (u = 0) and p2 (u = 1).
double catmullRom(double p0, double p1, double p2, double p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u2 + (3 * p1 - p0 - 3 * p2 + p3) * u3);
}

ControlPoint evaluateSegment(const std::vector<ControlPoint>& p, std::size_t i, double u) {
  const std::size_t n = p.size();
  const ControlPoint& a = p[i == 0 ? 0 : i - 1];
  const ControlPoint& b = p[i];
  const ControlPoint& c = p[i + 1];
  const ControlPoint& d = p[std::min(i + 2, n - 1)];
  ControlPoint out;
  out.x = catmullRom(a.x, b.x, c.x, d.x, u);
  out.y = catmullRom(a.y, b.y, c.y, d.y, u);
  out.radius = std::max(0.0, catmullRom(a.radius, b.radius, c.radius, d.radius, u));
  for (int k = 0; k < 3; ++k) out.colour[k] = b.colour[k] + (c.colour[k] - b.colour[k]) * u;
  out.opacity = b.opacity + (c.opacity - b.opacity) * u;
  return out;
}

// Colour and opacity at fraction f of the way from a to b.
void lerpInk(const ControlPoint& a, const ControlPoint& b, double f, ControlPoint& out) {
  for (int k = 0; k < 3; ++k) out.colour[k] = a.colour[k] + (b.colour[k] - a.colour[k]) * f;
  out.opacity = a.opacity + (b.opacity - a.opacity) * f;
}

bool finitePoint(const ControlPoint& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.radius) && std::isfinite(p.opacity) &&
         std::isfinite(p.colour[0]) && std::isfinite(p.colour[1]) && std::isfinite(p.colour[2]);
}

}  // namespace

ControlPoint evaluate(const Paintstroke& stroke, double t) {
  const auto& p = stroke.points;
  if (p.empty()) return {};
  if (p.size() == 1 || !(t > 0)) return p.front();  // also catches NaN
  const double last = double(p.size() - 1);
  if (t >= last) return p.back();
  const std::size_t i = std::min(std::size_t(t), p.size() - 2);
  ControlPoint out = evaluateSegment(p, i, t - double(i));
  // Colour and opacity are linear in arc length within the segment.
  constexpr int kSteps = 64;
  double total = 0, before = 0;
  ControlPoint prev = p[i];
  for (int k = 1; k <= kSteps; ++k) {
    const double u = double(k) / kSteps;
    const ControlPoint q = evaluateSegment(p, i, u);
    const double step = std::hypot(q.x - prev.x, q.y - prev.y);
    total += step;
    if (u <= t - double(i)) before += step;
    else if (u - 1.0 / kSteps < t - double(i)) before += step * (t - double(i) - (u - 1.0 / kSteps)) * kSteps;
    prev = q;
  }
  lerpInk(p[i], p[i + 1], total > 0 ? before / total : t - double(i), out);
  return out;
}

namespace detail {

double taperFactor(double arc, double length, double taper) {
  taper = std::clamp(taper, 0.0, 0.5);
  if (!(taper > 0) || !(length > 0)) return 1;
  const double x = std::clamp(std::min(arc, length - arc) / (taper * length), 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

std::vector<Sample> sampleCentreline(const Paintstroke& stroke, double maxPieceLength, double maxDeviation,
                                     std::size_t maxSamples) {
  const auto& p = stroke.points;
  std::vector<Sample> samples;
  if (p.size() < 2 || !std::all_of(p.begin(), p.end(), finitePoint)) return samples;
  if (!(maxPieceLength > 0) || !std::isfinite(maxPieceLength)) maxPieceLength = RasterOptions{}.maxPieceLength;
  if (!(maxDeviation > 0) || !std::isfinite(maxDeviation)) maxDeviation = RasterOptions{}.maxDeviation;
  maxDeviation = std::max(maxDeviation, 1e-4);

  auto toSample = [](const ControlPoint& c) {
    Sample s;
    s.x = c.x, s.y = c.y, s.radius = c.radius, s.opacity = c.opacity, s.colour = c.colour;
    return s;
  };
  samples.push_back(toSample(p.front()));
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    // The segment's length and total turn, from a polyline fine enough for the piece count. A piece of
    // length l turning by a strays about l a / 8 from its chord; n equal pieces of a segment of length
    // L turning by A stray L A / (8 n^2).
    constexpr int kProbe = 8;
    double length = 0, turn = 0, px = 0, py = 0;
    ControlPoint prev = p[i];
    for (int k = 1; k <= kProbe; ++k) {
      const ControlPoint q = evaluateSegment(p, i, double(k) / kProbe);
      const double dx = q.x - prev.x, dy = q.y - prev.y, step = std::hypot(dx, dy);
      if (step > 0) {
        if (px != 0 || py != 0) turn += std::acos(std::clamp((px * dx + py * dy) / step, -1.0, 1.0));
        px = dx / step, py = dy / step;
      }
      length += step;
      prev = q;
    }
    if (!std::isfinite(length)) return {};
    const double pieces = std::max({1.0, std::ceil(length / maxPieceLength),
                                    std::ceil(std::sqrt(length * turn / (8 * maxDeviation)))});
    if (pieces > double(maxSamples) || samples.size() + std::size_t(pieces) > maxSamples) return {};
    const int count = int(pieces);
    const std::size_t start = samples.size() - 1;
    for (int k = 1; k <= count; ++k) {
      Sample s = toSample(k == count ? p[i + 1] : evaluateSegment(p, i, double(k) / count));
      const Sample& before = samples.back();
      const double dx = s.x - before.x, dy = s.y - before.y;
      const double step = std::sqrt(dx * dx + dy * dy);
      s.arc = before.arc + (std::isfinite(step) ? step : std::hypot(dx, dy));
      samples.push_back(s);
    }
    // Colour and opacity: linear in arc length between the two control points.
    const double a0 = samples[start].arc, span = samples.back().arc - a0;
    for (std::size_t k = start + 1; k < samples.size(); ++k) {
      ControlPoint c;
      lerpInk(p[i], p[i + 1], span > 0 ? (samples[k].arc - a0) / span : double(k - start) / count, c);
      samples[k].opacity = c.opacity;
      samples[k].colour = c.colour;
    }
  }
  const double length = samples.back().arc;
  if (!std::isfinite(length)) return {};
  for (Sample& s : samples) {
    s.radius = std::max(0.0, s.radius) * taperFactor(s.arc, length, stroke.taper);
    s.opacity = std::clamp(s.opacity, 0.0, 1.0);
    for (double& c : s.colour) c = std::clamp(c, 0.0, 1.0);
  }
  return samples;
}

}  // namespace detail
}  // namespace bake::stroke
