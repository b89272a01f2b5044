#include "io/image_compare.h"

#include "io/image_codec.h"

#include <cstdio>

namespace bake {

Result<ImageDifference> compareImages(const Image& actual, const Image& expected, double threshold) {
  if (actual.width != expected.width || actual.height != expected.height || actual.channels != expected.channels) {
    return invalidInput("images differ in shape: " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                        "x" + std::to_string(actual.channels) + " against " + std::to_string(expected.width) + "x" +
                        std::to_string(expected.height) + "x" + std::to_string(expected.channels));
  }
  BAKE_ASSIGN_OR_RETURN(const ImageCodecTable* codec, imageCodec());
  ImageDifference difference;
  CodecFailure failure;
  if (!codec->compare(&actual, &expected, threshold, &difference, &failure)) return statusOf(failure, "");
  return difference;
}

bool withinTolerance(const ImageDifference& difference, const ImageTolerance& tolerance) {
  return difference.rmse <= tolerance.rmse && difference.percentOver <= tolerance.percentOver;
}

std::string describe(const ImageDifference& d) {
  char text[160];
  std::snprintf(text, sizeof text, "RMSE %.4g, max %.3g at (%d, %d), %.3g%% of pixels over %.3g", d.rmse, d.maxError,
                d.worstX, d.worstY, d.percentOver, d.threshold);
  return text;
}

}  // namespace bake
