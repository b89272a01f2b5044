// Quality of a tonal art map, measured for every report and checked by tests (issue "tambake",
// deliverable 4): per image the tone error against its target; nesting violations (a texel of a darker
// tone brighter than the same texel of a lighter tone, or a stroke of a coarse level missing from a
// finer level); monotone tones; the mean darkness difference between adjacent levels of a tone;
// ink uniformity as the coefficient of variation of the darkness over quarter-tile windows (16
// windows of side N/4, wrapping); the share of the darkness's spectral power (DC excluded) at
// frequencies below 4 cycles per tile ("low-frequency power").
//
// Where the uniformity targets apply (CV <= 0.08, low-frequency power <= 3 %): to stroke images of
// side >= kUniformityMinSide (128) holding >= kUniformityMinStrokes (128) strokes, i.e. at least 8
// strokes per quarter-tile window on average. The reasons, measured on the default style
// (bench/tam): (1) the window CV counts whole strokes: with n strokes per window the ink of a window
// varies by a fraction of a stroke at best, and below ~8 per window (tone 0.15 at 256^2, tone 0.3
// at 128^2: ~6 per window) evenly spread strokes still give a CV of 0.08-0.12 depending on the seed;
// (2) at 64 texels the band below 4 cycles per tile is 48 of the 4095 non-DC frequencies, white
// noise alone puts 1.2 % of its power there, and strokes 0.3-0.5 tile long keep most of their power at
// |f| <= 1 / length along their direction for every frequency across it, so even evenly spread
// hatching at 64^2 measures 3-6 %. Every image's figures are still measured and reported
// (ImageQuality, with its stroke count), and maxInkVariationAll / maxLowFrequencyPowerAll are the
// maxima over all stroke images.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hatching/bake/build.h"

namespace bake::hatching {

struct ImageQuality {
  int tone = 0, mip = 0, side = 0;
  double target = 0, darkness = 0;
  double toneError = 0;            // |darkness - target|
  double toneTolerance = 0;        // max(0.0025, 0.8 / side)
  double inkVariation = 0;         // coefficient of variation over quarter-tile windows
  double lowFrequencyPower = 0;    // share of non-DC power below 4 cycles per tile
  long long strokes = 0;           // strokes drawn in this image
  bool uniformityChecked = false;  // side >= kUniformityMinSide and strokes >= kUniformityMinStrokes
};

inline constexpr int kUniformityMinSide = 128;
inline constexpr long long kUniformityMinStrokes = 128;
// The scope above in words, for reports: "stroke images of side >= 128 holding >= 128 strokes ...".
std::string uniformityScope();
// The uniformity targets within that scope (the tambake issue's done-when figures).
inline constexpr double kInkVariationTarget = 0.08;
inline constexpr double kLowFrequencyPowerTarget = 0.03;

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

}  // namespace bake::hatching
