// The RGBA shape map of seed 001 ("Shape and displacement map"), made right: B holds the *signed*
// distance to the profile in the (r, h) half-plane (exactly the 3D distance to the revolved surface),
// R/G its unit gradient, A the coverage. From vector profiles the distance is exact at every texel
// centre; from coverage images an anti-aliasing-aware EDT (Gustavson & Strand 2011) and from binary
// images the exact linear-time EDT of Felzenszwalb & Huttenlocher (2012) give it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/revolution/profile.h"

namespace bake::revolution {

enum class DistanceEncoding { Float, Unorm16, Sqrt8 };
const char* encodingName(DistanceEncoding encoding);  // the format's names (bake_formats/revolution.h)

// The grid: `width` columns from r = 0, `height` rows from hMin, square texels of `texelSize`.
struct ShapeGrid {
  int width = 0, height = 0;
  double texelSize = 0;
  double hMin = 0;
  double centreR(int i) const { return (i + 0.5) * texelSize; }
  double centreH(int j) const { return hMin + (j + 0.5) * texelSize; }
};

// Grid for a profile: the larger side has `resolution` texels, with `paddingTexels` of empty space
// around the profile (beyond rMax and below/above the h range) so the march can start outside.
ShapeGrid gridForBounds(const Bounds2& bounds, int resolution, int paddingTexels);

// Decoded shape map: per texel signed distance (object units), gradient and coverage.
struct ShapeField {
  ShapeGrid grid;
  std::vector<float> distance;  // width * height, row-major from hMin
  std::vector<float> gradR, gradH;
  std::vector<float> coverage;
  // How the field was stored, when it comes from decodeShapeMap (scale 0: never encoded): the safety
  // margin filters as the GPU does, i.e. the encoded values, and adds that encoding's step.
  DistanceEncoding encoding = DistanceEncoding::Float;
  double distanceScale = 0;
  float at(int i, int j) const { return distance[std::size_t(j) * grid.width + i]; }
};

// Exact signed distance from a validated vector profile, at texel centres; coverage by exact area
// of the solid in each texel (polygon clipping, arcs flattened finely).
ShapeField distanceFromProfile(const Profile& profile, const ShapeGrid& grid);

// A coverage image (values in [0, 1], row 0 = hMin, column 0 at the axis) with its texel size.
struct CoverageImage {
  int width = 0, height = 0;
  double texelSize = 1;
  double hMin = 0;
  std::vector<float> coverage;
};
bool isBinary(const CoverageImage& image);
// Binary input: exact EDT (Felzenszwalb-Huttenlocher) of both phases, signed, with the surface put
// half a texel between inside and outside texel centres.
ShapeField distanceFromBinary(const CoverageImage& image);
// Anti-aliased input: Gustavson-Strand vector-propagation EDT with the edge distance estimated from
// the coverage and its gradient.
ShapeField distanceFromCoverage(const CoverageImage& image);

// The exact EDT of a binary image (edt_binary.cpp): `image` holds width x height bytes; the feature
// texels are its non-zero bytes, or its zero bytes (as OpenCV's distanceTransform counts them).
// squaredEdtBinary writes the squared distance in texels to the nearest feature texel (kNoFeature
// where the image has none); distanceEdtBinary its square root, correctly rounded (+inf where none).
// Exact for images up to 32767 texels a side; threads never change the result.
enum class FeatureTexels { nonZero, zero };
constexpr std::uint32_t kNoFeature = 0xffffffffu;
void squaredEdtBinary(const std::uint8_t* image, FeatureTexels which, int width, int height, std::uint32_t* out);
void distanceEdtBinary(const std::uint8_t* image, FeatureTexels which, int width, int height, float* out);

// Encoded texels, ready for upload (RGBA of the encoding's component type, little-endian), and the
// scale the distance is stored with.
struct EncodedShapeMap {
  DistanceEncoding encoding = DistanceEncoding::Unorm16;
  double distanceScale = 1;  // object units
  std::vector<std::uint8_t> bytes;
};
EncodedShapeMap encodeShapeMap(const ShapeField& field, DistanceEncoding encoding);
// Reads encoded texels back into a field (what the GPU sees after its own decoding).
ShapeField decodeShapeMap(const EncodedShapeMap& map, const ShapeGrid& grid);

// The margin a sphere tracer must keep so that a bilinear sample of the stored distance never
// exceeds the true distance: bilinear overestimate (measured against the exact distance of the
// profile on a fine sub-texel lattice, with the analytic bound as a ceiling) plus the quantisation
// step of the encoding. In object units.
struct SafetyMargin {
  double bilinearOverestimate = 0;
  double quantisation = 0;
  double total() const { return bilinearOverestimate + quantisation; }
};
SafetyMargin measureSafetyMargin(const ShapeField& decoded, const Profile* exactProfile);

// Exact signed distance and unit gradient of a validated profile at one point (negative inside).
struct DistanceSample {
  double distance = 0;
  double gradR = 1, gradH = 0;
};
DistanceSample signedDistance(const Profile& profile, Point2 p);

}  // namespace bake::revolution
