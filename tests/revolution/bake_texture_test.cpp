// The arc-length map of revolbake's texturing stage against the analytic arc length of a sphere's
// profile, and the choice of projection the stage records.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "revolution/bake/bake_stages.h"

namespace bake::revolution {
namespace {

// The unit sphere's profile: a half circle from the south pole to the north pole through r = 1.
Profile sphereProfile() {
  Profile profile;
  Contour contour;
  contour.segments.push_back({{0, -1}, {0, 1}, 1.0, false});
  profile.contours.push_back(contour);
  profile.source = "sphere";
  std::vector<std::string> repairs;
  EXPECT_TRUE(validateProfile(profile, repairs).isOk());
  return profile;
}

TEST(ArcLengthMap, EveryTexelHoldsTheArcLengthOfItsNearestSpherePoint) {
  BakeState state;
  state.profile = sphereProfile();
  state.field = distanceFromProfile(state.profile, gridForBounds(profileBounds(state.profile), 128, 4));
  Settings settings;
  settings.projection = Projection::ArcLength;
  chooseTextureProjection(settings, state);
  ASSERT_EQ(state.projection.chosen, Projection::ArcLength);
  const ShapeGrid& grid = state.field.grid;
  ASSERT_EQ(state.arcLengthMap.size(), std::size_t(grid.width) * grid.height * 2);
  double worst = 0;
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      const double r = grid.centreR(i), h = grid.centreH(j);
      if (std::hypot(r, h) < 0.05) continue;  // the centre is equally near every point
      // The nearest point of the half circle lies on the ray from the centre; its arc length from the
      // south pole is the polar angle measured from -h.
      const double expected = (std::atan2(h, r) + std::numbers::pi / 2) / std::numbers::pi;
      const std::size_t k = std::size_t(j) * grid.width + i;
      const double stored = (state.arcLengthMap[2 * k] | (state.arcLengthMap[2 * k + 1] << 8)) / 65535.0;
      worst = std::max(worst, std::abs(stored - expected));
    }
  }
  // unorm16 rounding plus the float field's gradient.
  EXPECT_LT(worst, 1e-4);
}

TEST(ArcLengthMap, OnlyTheArcLengthProjectionCarriesTheMap) {
  BakeState state;
  state.profile = sphereProfile();
  state.field = distanceFromProfile(state.profile, gridForBounds(profileBounds(state.profile), 64, 4));
  Settings settings;
  settings.projection = Projection::Spherical;
  chooseTextureProjection(settings, state);
  EXPECT_EQ(state.projection.chosen, Projection::Spherical);
  EXPECT_TRUE(state.arcLengthMap.empty());
  EXPECT_EQ(state.projection.scores.size(), 3u);
}

}  // namespace
}  // namespace bake::revolution
