#include "io/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>

namespace bake {
namespace {

OIIO::ImageBuf toImageBuf(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec);
  buffer.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.pixels.data());
  return buffer;
}

}  // namespace

Result<ImageDifference> compareImages(const Image& actual, const Image& expected, double threshold) {
  if (actual.width != expected.width || actual.height != expected.height || actual.channels != expected.channels) {
    return invalidInput("images differ in shape: " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                        "x" + std::to_string(actual.channels) + " against " + std::to_string(expected.width) + "x" +
                        std::to_string(expected.height) + "x" + std::to_string(expected.channels));
  }
  const OIIO::ImageBuf a = toImageBuf(actual), b = toImageBuf(expected);
  const OIIO::ImageBufAlgo::CompareResults result =
      OIIO::ImageBufAlgo::compare(a, b, float(threshold), float(threshold), OIIO::ROI::All(), 1);
  // OIIO 2.4 sets `error` whenever a pixel fails the threshold, so only its message tells a real error.
  if (const std::string message = OIIO::geterror(); !message.empty()) {
    return internalError("image comparison failed: " + message);
  }
  ImageDifference difference;
  difference.rmse = result.rms_error;
  difference.maxError = result.maxerror;
  difference.worstX = result.maxx;
  difference.worstY = result.maxy;
  difference.threshold = threshold;
  const double pixels = double(actual.width) * double(actual.height);
  difference.percentOver = pixels > 0 ? 100.0 * double(result.nfail) / pixels : 0.0;
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
