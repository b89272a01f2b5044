// The rendering model shared by the seed's method (shade.h), the ray-traced reference (reference.h)
// and the runtime shader: orthographic view, parallelogram pixel footprints on the base plane, one
// directional light, normalised Blinn-Phong plus perfect mirrors (formats/groove-scene.md, "Rendering
// model").
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bake/core/status.h"
#include "bake/io/image.h"
#include "grooves/input/scene.h"

namespace bake::grooves {

// Groove space: u, v on the base plane, w up (seed §3: T, B, W frame at a path point).
struct Vec3 {
  double u = 0, v = 0, w = 0;
};
using Rgb = std::array<double, 3>;

// A pixel's footprint on the base plane: the parallelogram centre ± axis1 / 2 ± axis2 / 2.
struct Footprint {
  Vec2 centre;
  Vec2 axis1, axis2;
};

struct Lighting {
  Vec3 toLight{0, 0, 1};      // unit
  Rgb radiance{1, 1, 1};      // irradiance on a surface facing the light
  int maxBounces = 0;         // mirror reflections followed (seed §7)
  // Radiance of the rest of the scene, constant in every direction: what a reflected ray that leaves
  // the grooved surface sees (seed §7, weighted by the uncovered part of the new footprint, 1 - Σ r_i).
  Rgb environment{0, 0, 0};
};

// An orthographic view of a rectangle of the base plane: pixel (x, y) has its footprint centre at
// origin + (x + 0.5) axisX + (y + 0.5) axisY and edges axisX, axisY.
struct View {
  Vec3 toViewer{0, 0, 1};  // unit, w > 0
  Vec2 origin;
  Vec2 axisX, axisY;
  int width = 0, height = 0;
  Footprint pixel(int x, int y) const;
};

// A view of the window [u0, u1] x [v0, v1] seen from polar angle theta (radians from the normal) and
// azimuth phi, `width` pixels across; the pixels are the window's rows (square in uv, so elongated
// on screen at grazing angles, like a texture seen at an angle).
View windowView(Vec2 lower, Vec2 upper, int width, double theta, double phi);
Vec3 directionFromAngles(double theta, double phi);

// Rendered images are io/image.h Images of three linear channels, row-major, y down (writeImage
// writes them as EXR, or as 8-bit PNG: round(255 clamp(x))).
Image rgbImage(int width, int height);  // black
Rgb rgbAt(const Image& image, int x, int y);
void setRgb(Image& image, int x, int y, const Rgb& value);

// Radiance sent towards E by a lit point with normal N: f(E, L) max(N.L, 0) radiance, f normalised
// Blinn-Phong (the one material model; also in shaders/grooves).
Rgb directRadiance(const Material& material, const Vec3& normal, const Vec3& toViewer, const Lighting& lighting);
// What a mirror facet adds by reflecting the environment where its reflection leaves the surface
// untraced (the flat base beyond a section): mirror x environment, when bounces are followed.
Rgb environmentReflection(const Material& material, const Lighting& lighting);
// The flat base plane seen from toViewer: its direct light and, if it mirrors, the environment.
Rgb flatBaseRadiance(const Material& base, const Vec3& toViewer, const Lighting& lighting);
Vec3 reflect(const Vec3& toViewer, const Vec3& normal);  // mirrored direction, unit

// directRadiance under one view and light, remembering (material, normal) pairs: the facets of a
// section and the pieces of a footprint's surface repeat a handful of normals (the flat ground between
// grooves above all), from pixel to pixel too, and the lobe's pow is most of a radiance's cost. The
// memo is per thread and outlives the object: a new one under the same view, light and materials
// (compared by value, so a changed scene cannot hit a stale entry) keeps what the last one learnt.
// Same values as directRadiance, bit for bit.
class RadianceMemo {
 public:
  RadianceMemo(const std::vector<Material>& materials, const Vec3& toViewer, const Lighting& lighting);
  Rgb operator()(std::size_t material, const Vec3& normal);

  struct Entry {
    std::size_t material = 0;
    Vec3 normal;
    Rgb radiance{0, 0, 0};
  };
  static constexpr int kEntries = 16;
  // What the entries were computed under: the view, the light and every material's reflectance.
  struct Store {
    Vec3 toViewer, toLight;
    Rgb lightRadiance{0, 0, 0};
    std::vector<double> reflectance;
    std::array<Entry, kEntries> entries;
    int count = 0, next = 0;
    std::uint64_t generation = 0;  // counts the times it was emptied
  };

 private:
  const std::vector<Material>& materials_;
  Vec3 toViewer_;
  Lighting lighting_;
  Store& store_;
  std::uint64_t generation_;  // the store's when this memo last made it its own
};

// Image error figures against a reference image (same size): RMSE over channels, relative MSE
// (MSE / mean square of the reference), 99th percentile of the per-pixel max-channel error, max.
struct ImageError {
  double rmse = 0, relativeMse = 0, p99 = 0, max = 0;
};
ImageError imageError(const Image& image, const Image& reference);

}  // namespace bake::grooves
