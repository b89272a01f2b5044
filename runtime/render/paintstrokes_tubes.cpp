// The command-line options of the paintstroke renderer, and the fixed-tube reference. (The package is
// read and checked by libbake: paintstrokes/package/package.h, readPaintstrokes.)
//
// Tubes (the reference, and the coarse fixed-tessellation peer): per segment, `steps` + 1 rings of
// `sides` vertices along the same Catmull-Rom path and radius the shaders evaluate (seed 002: "we
// generate Catmull-Rom spline interpolants for the path and radius components"), each ring in a frame
// carried from the previous ring by the rotation that takes the old tangent to the new one (parallel
// transport, so the tube does not twist). The normal of a generalized cylinder tilts against the
// radius' slope: n = normalize(radial - (dr/ds) tangent), s the arc length.
#include <bake_formats/paintstrokes.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "bake/core/vec.h"
#include "render/paintstrokes.h"

namespace bake::play {
namespace {

namespace fmt = format::paintstrokes;
using V3 = Vec3d;
using vec::add;
using vec::cross;
using vec::dot;
using vec::length;
using vec::scale;
using vec::sub;
using vec::unit;

// A Catmull-Rom spline through p0..p3 at u (segment p1 -> p2) and its derivative, on 4 components
// (position and radius), exactly as shaders/paintstrokes/paintstroke.tese evaluates it.
struct SplineSample {
  std::array<double, 4> value, derivative;
};
SplineSample catmullRom(const std::array<std::array<double, 4>, 4>& p, double u) {
  const double u2 = u * u, u3 = u2 * u;
  const double w[4] = {0.5 * (-u3 + 2 * u2 - u), 0.5 * (3 * u3 - 5 * u2 + 2), 0.5 * (-3 * u3 + 4 * u2 + u), 0.5 * (u3 - u2)};
  const double dw[4] = {0.5 * (-3 * u2 + 4 * u - 1), 0.5 * (9 * u2 - 10 * u), 0.5 * (-9 * u2 + 8 * u + 1), 0.5 * (3 * u2 - 2 * u)};
  SplineSample s{};
  for (int k = 0; k < 4; ++k) {
    for (int c = 0; c < 4; ++c) {
      s.value[c] += w[k] * p[k][c];
      s.derivative[c] += dw[k] * p[k][c];
    }
  }
  return s;
}

// Control point `local` of a stroke, reflected through the end point beyond either end.
std::array<double, 4> controlPoint(const paintstrokes::PaintstrokePackage& p, std::size_t stroke, int local) {
  const int count = int(p.strokes[stroke].info[1]);
  auto reflect = [&](int end, int inner) {
    const auto a = p.positionRadius(stroke, std::size_t(end)), b = p.positionRadius(stroke, std::size_t(inner));
    return std::array<double, 4>{2 * a[0] - b[0], 2 * a[1] - b[1], 2 * a[2] - b[2], 2 * a[3] - b[3]};
  };
  if (local < 0) return reflect(0, 1);
  if (local >= count) return reflect(count - 1, count - 2);
  return p.positionRadius(stroke, std::size_t(local));
}

V3 anyOrthogonal(const V3& t) {
  const V3 a = std::fabs(t[0]) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  return unit(cross(t, a), {0, 0, 1});
}

// Carries `normal` (orthogonal to `from`) to be orthogonal to `to` by the smallest rotation.
V3 transport(const V3& normal, const V3& from, const V3& to) {
  const V3 projected = sub(normal, scale(to, dot(normal, to)));
  return length(projected) > 1e-9 ? unit(projected, anyOrthogonal(to)) : unit(cross(to, cross(normal, from)), anyOrthogonal(to));
}

void addStrokeTube(const paintstrokes::PaintstrokePackage& p, std::size_t stroke, int sides, int steps, TubeMesh& mesh) {
  const int count = int(p.strokes[stroke].info[1]);
  V3 previousTangent{0, 0, 0}, normal{0, 0, 0};
  for (int i = 0; i + 1 < count; ++i) {
    const std::array<std::array<double, 4>, 4> control = {controlPoint(p, stroke, i - 1), controlPoint(p, stroke, i),
                                                          controlPoint(p, stroke, i + 1), controlPoint(p, stroke, i + 2)};
    const V3 chord = sub({control[2][0], control[2][1], control[2][2]}, {control[1][0], control[1][1], control[1][2]});
    const std::uint32_t base = std::uint32_t(mesh.vertices.size());
    for (int j = 0; j <= steps; ++j) {
      const double u = double(j) / steps;
      const SplineSample s = catmullRom(control, u);
      const V3 centre{s.value[0], s.value[1], s.value[2]};
      const V3 derivative{s.derivative[0], s.derivative[1], s.derivative[2]};
      const V3 tangent = unit(derivative, unit(chord, {0, 0, 1}));
      normal = length(normal) == 0 ? anyOrthogonal(tangent) : transport(normal, previousTangent, tangent);
      previousTangent = tangent;
      const V3 binormal = cross(tangent, normal);  // (normal, binormal, tangent) is right-handed
      const double radius = std::max(s.value[3], 0.0);
      const double speed = length(derivative);
      const double slope = speed > 1e-300 ? s.derivative[3] / speed : 0.0;  // dr/ds
      for (int k = 0; k < sides; ++k) {
        const double a = 2 * M_PI * k / sides;
        const V3 radial = add(scale(normal, std::cos(a)), scale(binormal, std::sin(a)));
        const V3 position = add(centre, scale(radial, radius));
        const V3 n = unit(sub(radial, scale(tangent, slope)), radial);
        TubeVertex v{};
        for (int c = 0; c < 3; ++c) {
          v.position[c] = float(position[c]);
          v.normal[c] = float(n[c]);
          v.tangent[c] = float(tangent[c]);
        }
        v.t = float(u);
        v.point = p.strokes[stroke].info[0] + std::uint32_t(i);
        v.stroke = std::uint32_t(stroke);
        mesh.vertices.push_back(v);
      }
    }
    // Quads between rings j and j+1, counter-clockwise seen from outside: (around) x (along) points out.
    for (int j = 0; j < steps; ++j) {
      for (int k = 0; k < sides; ++k) {
        const std::uint32_t a = base + std::uint32_t(j * sides + k), b = base + std::uint32_t(j * sides + (k + 1) % sides);
        const std::uint32_t c = b + std::uint32_t(sides), d = a + std::uint32_t(sides);
        mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
      }
    }
  }
}

}  // namespace

std::string PaintstrokeOptions::describe() const {
  char text[96];
  if (tubes()) {
    std::snprintf(text, sizeof text, "tubes %dx%d", tubeSides, tubeSteps);
  } else {
    std::snprintf(text, sizeof text, "quality %d, tolerance %g px", quality, double(tolerance));
  }
  return text;
}

Result<PaintstrokeOptions> makePaintstrokeOptions(int quality, double tolerance, const std::string& tubes) {
  PaintstrokeOptions options;
  if (quality < 0 || quality >= fmt::kQualityLevels)
    return usageError("--stroke-quality " + std::to_string(quality) + " must be 0, 1 or 2");
  if (!std::isfinite(tolerance) || tolerance < 0.01 || tolerance > 1000)
    return usageError("--stroke-tolerance " + std::to_string(tolerance) + " must be a number of pixels in [0.01, 1000]");
  options.quality = quality;
  options.tolerance = float(tolerance);
  if (tubes.empty()) return options;
  int sides = 0, steps = 0;
  char x = 0, extra = 0;
  const int fields = std::sscanf(tubes.c_str(), "%d%c%d%c", &sides, &x, &steps, &extra);
  const bool sidesOnly = fields == 1 && tubes.find_first_not_of("0123456789") == std::string::npos;
  if (sidesOnly) steps = std::max(1, sides / 2);
  if (!(sidesOnly || (fields == 3 && (x == 'x' || x == 'X') &&
                      tubes.find_first_not_of("0123456789xX") == std::string::npos)) ||
      sides < 3 || sides > 1024 || steps < 1 || steps > 1024) {
    return usageError("--stroke-tubes \"" + tubes + "\" must be SIDES or SIDESxSTEPS, SIDES 3 to 1024, STEPS 1 to 1024");
  }
  options.tubeSides = sides;
  options.tubeSteps = steps;
  return options;
}

TubeMesh buildStrokeTubes(const paintstrokes::PaintstrokePackage& package, int sides, int steps) {
  TubeMesh mesh;
  for (std::size_t s = 0; s < package.strokes.size(); ++s) addStrokeTube(package, s, sides, steps, mesh);
  return mesh;
}

}  // namespace bake::play
