// The ray march of seed 001 ("Ray tracing", Eq. 2-3) as the runtime's shader runs it, on the CPU:
// the ray enters the shape box (or the proxy bands), and each step maps the point to (r, h) = (|xz|,
// y), samples the shape map bilinearly exactly as the GPU filters it (encoded values filtered, then
// decoded), subtracts the safety margin and steps by the distance, over-relaxed (Keinert et al. 2014).
// Against it, an analytic reference: a ray against each revolved segment (a cone frustum: a quadratic)
// and arc (a torus section: roots of the exact distance along the ray, bracketed and bisected).
// The object's axis is its local +y; r is the distance to it.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "bake/core/vec.h"
#include "bake/revolution/profile.h"
#include "bake/revolution/shape_map.h"
#include "bake_formats/revolution.h"

namespace bake::revolution {


struct Ray {
  Vec3d origin, direction;  // direction unit length
};

// Ray parameters inside the shape box (x, z in [-R, R], y in the grid's h range), t >= 0; nullopt
// when the ray misses it.
std::optional<std::array<double, 2>> enterShapeBox(const Ray& ray, const ShapeGrid& grid);

// Stacked bands that bound the solid: in each h range, the largest r of the surface plus the
// margin. The march starts where the ray first enters one.
struct ProxyBand {
  double hMin = 0, hMax = 0, rMax = 0;
};
std::vector<ProxyBand> buildProxyBands(const ShapeField& field, int bandCount, double margin);
// Entry and exit parameters of the ray into the union of bands (nullopt: misses them all).
std::optional<std::array<double, 2>> enterBands(const Ray& ray, const std::vector<ProxyBand>& bands);

struct MarchSettings {
  int maxIterations = 35;
  double safetyMargin = 0;      // object units, from measureSafetyMargin
  double overRelaxation = format::revolution::kDefaultOverRelaxation;  // 1: plain sphere tracing
  double hitEpsilon = 0;        // object units (0: kHitEpsilonTexels texels)
  bool useProxy = true;
};

struct MarchResult {
  bool hit = false;
  double t = 0;       // ray parameter of the hit
  int fetches = 0;    // shape map samples taken
  int iterations = 0;
};

// `encoded` is what the shader samples; `grid` its layout.
MarchResult marchRay(const Ray& ray, const EncodedShapeMap& encoded, const ShapeGrid& grid,
                     const std::vector<ProxyBand>& bands, const MarchSettings& settings);

// Bilinear sample of the encoded map at (r, h), mirrored at r = 0 and clamped elsewhere, decoded
// after filtering as the shader does.
double sampleDistance(const EncodedShapeMap& encoded, const ShapeGrid& grid, double r, double h);

// First intersection of the ray with the revolved vector profile (nullopt: none).
std::optional<double> intersectExact(const Ray& ray, const Profile& profile);

// Error against run time: rays through a view grid from several directions around the object.
struct MarchErrorPoint {
  int iterations = 0;
  double silhouetteMismatch = 0;  // rays whose hit/miss differs / rays that hit in the reference or the march
  double meanHitError = 0;        // object units: |march hit point - reference hit| over agreed hits
  double maxHitError = 0;
  double meanFetches = 0;         // per ray that enters the shape box (a fragment the shader runs)
};
struct MarchErrorSettings {
  int raysPerView = 128 * 128;
  int views = 6;
  std::vector<int> iterationBudgets{10, 15, 20, 25, 35, 50, 64, 96, 128, 192, 256};
  unsigned threads = 0;  // 0: all hardware threads; results do not depend on it
};
std::vector<MarchErrorPoint> measureMarchError(const Profile& profile, const EncodedShapeMap& encoded,
                                               const ShapeGrid& grid, const std::vector<ProxyBand>& bands,
                                               MarchSettings base, const MarchErrorSettings& settings);
// Smallest budget whose silhouette mismatch is <= target (the largest budget when none is).
int iterationsForTarget(const std::vector<MarchErrorPoint>& curve, double targetMismatch);

}  // namespace bake::revolution
