// Construction of a tonal art map after Praun, Hoppe, Webb, Finkelstein, "Real-time hatching",
// SIGGRAPH 2001, section 3 ("Tonal art maps"): tones are filled light -> dark and levels coarse -> fine;
// each image starts from its lighter neighbour at the same level plus the strokes of coarser levels of
// its own tone; strokes are chosen greedily, the best of K random candidates by tone progress over
// all finer levels per unit of ink, progress measured on a slightly blurred image so overlapping
// strokes score less and strokes spread evenly. A stroke placed at level l is drawn into every level
// >= l of its tone and of every darker tone, at the same width in pixels (levels are rendered, never
// downsampled), so nesting across tones and resolutions holds by construction. Tiles wrap toroidally.
// Mip levels below the coarsest stroke level are box-filtered (mean-preserving).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/status.h"
#include "stroke/paintstroke.h"
#include "tam/style.h"

namespace bake::tam {

// One placed stroke, in tile units ([0, 1)^2, wrapping); radius in pixels (same at every level).
struct PlacedStroke {
  int tone = 0;   // first tone that has it
  int level = 0;  // first (coarsest) level that has it, 0 = coarsest stroke level
  stroke::Paintstroke stroke;  // positions in tile units, radii in pixels
};

struct Tam {
  int tones = 0;
  int strokeLevels = 0;  // levels drawn with strokes
  int mipLevels = 0;     // full chain down to 1x1
  int resolution = 0;    // side of mip level 0 (finest)
  bool coloured = false;
  // images[tone][mip], mip 0 = finest (resolution), mip m has side resolution >> m. Mips 0 ..
  // strokeLevels-1 are drawn with strokes, the rest box-filtered.
  std::vector<std::vector<stroke::Raster>> images;
  std::vector<PlacedStroke> strokes;  // in placement order
  std::vector<double> targets;        // target darkness per tone
};

struct BuildOptions {
  int threads = 0;  // 0: hardware; the result does not depend on it
  // Progress callback: fraction done in [0, 1] (may be empty).
  std::function<void(double)> progress;
};

// Deterministic for a style (seed included), whatever the thread count.
Result<Tam> buildTam(const Style& style, const BuildOptions& options = {});

// Threshold texture (Webb et al. 2002): per texel of every mip, the darkness of the first tone whose
// image inks it (1 - brightness >= kThresholdInk), or 1 when none. thresholds[mip] is one channel.
std::vector<stroke::Raster> thresholdTexture(const Tam& tam);

}  // namespace bake::tam
