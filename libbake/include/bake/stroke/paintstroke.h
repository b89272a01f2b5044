// 2D paintstrokes (seed 002, Neulander & van de Panne 1998, reduced to the image plane): a stroke is a
// list of control points; the centreline is a Catmull-Rom spline through them, the radius too, and
// colour and opacity vary linearly along the length. Across the stroke the opacity goes from
// `centreOpacity` to `edgeOpacity` (breadthwise opacity); the ends taper. Coverage is antialiased
// analytically (box-filtered pixel against the stroke's edge), and a stroke thinner than a pixel keeps
// its ink (coverage x width is conserved, only spread). Images wrap toroidally when asked, so tiles
// repeat. Compositing is multiplicative: ink darkens paper and never lightens it, so drawing a stroke
// on top of an image only ever removes brightness (what TAM nesting needs).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace bake::stroke {

struct ControlPoint {
  double x = 0, y = 0;       // image units (pixels of the image drawn into, or tile units; see Raster)
  double radius = 0.5;       // half-width, same units as x and y
  std::array<double, 3> colour{0, 0, 0};  // ink colour (linear RGB); black ink by default
  double opacity = 1;        // in [0, 1]
};

// A user-supplied stroke image (tambake's "image" style): ink alpha in [0, 1], x along the stroke's
// length (left = start), y across it (top = left edge), bilinearly sampled.
struct StrokeTexture {
  int width = 0, height = 0;
  std::vector<float> alpha;  // row-major
};

struct Paintstroke {
  std::vector<ControlPoint> points;  // at least 2; a single dot is two coincident-ish points
  double centreOpacity = 1;          // breadthwise opacity at the centreline ...
  double edgeOpacity = 1;            // ... and at the edges (linear in |offset| / radius)
  double taper = 0;                  // fraction of the length (at most 0.5) over which each end narrows
                                     // to 0 (smoothstep in arc length: a tapered stretch keeps half its ink)
  const StrokeTexture* texture = nullptr;  // optional: multiplies the alpha at the pixel centre (not owned)
};

// A grey or colour image the strokes are drawn into, values in [0, 1], 1 = untouched paper.
struct Raster {
  int width = 0, height = 0;
  int channels = 1;            // 1 (brightness) or 3 (RGB)
  bool wrap = true;            // toroidal: strokes leaving one side come back on the other
  std::vector<float> values;   // row-major, channels interleaved

  Raster() = default;
  Raster(int w, int h, int c, bool wrapAround) : width(w), height(h), channels(c), wrap(wrapAround),
      values(std::size_t(w) * std::size_t(h) * std::size_t(c), 1.0f) {}
  float& at(int x, int y, int c = 0) { return values[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c = 0) const { return values[(std::size_t(y) * width + x) * channels + c]; }
};

// The ink a stroke puts on each pixel it touches: alpha in (0, 1] = opacity x coverage, and the
// colour. Pixels are listed once each (after wrap-around), in row-major order.
struct InkFootprint {
  struct Pixel {
    std::int32_t x, y;
    float alpha;
    std::array<float, 3> colour;
  };
  std::vector<Pixel> pixels;
  double ink() const;  // sum of alpha: the stroke's ink in pixel units
};

// How the centreline is sampled: each spline segment (between two control points) is cut into
// straight pieces no longer than `maxPieceLength` pixels (and at least one), and more where the
// segment bends, so that no piece's chord strays further than `maxDeviation` pixels from the spline.
// Coverage is exact for each straight piece whatever its length; these bound only how well the
// polyline follows the curve.
struct RasterOptions {
  double maxPieceLength = 2;
  double maxDeviation = 0.02;
};

// Rasterises `stroke` whose coordinates are in pixels of a `width` x `height` image (pixel (i, j)
// covers [i, i + 1] x [j, j + 1]). The stroke's shape is the disc of its radius swept along the
// centreline, so its ends are round; a pixel's alpha is the ink density integrated over the pixel
// (box filter), exact for straight pieces and the caps, so a straight stroke of length L puts
// opacity x (2 r L + pi r^2) of ink at any width, angle and sub-pixel position (times (centre + edge)/2
// on the body with breadthwise opacity). Two coincident points make a dot. With wrap on, a pixel's ink
// is the sum of the stroke's coverage over every periodic copy, clamped to 1, and a radius beyond
// max(width, height) counts as that. Negative radii count as 0; opacities and colours are clamped to
// [0, 1]. A stroke with fewer than two points or a non-finite value, or one longer than about a
// million pieces, gives an empty footprint. Deterministic; no shared state, so calls may run
// concurrently.
InkFootprint rasterize(const Paintstroke& stroke, int width, int height, bool wrap, const RasterOptions& options = {});

// Composites a footprint multiplicatively: value *= 1 - alpha * (1 - colour), per channel (for a
// 1-channel raster the colour's mean is used). Never raises a value.
void composite(const InkFootprint& footprint, Raster& raster);

// Convenience: rasterize + composite.
void draw(const Paintstroke& stroke, Raster& raster, const RasterOptions& options = {});

// The stroke scaled about the origin (for drawing one tile-space stroke at several resolutions: the
// positions scale, the radius is kept, since every TAM level uses the same stroke width in pixels).
Paintstroke scaledPositions(const Paintstroke& stroke, double factor);

// Catmull-Rom evaluation used by the rasterizer (centripetal would change the seed's look; this is
// the uniform spline through the points, with the end points doubled), exposed for tests: position
// and radius at parameter t in [0, points - 1]; colour and opacity at t are linear in arc length
// between the two control points around t (as the rasterizer draws them). No taper is applied here.
ControlPoint evaluate(const Paintstroke& stroke, double t);

}  // namespace bake::stroke
