// Shape map encodings and the safety margin (shape_map_encode.cpp): round trips stay within each
// encoding's quantisation bound, the sqrt encoding keeps the step at the surface under a texel at
// 4096^2 where 8-bit linear would not, and a bilinear sample minus the margin does not exceed the
// exact distance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bake/revolution/shape_map.h"
#include "revolution/profile_shapes.h"

namespace bake::revolution {
namespace {

using namespace bake::revolution::test;

Profile vase() {
  Profile profile = makeProfile({vaseContour()});
  std::vector<std::string> warnings;
  EXPECT_TRUE(validateProfile(profile, warnings).isOk());
  return profile;
}

double largest(const ShapeField& field) {
  double s = 0;
  for (float d : field.distance) s = std::max(s, double(std::abs(d)));
  return s;
}

TEST(EncodeShapeMap, RoundTripsWithinTheQuantisationBound) {
  const Profile profile = vase();
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 64, 4);
  const ShapeField field = distanceFromProfile(profile, grid);
  const double scale = largest(field);
  for (DistanceEncoding encoding : {DistanceEncoding::Float, DistanceEncoding::Unorm16, DistanceEncoding::Sqrt8}) {
    const EncodedShapeMap map = encodeShapeMap(field, encoding);
    EXPECT_DOUBLE_EQ(map.distanceScale, scale);
    const std::size_t bytesPerTexel = encoding == DistanceEncoding::Float ? 16 : encoding == DistanceEncoding::Unorm16 ? 8 : 4;
    ASSERT_EQ(map.bytes.size(), field.distance.size() * bytesPerTexel);
    const ShapeField back = decodeShapeMap(map, grid);
    EXPECT_EQ(back.encoding, encoding);
    for (std::size_t k = 0; k < field.distance.size(); ++k) {
      const double d = field.distance[k], e = back.distance[k];
      double bound = 1e-6 * scale;
      double channelBound = 1e-7;
      if (encoding == DistanceEncoding::Unorm16) {
        bound += scale / 65535.0;
        channelBound = 1.0 / 65535.0;
      } else if (encoding == DistanceEncoding::Sqrt8) {
        // Half a code is 1/255 in s = sqrt(|d| / S); d = S s^2 moves by S ds (2 s + ds).
        const double s = std::sqrt(std::abs(d) / scale);
        bound += scale * (1.0 / 255.0) * (2 * s + 1.0 / 255.0);
        channelBound = 1.0 / 255.0;
      }
      ASSERT_LE(std::abs(d - e), bound) << encodingName(encoding) << " texel " << k;
      ASSERT_LE(std::abs(field.gradR[k] - back.gradR[k]), channelBound * 1.0001);
      ASSERT_LE(std::abs(field.gradH[k] - back.gradH[k]), channelBound * 1.0001);
      ASSERT_LE(std::abs(field.coverage[k] - back.coverage[k]), 0.5 * channelBound * 1.0001);
      ASSERT_EQ(d < 0, e < 0 || (e == 0 && d > -bound)) << "sign flipped at " << k;
    }
  }
}

TEST(EncodeShapeMap, SqrtEightBitStepIsUnderATexelAt4096) {
  const Profile profile = vase();
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 4096, 8);
  // The largest |d| of the map is on its border (outside, the distance has no interior maximum) or
  // deep inside (less than the vase's half width); sample both.
  ShapeField field;
  field.grid = grid;
  auto add = [&](int i, int j) {
    const DistanceSample s = signedDistance(profile, {grid.centreR(i), grid.centreH(j)});
    field.distance.push_back(float(s.distance));
    field.gradR.push_back(float(s.gradR));
    field.gradH.push_back(float(s.gradH));
    field.coverage.push_back(s.distance < 0 ? 1.0f : 0.0f);
  };
  for (int i = 0; i < grid.width; i += 7) add(i, 0), add(i, grid.height - 1);
  for (int j = 0; j < grid.height; j += 7) add(0, j), add(grid.width - 1, j);
  for (int j = 0; j < grid.height; j += 64)
    for (int i = 0; i < grid.width; i += 64) add(i, j);
  const EncodedShapeMap map = encodeShapeMap(field, DistanceEncoding::Sqrt8);
  const double scale = map.distanceScale;
  // Codes 127 and 128 straddle d = 0: the step across the surface.
  EncodedShapeMap probe = map;
  probe.bytes.assign(8, 0);
  probe.bytes[2] = 127;
  probe.bytes[6] = 128;
  ShapeGrid two;
  two.width = 2;
  two.height = 1;
  two.texelSize = grid.texelSize;
  const ShapeField decoded = decodeShapeMap(probe, two);
  const double sqrtStep = decoded.distance[1] - decoded.distance[0];
  const double linearStep = 2 * scale / 255.0;
  EXPECT_NEAR(sqrtStep, 2 * scale / (255.0 * 255.0), 1e-9 * scale);
  EXPECT_LT(sqrtStep, grid.texelSize);
  EXPECT_GT(linearStep, grid.texelSize) << "scale " << scale << " texel " << grid.texelSize;
  // And within a texel of the surface every step between neighbouring codes is under a texel.
  const double x1 = std::sqrt(grid.texelSize / scale);  // s at one texel from the surface
  const int lastCode = int(std::ceil((0.5 + 0.5 * x1) * 255.0));
  for (int code = 128; code < lastCode; ++code) {
    auto decode = [&](int c) {
      const double x = 2.0 * c / 255.0 - 1;
      return x * x * scale;
    };
    EXPECT_LT(decode(code + 1) - decode(code), grid.texelSize) << "code " << code;
  }
}

// Bilinear sample of the stored distance as the GPU does it (formats/revolution.md): on the encoded
// B values, mirrored at r = 0, clamped elsewhere, then decoded.
double gpuSample(const EncodedShapeMap& map, const ShapeGrid& grid, double r, double h) {
  const ShapeField f = decodeShapeMap(map, grid);
  auto code = [&](int i, int j) {
    if (i < 0) i = -1 - i;
    i = std::min(i, grid.width - 1);
    j = std::clamp(j, 0, grid.height - 1);
    const double d = f.at(i, j);
    if (map.encoding == DistanceEncoding::Sqrt8) return 0.5 + 0.5 * std::copysign(std::sqrt(std::abs(d) / map.distanceScale), d);
    return d;
  };
  const double x = r / grid.texelSize - 0.5, y = (h - grid.hMin) / grid.texelSize - 0.5;
  const int i = int(std::floor(x)), j = int(std::floor(y));
  const double u = x - i, v = y - j;
  const double b = (1 - v) * ((1 - u) * code(i, j) + u * code(i + 1, j)) + v * ((1 - u) * code(i, j + 1) + u * code(i + 1, j + 1));
  if (map.encoding != DistanceEncoding::Sqrt8) return b;
  const double s = 2 * b - 1;
  return std::copysign(s * s, s) * map.distanceScale;
}

TEST(SafetyMargin, BilinearSampleMinusMarginStaysBelowTheExactDistance) {
  const Profile profile = vase();
  const ShapeGrid grid = gridForBounds(profileBounds(profile), 48, 4);
  const ShapeField field = distanceFromProfile(profile, grid);
  for (DistanceEncoding encoding : {DistanceEncoding::Float, DistanceEncoding::Unorm16, DistanceEncoding::Sqrt8}) {
    const EncodedShapeMap map = encodeShapeMap(field, encoding);
    const ShapeField decoded = decodeShapeMap(map, grid);
    const SafetyMargin margin = measureSafetyMargin(decoded, &profile);
    EXPECT_GT(margin.bilinearOverestimate, 0);
    EXPECT_GT(margin.quantisation, 0);
    if (encoding == DistanceEncoding::Float) {
      EXPECT_LE(margin.bilinearOverestimate, grid.texelSize * std::sqrt(0.5));  // the analytic ceiling
    }
    // Independent points (not on the 4 x 4 lattice) within 2 texels of the surface. The lattice
    // can miss the very worst point between its samples; allow a hundredth of a texel for that.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> r(0.0, grid.width * grid.texelSize), h(grid.hMin, grid.hMin + grid.height * grid.texelSize);
    int tested = 0;
    for (int k = 0; k < 200000 && tested < 3000; ++k) {
      const Point2 p{r(rng), h(rng)};
      const double exact = signedDistance(profile, p).distance;
      if (std::abs(exact) > 2 * grid.texelSize) continue;
      ++tested;
      EXPECT_LE(gpuSample(map, grid, p.r, p.h) - margin.total(), exact + 0.01 * grid.texelSize)
          << encodingName(encoding) << " at " << p.r << ", " << p.h;
    }
    EXPECT_EQ(tested, 3000);
  }
  const SafetyMargin ceiling = measureSafetyMargin(field, nullptr);
  EXPECT_DOUBLE_EQ(ceiling.bilinearOverestimate, grid.texelSize * std::sqrt(0.5));
}

}  // namespace
}  // namespace bake::revolution
