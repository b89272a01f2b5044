// Quality of a tonal art map, measured for every report and checked by tests (issue "tambake",
// deliverable 4): per image the tone error against its target; nesting violations (a texel of a darker
// tone brighter than the same texel of a lighter tone, or a stroke of a coarse level missing from a
// finer level); monotone tones; the mean darkness difference between adjacent levels of a tone;
// ink uniformity as the coefficient of variation of the darkness over quarter-tile windows (16
// windows of side N/4, wrapping); the share of the darkness's spectral power (DC excluded) at
// frequencies below 4 cycles per tile ("low-frequency power").
//
// Where the uniformity targets apply (CV <= 0.08, low-frequency power <= 3 %): to stroke images of
// side >= 64 whose target darkness is >= kUniformityMinDarkness. The reason: a quarter-tile window of
// a light tone holds only a few strokes (tone 0.15 at 256^2 with strokes 0.3-0.5 tile long and
// 1-1.5 px wide: about 60 strokes per tile, each crossing 2-3 windows), so its ink varies from
// window to window by whole strokes whatever the placement; and below 64 texels a window is 16 texels
// or less, narrower than one stroke. Every image's figures are still measured and reported
// (ImageQuality), and maxInkVariationAll / maxLowFrequencyPowerAll give the maxima over all of them.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "tam/build.h"

namespace bake::tam {

struct ImageQuality {
  int tone = 0, mip = 0, side = 0;
  double target = 0, darkness = 0;
  double toneError = 0;            // |darkness - target|
  double toneTolerance = 0;        // max(0.0025, 0.8 / side)
  double inkVariation = 0;         // coefficient of variation over quarter-tile windows
  double lowFrequencyPower = 0;    // share of non-DC power below 4 cycles per tile
  bool uniformityChecked = false;  // side >= 64 and target >= kUniformityMinDarkness
};

inline constexpr int kUniformityMinSide = 64;
inline constexpr double kUniformityMinDarkness = 0.3;

struct Quality {
  std::vector<ImageQuality> images;  // stroke levels only (box-filtered mips are exact by construction)
  long long nestingViolationsTone = 0;        // texels darker in a lighter tone (beyond 1e-6)
  long long nestingViolationsResolution = 0;  // strokes of level l missing from a finer level
  bool monotoneTones = true;
  double maxToneError = 0, maxToneErrorOverTolerance = 0;
  double meanLevelDifference = 0;  // mean |darkness(l) - darkness(l+1)| over tones and stroke levels
  double maxInkVariation = 0, maxLowFrequencyPower = 0;  // over images with uniformityChecked
  double maxInkVariationAll = 0, maxLowFrequencyPowerAll = 0;  // over every stroke image
  nlohmann::json toJson() const;
};

Quality measureQuality(const Tam& tam);

// The figures of one image (channel 0 of `brightness`, square, side a power of two for the spectrum):
// mean darkness, coefficient of variation of the darkness over the 16 quarter-tile windows (0 for a
// blank image), and the share of the darkness's non-DC spectral power at frequencies below 4 cycles
// per tile (0 for a uniform image).
double meanDarkness(const stroke::Raster& brightness);
double inkVariation(const stroke::Raster& brightness);
double lowFrequencyPower(const stroke::Raster& brightness);

}  // namespace bake::tam
