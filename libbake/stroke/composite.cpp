// Multiplicative compositing of paintstroke ink (see paintstroke.h): a pixel of brightness v under ink
// of alpha a and colour c becomes v (1 - a (1 - c)), so black ink (c = 0) multiplies by 1 - a and white
// ink leaves the paper alone. Since a and c lie in [0, 1] the factor is in [0, 1]: drawing never
// lightens an image, which is what the nesting of tonal art maps (Praun et al. 2001, section 3.2)
// relies on.
#include <algorithm>
#include <cmath>

#include "bake/stroke/paintstroke.h"

namespace bake::stroke {

double InkFootprint::ink() const {
  double sum = 0;
  for (const Pixel& p : pixels) sum += double(p.alpha);
  return sum;
}

void composite(const InkFootprint& footprint, Raster& raster) {
  if (raster.channels != 1 && raster.channels != 3) return;
  if (raster.values.size() < std::size_t(raster.width) * std::size_t(raster.height) * std::size_t(raster.channels)) return;
  for (const InkFootprint::Pixel& p : footprint.pixels) {
    if (p.x < 0 || p.y < 0 || p.x >= raster.width || p.y >= raster.height) continue;
    const float alpha = std::isfinite(p.alpha) ? std::clamp(p.alpha, 0.0f, 1.0f) : 0.0f;
    if (alpha <= 0) continue;
    std::array<float, 3> colour;
    for (int k = 0; k < 3; ++k) colour[k] = std::isfinite(p.colour[k]) ? std::clamp(p.colour[k], 0.0f, 1.0f) : 0.0f;
    if (raster.channels == 1) {
      const float mean = (colour[0] + colour[1] + colour[2]) / 3;
      raster.at(p.x, p.y) *= 1 - alpha * (1 - mean);
    } else {
      for (int k = 0; k < 3; ++k) raster.at(p.x, p.y, k) *= 1 - alpha * (1 - colour[k]);
    }
  }
}

void draw(const Paintstroke& stroke, Raster& raster, const RasterOptions& options) {
  composite(rasterize(stroke, raster.width, raster.height, raster.wrap, options), raster);
}

Paintstroke scaledPositions(const Paintstroke& stroke, double factor) {
  Paintstroke out = stroke;
  for (ControlPoint& p : out.points) {
    p.x *= factor;
    p.y *= factor;
  }
  return out;
}

}  // namespace bake::stroke
