// Construction of a tonal art map after Praun, Hoppe, Webb, Finkelstein, "Real-time hatching",
// SIGGRAPH 2001, section 3 ("Tonal art maps"): tones are filled light -> dark and levels coarse -> fine;
// each image starts from its lighter neighbour at the same level plus the strokes of coarser levels of
// its own tone; strokes are chosen greedily, the best of K random candidates by tone progress over
// all finer levels per unit of ink, progress measured on a slightly blurred image so overlapping
// strokes score less and strokes spread evenly (plus, at the tile's scale, a weight favouring the
// coarse cells that lag behind the target: build_level.cpp). A stroke placed at level l is drawn into every level
// >= l of its tone and of every darker tone, at the same width in pixels (levels are rendered, never
// downsampled), so nesting across tones and resolutions holds by construction. Tiles wrap toroidally.
// Mip levels below the coarsest stroke level are box-filtered (mean-preserving), and so are the
// coarse levels the style asks for that cannot hold a stroke (side < max(8, 4 x the widest stroke)).
// An image stops receiving strokes when its mean darkness reaches the target: the last stroke is
// kept only if it brings the mean closer to the target.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "bake/core/status.h"
#include "bake/hatching/style.h"
#include "bake/stroke/paintstroke.h"

namespace bake::hatching {

// One placed stroke, in tile units ([0, 1)^2, wrapping); radius in pixels (same at every level).
struct PlacedStroke {
  int tone = 0;   // first tone that has it
  int level = 0;  // first (coarsest) level that has it, 0 = coarsest stroke level
  stroke::Paintstroke stroke;  // positions in tile units, radii in pixels; image strokes point at
                               // Tam::strokeTexture
};

struct Tam {
  int tones = 0;
  int strokeLevels = 0;  // levels drawn with strokes
  int mipLevels = 0;     // full chain down to 1x1
  int resolution = 0;    // side of mip level 0 (finest)
  bool coloured = false;
  // images[tone][mip], mip 0 = finest (resolution), mip m has side resolution >> m. Mips 0 ..
  // strokeLevels-1 are drawn with strokes, the rest box-filtered.
  // Brightness: the ink as if black (1 - brightness is the darkness the tone targets), 1 channel.
  std::vector<std::vector<stroke::Raster>> images;
  // Coloured ink only: the same images in RGB (the ink composited on white paper), 3 channels.
  std::vector<std::vector<stroke::Raster>> colourImages;
  // Fine tone control (Webb et al. 2002): per mip, the darkness at which each texel turns to ink.
  // Stroke levels: texels are ordered by the stroke that first inked them (1 - brightness >=
  // kThresholdInk), and each stroke's texels get the mean darkness of the darkest tone's image over
  // them and all texels inked before them, so that inking every texel whose threshold is <= d gives
  // mean darkness d; 1 where no tone inks the texel. Coarser mips: 2x2 averages. One channel.
  std::vector<stroke::Raster> thresholds;
  std::vector<PlacedStroke> strokes;  // in placement order
  std::vector<double> targets;        // target darkness per tone
  std::shared_ptr<const stroke::StrokeTexture> strokeTexture;  // image strokes' alpha (shared by copies)
  long long candidatesEvaluated = 0;  // statistics: candidate strokes scored
};

struct BuildOptions {
  int threads = 0;  // 0: hardware; the result does not depend on it
  // Progress callback: fraction done in [0, 1] (may be empty).
  std::function<void(double)> progress;
};

// The number of levels drawn with strokes: the style's `levels`, at most log2(resolution) + 1, less
// the coarse levels narrower than max(8, 4 x stroke.width.max) pixels (they cannot hold a stroke and
// are box-filtered instead); at least 1.
int strokeLevelCount(const Style& style);

// Checks what the construction relies on (the style reader checks more); errors name the style's
// source and the JSON pointer of the element at fault.
Status checkStyle(const Style& style);

// Deterministic for a style (seed included), whatever the thread count.
Result<Tam> buildTam(const Style& style, const BuildOptions& options = {});

// Threshold texture (Webb et al. 2002): Tam::thresholds, one channel per mip.
std::vector<stroke::Raster> thresholdTexture(const Tam& tam);

}  // namespace bake::hatching
