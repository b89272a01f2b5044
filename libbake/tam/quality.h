// Quality of a tonal art map, measured for every report and checked by tests (issue "tambake",
// deliverable 4): per image the tone error against its target; nesting violations (a texel of a darker
// tone brighter than the same texel of a lighter tone, or a stroke of a coarse level missing from a
// finer level); monotone tones; the mean darkness difference between adjacent levels of a tone;
// ink uniformity as the coefficient of variation of the darkness over quarter-tile windows (16
// windows of side N/4, wrapping); the share of the darkness's spectral power (DC excluded) at
// frequencies below 4 cycles per tile ("low-frequency power").
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
};

struct Quality {
  std::vector<ImageQuality> images;  // stroke levels only (box-filtered mips are exact by construction)
  long long nestingViolationsTone = 0;        // texels darker in a lighter tone (beyond 1e-6)
  long long nestingViolationsResolution = 0;  // strokes of level l missing from a finer level
  bool monotoneTones = true;
  double maxToneError = 0, maxToneErrorOverTolerance = 0;
  double meanLevelDifference = 0;  // mean |darkness(l) - darkness(l+1)| over tones and stroke levels
  double maxInkVariation = 0, maxLowFrequencyPower = 0;  // over images whose side >= 64
  nlohmann::json toJson() const;
};

Quality measureQuality(const Tam& tam);

}  // namespace bake::tam
