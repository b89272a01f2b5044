// Image comparison for golden tests and package validation, through OpenImageIO's
// ImageBufAlgo::compare: RMSE and largest error over all channels, the worst pixel, and the share of
// pixels with a channel off by more than a threshold. Images must have equal sizes and channels.
#pragma once

#include <string>

#include "bake/core/status.h"
#include "bake/io/image.h"

namespace bake {

struct ImageDifference {
  double rmse = 0;
  double maxError = 0;
  int worstX = 0, worstY = 0;
  double percentOver = 0;  // pixels with any channel off by more than `threshold`, in percent
  double threshold = 0;
};

struct ImageTolerance {
  double rmse = 0.01;        // in the images' units (0..1 for PNG)
  double threshold = 0.1;    // per-channel difference that makes a pixel "over"
  double percentOver = 0.5;  // how many such pixels are allowed, in percent
};

Result<ImageDifference> compareImages(const Image& actual, const Image& expected, double threshold);
bool withinTolerance(const ImageDifference& difference, const ImageTolerance& tolerance);
// "RMSE 0.0031, max 0.21 at (120, 44), 0.02% of pixels over 0.1"
std::string describe(const ImageDifference& difference);

}  // namespace bake
