// The ray-traced reference renderer (formats/groove-scene.md, "Rendering model"), the oracle of the
// seed's method: it shares only the scene and the material model (render.h) with it.
//
// Radiance along a view line: the line through base-plane point x towards the viewer starts where it
// is above the highest ridge and is cast down to its first hit on the exact surface
// (reference_surface.cpp). A hit facing the light is lit when a shadow ray towards L, started a little
// off the surface along its normal, leaves the surface; it then sends the normalised Blinn-Phong
// radiance. Mirror materials add mirror x the radiance along the reflected ray, up to maxBounces
// reflections; a reflected ray that leaves the surface sees the environment (black by default).
//
// Pixels: n x n stratified samples over the footprint parallelogram (n = sqrt(samplesPerPixel),
// rounded to the nearest integer >= 1 when samplesPerPixel is not a square), jittered inside each
// stratum by a counter-based hash of (seed, pixel, sample), so an image never depends on the thread
// count; the pixel value is their mean.
#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "grooves/reference/reference.h"

namespace bake::grooves {
namespace {

double dot3(const Vec3& a, const Vec3& b) { return a.u * b.u + a.v * b.v + a.w * b.w; }
Vec3 along(const Vec3& p, const Vec3& d, double t) { return {p.u + t * d.u, p.v + t * d.v, p.w + t * d.w}; }

// How far rays start off the surface: far above rounding, far below any groove (profiles are few,
// grooves may be many: this runs per sample in referenceRadiance).
double offsetDistance(const GrooveScene& scene) {
  double size = std::max(scene.domain[0], scene.domain[1]);
  for (const Profile& p : scene.profiles) size = std::min(size, p.wmax);
  return std::max(1e-7 * size, 1e-12 * std::max(scene.domain[0], scene.domain[1]));
}

bool lit(const ReferenceSurface& surface, const ReferenceSurface::Hit& hit, const Lighting& lighting, double offset) {
  if (dot3(hit.normal, lighting.toLight) <= 0) return false;  // unlit anyway: no shadow ray needed
  ReferenceSurface::Hit blocker;
  return !surface.intersect(along(hit.point, hit.normal, offset), lighting.toLight, blocker);
}

// Radiance arriving along the ray origin + t dir (dir unit), following mirror reflections.
Rgb traceRadiance(const ReferenceSurface& surface, const GrooveScene& scene, const Vec3& origin, const Vec3& dir,
                  const Lighting& lighting, int bounce, double offset) {
  ReferenceSurface::Hit hit;
  if (!surface.intersect(origin, dir, hit)) return bounce > 0 ? lighting.environment : Rgb{0, 0, 0};
  const Material& material = scene.materials[hit.material];
  const Vec3 toViewer{-dir.u, -dir.v, -dir.w};
  Rgb out{0, 0, 0};
  if (lit(surface, hit, lighting, offset)) out = directRadiance(material, hit.normal, toViewer, lighting);
  if (material.hasMirror && bounce < lighting.maxBounces) {
    const Vec3 reflected = reflect(toViewer, hit.normal);
    const Rgb seen = traceRadiance(surface, scene, along(hit.point, hit.normal, offset), reflected, lighting,
                                   bounce + 1, offset);
    for (int c = 0; c < 3; ++c) out[c] += material.mirror[c] * seen[c];
  }
  return out;
}

Rgb radianceAt(const ReferenceSurface& surface, const GrooveScene& scene, Vec2 x, const Vec3& toViewer,
               const Lighting& lighting, double offset) {
  const double n = std::sqrt(dot3(toViewer, toViewer));
  const Vec3 e{toViewer.u / n, toViewer.v / n, toViewer.w / n};
  if (!(e.w > 0)) return {0, 0, 0};
  // Start on the view line where it is above every ridge.
  const double t = (std::max(scene.hmax, 0.0) + 1e-6 * std::max(scene.domain[0], scene.domain[1])) / e.w;
  const Vec3 origin{x.u + t * e.u, x.v + t * e.v, t * e.w};
  return traceRadiance(surface, scene, origin, {-e.u, -e.v, -e.w}, lighting, 0, offset);
}

// SplitMix64's finaliser: a well-mixed 64-bit hash of a counter.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double uniform01(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

int strataPerSide(int samplesPerPixel) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, samplesPerPixel)))));
}

}  // namespace

Rgb referenceRadiance(const ReferenceSurface& surface, const GrooveScene& scene, Vec2 x, const Vec3& toViewer,
                      const Lighting& lighting) {
  return radianceAt(surface, scene, x, toViewer, lighting, offsetDistance(scene));
}

Image renderReference(const GrooveScene& scene, const View& view, const Lighting& lighting,
                         const ReferenceSettings& settings) {
  Image image = rgbImage(view.width, view.height);
  const ReferenceSurface surface(scene);
  const double offset = offsetDistance(scene);
  const int n = strataPerSide(settings.samplesPerPixel);
  const std::size_t pixels = std::size_t(image.width) * image.height;
  parallelFor(pixels, resolveThreadCount(unsigned(std::max(0, settings.threads))), [&](std::size_t index) {
    const int x = static_cast<int>(index % image.width), y = static_cast<int>(index / image.width);
    const Footprint f = view.pixel(x, y);
    const std::uint64_t pixelKey = mix(settings.seed ^ mix(index));
    Rgb sum{0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const std::uint64_t bits = mix(pixelKey + std::uint64_t(i * n + j));
        const double a = (i + uniform01(bits)) / n - 0.5, b = (j + uniform01(mix(bits))) / n - 0.5;
        const Vec2 point{f.centre.u + a * f.axis1.u + b * f.axis2.u, f.centre.v + a * f.axis1.v + b * f.axis2.v};
        const Rgb value = radianceAt(surface, scene, point, view.toViewer, lighting, offset);
        for (int c = 0; c < 3; ++c) sum[c] += value[c];
      }
    const double weight = 1.0 / (double(n) * n);
    setRgb(image, x, y, {sum[0] * weight, sum[1] * weight, sum[2] * weight});
  }, 4);
  return image;
}

}  // namespace bake::grooves
