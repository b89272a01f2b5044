// Procedural example images. Periodicity comes from construction: sines with whole cycles per tile,
// and cellular dimples whose feature points are looked up with wrapped cell indices, so the left and
// right (top and bottom) edges continue each other.
#include "bake/mesh/patterns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace bake {
namespace {

constexpr double kTau = 2 * std::numbers::pi;

// A small integer hash to [0, 1): the same cell always gets the same value.
double hash01(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return double(h & 0xffffffu) / double(0x1000000);
}

double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

void mixInto(float* rgb, const double* a, const double* b, double t) {
  for (int c = 0; c < 3; ++c) rgb[c] = float(a[c] + (b[c] - a[c]) * t);
}

// Distance to the nearest feature point of a periodic cellular pattern with `cells` cells per tile.
double cellularDistance(double u, double v, int cells, std::uint32_t seed) {
  const double x = u * cells, y = v * cells;
  const int cx = int(std::floor(x)), cy = int(std::floor(y));
  double best = 1e9;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int ix = cx + dx, iy = cy + dy;
      const auto wx = std::uint32_t((ix % cells + cells) % cells), wy = std::uint32_t((iy % cells + cells) % cells);
      const double px = ix + 0.15 + 0.7 * hash01(wx, wy, seed), py = iy + 0.15 + 0.7 * hash01(wx, wy, seed + 1);
      best = std::min(best, std::hypot(x - px, y - py));
    }
  return best;
}

void glaze(double u, double v, float* rgb) {
  static const double body[3] = {0.86, 0.80, 0.68}, glazeColour[3] = {0.10, 0.28, 0.45};
  // The glaze runs down from the top (v = 1) in drips of whole cycles around.
  const double drip = 0.55 + 0.08 * std::sin(kTau * 7 * u) + 0.05 * std::sin(kTau * 13 * u + 1.3) +
                      0.03 * std::sin(kTau * 29 * u + 0.4);
  mixInto(rgb, body, glazeColour, smoothstep(drip - 0.02, drip + 0.02, v));
  const double speckle = cellularDistance(u, v, 48, 7);
  if (speckle < 0.08) {
    for (int c = 0; c < 3; ++c) rgb[c] *= 0.55f;
  }
}

void bands(double u, double v, float* rgb) {
  static const double clay[3] = {0.72, 0.36, 0.18}, black[3] = {0.05, 0.04, 0.03};
  const double wave = 0.012 * std::sin(kTau * 24 * u);
  const double stripe = std::abs(std::sin(kTau * 6 * (v + wave)));
  mixInto(rgb, black, clay, smoothstep(0.15, 0.25, stripe));
}

double hammered(double u, double v) {
  const double d = cellularDistance(u, v, 12, 3);
  return std::clamp(d * d * 2.5, 0.0, 1.0);  // round dimples, flat ridges between them
}

double knurl(double u, double v) {
  const double a = std::abs(std::sin(kTau * 16 * (u + v) / 2)), b = std::abs(std::sin(kTau * 16 * (u - v) / 2));
  return std::min(a, b);
}

// An outdoor sky for environment lighting, in linear radiance (values above 1: the sun), for the
// equirectangular layout bakeplay reads: the direction of row theta (from +Y) and column phi (from -Z
// toward +X) is (sin theta sin phi, cos theta, -sin theta cos phi).
void sky(double theta, double phi, float* rgb) {
  const double d[3] = {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
  static const double zenith[3] = {0.12, 0.28, 0.75}, horizon[3] = {0.85, 0.88, 0.92}, ground[3] = {0.22, 0.2, 0.17};
  if (d[1] >= 0) {
    mixInto(rgb, horizon, zenith, std::pow(d[1], 0.45));
  } else {
    mixInto(rgb, horizon, ground, smoothstep(0.0, 0.08, -d[1]));
  }
  // The sun, up and to the left of -Z, with a soft glow around its disc.
  const double sun[3] = {-0.45, 0.55, -0.7};
  const double length = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
  const double cosine = (d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2]) / length;
  const double glow = 0.6 * std::pow(std::max(cosine, 0.0), 64) + (cosine > 0.9995 ? 30.0 : 0.0);
  for (int c = 0; c < 3; ++c) rgb[c] += float(glow * (c == 2 ? 0.85 : 1.0));
}

}  // namespace

std::vector<std::string> patternNames() { return {"glaze", "bands", "hammered", "knurl", "sky"}; }

Result<Image> makePattern(const std::string& name, int size) {
  const auto names = patternNames();
  if (std::find(names.begin(), names.end(), name) == names.end())
    return usageError("unknown pattern '" + name + "'");
  if (size < 8 || size > 8192) return usageError("--resolution for a pattern must be within 8 .. 8192 pixels");
  const bool colour = name == "glaze" || name == "bands" || name == "sky";
  Image image;
  image.width = image.height = size;
  if (name == "sky") image.height = std::max(1, size / 2);  // equirectangular: 360 by 180 degrees
  image.channels = colour ? 3 : 1;
  image.pixels.resize(std::size_t(image.width) * std::size_t(image.height) * image.channels);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < size; ++x) {
      // Pixel centres; v grows upwards (the image's top row is v near 1).
      const double u = (x + 0.5) / size, v = 1 - (y + 0.5) / image.height;
      float* pixel = &image.pixels[(std::size_t(y) * size + x) * image.channels];
      if (name == "sky") sky((y + 0.5) / image.height * std::numbers::pi, (u - 0.5) * kTau, pixel);
      else if (name == "glaze") glaze(u, v, pixel);
      else if (name == "bands") bands(u, v, pixel);
      else if (name == "hammered") pixel[0] = float(hammered(u, v));
      else pixel[0] = float(knurl(u, v));
    }
  }
  return image;
}

}  // namespace bake
