// Area sampling for special cases (libbake/grooves/oracle/area_sampling.cpp, seed 000 §6): closed forms derived
// by hand for an isolated V-groove (masking and shadowing in the cross-section), the facet fractions of
// a 90° crossing and a 90° corner seen from above, the wall's share at an open end seen from the side,
// continuity across nearly straight corners, and the ray-traced reference (reference.h) for crossings,
// T-junctions and corners at oblique views.
#include "area_support.h"

namespace bake::grooves {
namespace {

using namespace area_test;

// The V-groove along v through u = 0.5: the facet x = u - 0.5 in [-w, 0] rises towards -u (it faces
// +u), the facet in [0, w] faces -u.
const Vec3 kFacesPlusU = facetNormal(-kD / kW, 0), kFacesMinusU = facetNormal(kD / kW, 0);
constexpr double kSide = 0.05;  // footprint side

GrooveScene isolatedV() { return sceneWith(line("v", "red", {0.5, 0}, {0.5, 1})); }

double lambert(const GrooveScene& s, const char* material, const Vec3& n, const Lighting& l, int c) {
  return directRadiance(materialNamed(s, material), n, {0, 0, 1}, l)[c];
}

TEST(GrooveAreaSampling, IsolatedVGrooveFromAboveLitFromAbove) {
  const GrooveScene s = isolatedV();
  const Lighting l = lightTowards({0, 0, 1});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), {0, 0, 1}, l);
  for (int c = 0; c < 3; ++c) {
    const double expected = ((kSide - 2 * kW) * lambert(s, "ground", {0, 0, 1}, l, c) +
                             kW * lambert(s, "red", kFacesPlusU, l, c) + kW * lambert(s, "red", kFacesMinusU, l, c)) /
                            kSide;
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
}

TEST(GrooveAreaSampling, IsolatedVGrooveObliqueViewAcross) {
  // Seen from 30° towards +u: the facet facing +u is stretched to w + d tan(theta) on the base plane,
  // the other squeezed to w - d tan(theta); a light tilted 20° along u leaves both lit, unshadowed.
  const GrooveScene s = isolatedV();
  const double theta = 30 * kPi / 180, phi = 20 * kPi / 180;
  const Vec3 e{std::sin(theta), 0, std::cos(theta)};
  const Lighting l = lightTowards({std::sin(phi), 0, std::cos(phi)});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), e, l);
  const double shift = kD * std::tan(theta);
  for (int c = 0; c < 3; ++c) {
    const double expected = ((kSide - 2 * kW) * lambert(s, "ground", {0, 0, 1}, l, c) +
                             (kW + shift) * lambert(s, "red", kFacesPlusU, l, c) +
                             (kW - shift) * lambert(s, "red", kFacesMinusU, l, c)) /
                            kSide;
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
}

// Light from +u at phi beyond the facet slope: the facet facing -u is dark, and the rim at x = +w
// shadows the facet facing +u from x_s = (w cot(phi) - d) / (d / w + cot(phi)) to 0.
double shadowStart(double phi) {
  const double c = 1 / std::tan(phi);
  return (c * kW - kD) / (kD / kW + c);
}

TEST(GrooveAreaSampling, IsolatedVGrooveFromAboveObliqueLight) {
  const GrooveScene s = isolatedV();
  const double phi = 70 * kPi / 180;
  const Lighting l = lightTowards({std::sin(phi), 0, std::cos(phi)});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), {0, 0, 1}, l);
  const double lit = shadowStart(phi) + kW;
  ASSERT_GT(lit, 0);
  ASSERT_LT(lit, kW);
  for (int c = 0; c < 3; ++c) {
    const double expected =
        ((kSide - 2 * kW) * lambert(s, "ground", {0, 0, 1}, l, c) + lit * lambert(s, "red", kFacesPlusU, l, c)) /
        kSide;
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
}

TEST(GrooveAreaSampling, IsolatedVGrooveObliqueViewAndLight) {
  // Seen from 25° towards -u (the facet facing +u is squeezed by 1 - (d/w) tan(theta)), lit from 70°
  // towards +u: its lit part [-w, x_s] keeps that squeeze on the base plane.
  const GrooveScene s = isolatedV();
  const double theta = 25 * kPi / 180, phi = 70 * kPi / 180;
  const Vec3 e{-std::sin(theta), 0, std::cos(theta)};
  const Lighting l = lightTowards({std::sin(phi), 0, std::cos(phi)});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), e, l);
  const double lit = (shadowStart(phi) + kW) * (1 - kD / kW * std::tan(theta));
  const Material &base = materialNamed(s, "ground"), &red = materialNamed(s, "red");
  for (int c = 0; c < 3; ++c) {
    const double expected = ((kSide - 2 * kW) * directRadiance(base, {0, 0, 1}, e, l)[c] +
                             lit * directRadiance(red, kFacesPlusU, e, l)[c]) /
                            kSide;
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
}

TEST(GrooveAreaSampling, RightAngleCrossingFromAboveFacetFractions) {
  // Two V-grooves crossing at (0.5, 0.5), seen from above: inside the crossing square the deeper one is
  // the one whose path is nearer, so each of the four facets gets w (a - 2w) outside the square plus
  // w^2 inside, and the ground a^2 - 4 w (a - w). A shiny material gives the four facets different
  // radiance under a tilted light (all facing it, so nothing is shadowed).
  const GrooveScene s = sceneWith(line("v", "shiny", {0.5, 0}, {0.5, 1}) + ", " + line("v", "red", {0, 0.5}, {1, 0.5}));
  const Vec3 e{0, 0, 1};
  for (const Vec3 toLight : {Vec3{0.2, 0.3, 1}, Vec3{-0.25, 0.1, 1}}) {
    const Lighting l = lightTowards(toLight);
    const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), e, l);
    const double facet = kW * (kSide - kW), ground = kSide * kSide - 4 * facet;
    const Material &base = materialNamed(s, "ground"), &red = materialNamed(s, "red");
    const Material& shiny = materialNamed(s, "shiny");
    for (int c = 0; c < 3; ++c) {
      const double expected =
          (ground * directRadiance(base, {0, 0, 1}, e, l)[c] +
           facet * (directRadiance(shiny, facetNormal(-kD / kW, 0), e, l)[c] +
                    directRadiance(shiny, facetNormal(kD / kW, 0), e, l)[c] +
                    directRadiance(red, facetNormal(0, -kD / kW), e, l)[c] +
                    directRadiance(red, facetNormal(0, kD / kW), e, l)[c])) /
          (kSide * kSide);
      EXPECT_NEAR(value[c], expected, 1e-9);
    }
  }
}

TEST(GrooveAreaSampling, RightAngleCornerFromAboveFacetFractions) {
  // A polyline turning left by 90° at (0.5, 0.5): each arm stops on the mitre line u + v = 1, its inner
  // facet covers a w / 2 - w^2 / 2 of the footprint, its outer facet a w / 2 + w^2 / 2.
  const GrooveScene s = sceneWith(polyline("v", "shiny", {{0.2, 0.5}, {0.5, 0.5}, {0.5, 0.8}}));
  const Vec3 e{0, 0, 1};
  const Lighting l = lightTowards({0.3, -0.2, 1});
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), e, l);
  const double inner = kSide * kW / 2 - kW * kW / 2, outer = kSide * kW / 2 + kW * kW / 2;
  const double ground = kSide * kSide - 2 * kSide * kW;
  const Material &base = materialNamed(s, "ground"), &shiny = materialNamed(s, "shiny");
  for (int c = 0; c < 3; ++c) {
    // Arm 1 runs along +u (inner facet v > 0.5 rises towards +v), arm 2 along +v (inner facet u < 0.5).
    const double expected = (ground * directRadiance(base, {0, 0, 1}, e, l)[c] +
                             inner * directRadiance(shiny, facetNormal(0, kD / kW), e, l)[c] +
                             outer * directRadiance(shiny, facetNormal(0, -kD / kW), e, l)[c] +
                             inner * directRadiance(shiny, facetNormal(-kD / kW, 0), e, l)[c] +
                             outer * directRadiance(shiny, facetNormal(kD / kW, 0), e, l)[c]) /
                            (kSide * kSide);
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
}

TEST(GrooveAreaSampling, OpenEndSeenFromTheSideShowsItsWall) {
  // A box groove starting at u = 0.5, seen from 40° towards +u and lit from 50° towards +u: on the base
  // plane the cut's wall covers d tan(theta) x 2w, the floor the rest of the band beyond u = 0.5 (the
  // side walls are edge-on to both), the ground everything else.
  const GrooveScene s = sceneWith(line("box", "red", {0.5, 0.5}, {0.9, 0.5}));
  const double theta = 40 * kPi / 180, phi = 50 * kPi / 180;
  const Vec3 e{std::sin(theta), 0, std::cos(theta)};
  const Lighting l = lightTowards({std::sin(phi), 0, std::cos(phi)});
  AreaSampleStats stats;
  const Rgb value = sample(s, squareFootprint({0.5, 0.5}, kSide), e, l, &stats);
  EXPECT_GE(stats.surface.walls, 1u);
  const double wall = kD * std::tan(theta) * 2 * kW, floor = (kSide / 2 - kD * std::tan(theta)) * 2 * kW;
  const double ground = kSide * kSide - kSide / 2 * 2 * kW;
  const Material &base = materialNamed(s, "ground"), &red = materialNamed(s, "red");
  for (int c = 0; c < 3; ++c) {
    const double expected = (ground * directRadiance(base, {0, 0, 1}, e, l)[c] +
                             wall * directRadiance(red, {1, 0, 0}, e, l)[c] +
                             floor * directRadiance(red, {0, 0, 1}, e, l)[c]) /
                            (kSide * kSide);
    EXPECT_NEAR(value[c], expected, 1e-9);
  }
  // Seen from the other side the wall faces away: only the floor's visible part remains.
  const Vec3 back{-std::sin(theta), 0, std::cos(theta)};
  const Rgb hidden = sample(s, squareFootprint({0.5, 0.5}, kSide), back, l);
  // The rim hides the floor's first d tan(theta), which the floor beyond the footprint makes up for.
  const double floorSeen = kSide / 2 * 2 * kW;
  for (int c = 0; c < 3; ++c) {
    const double expected = (ground * directRadiance(base, {0, 0, 1}, back, l)[c] +
                             floorSeen * directRadiance(red, {0, 0, 1}, back, l)[c]) /
                            (kSide * kSide);
    EXPECT_NEAR(hidden[c], expected, 1e-9);
  }
}

TEST(GrooveAreaSampling, NearlyStraightCornerIsContinuous) {
  // A 179° corner (a 1° turn) differs from the straight groove only by the thin wedge the turn opens.
  const double turn = 1 * kPi / 180;
  const GrooveScene bent =
      sceneWith(polyline("v", "red", {{0.2, 0.5}, {0.5, 0.5}, {0.5 + 0.3 * std::cos(turn), 0.5 + 0.3 * std::sin(turn)}}));
  const GrooveScene straight = sceneWith(line("v", "red", {0.2, 0.5}, {0.8, 0.5}));
  const double theta = 50 * kPi / 180;
  const Vec3 e{0, -std::sin(theta), std::cos(theta)};
  const Lighting l = lightTowards({0.2, 0.5, 0.6});
  const Footprint f = squareFootprint({0.5, 0.5}, kSide);
  const Rgb a = sample(bent, f, e, l), b = sample(straight, f, e, l);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(b[c], 0);
    EXPECT_NEAR(a[c], b[c], 0.01 * b[c]);
    EXPECT_NE(a[c], b[c]);
  }
}

TEST(GrooveAreaSampling, CrossingObliqueAgreesWithReference) {
  const GrooveScene s = sceneWith(line("v", "shiny", {0.5, 0.1}, {0.5, 0.9}) + ", " +
                                  line("box", "red", {0.1, 0.3}, {0.9, 0.7}));
  const Footprint f{{0.5, 0.5}, {0.02, 0.004}, {-0.006, 0.025}};
  const double theta = 55 * kPi / 180;
  const Vec3 e{std::sin(theta) * std::cos(0.4), std::sin(theta) * std::sin(0.4), std::cos(theta)};
  const Lighting l = lightTowards({-0.5, 0.4, 0.5});
  expectNearReference(sample(s, f, e, l), referenceMean(s, f, e, l), 2e-4);
}

TEST(GrooveAreaSampling, TJunctionAgreesWithReference) {
  // A box groove ending on the centre line of a V-groove (an intersected end).
  const GrooveScene s = sceneWith(line("v", "red", {0.1, 0.5}, {0.9, 0.5}) + ", " +
                                  line("box", "shiny", {0.5, 0.5}, {0.5, 0.9}));
  const Footprint f = squareFootprint({0.5, 0.51}, 0.03);
  const double theta = 45 * kPi / 180;
  for (const double azimuth : {-kPi / 2, 0.3}) {
    const Vec3 e{std::sin(theta) * std::cos(azimuth), std::sin(theta) * std::sin(azimuth), std::cos(theta)};
    const Lighting l = lightTowards({0.3, -0.6, 0.5});
    expectNearReference(sample(s, f, e, l), referenceMean(s, f, e, l), 2e-4);
  }
}

TEST(GrooveAreaSampling, CornersAgreeWithReference) {
  for (const double cornerDegrees : {90.0, 150.0, 179.0}) {
    const double turn = kPi - cornerDegrees * kPi / 180;
    const GrooveScene s = sceneWith(polyline(
        "box", "red", {{0.2, 0.5}, {0.5, 0.5}, {0.5 + 0.3 * std::cos(turn), 0.5 + 0.3 * std::sin(turn)}}));
    const Footprint f = squareFootprint({0.5, 0.5}, 0.03);
    const double theta = 40 * kPi / 180;
    const Vec3 e{-std::sin(theta) * 0.6, std::sin(theta) * 0.8, std::cos(theta)};
    const Lighting l = lightTowards({0.5, -0.3, 0.6});
    SCOPED_TRACE(cornerDegrees);
    expectNearReference(sample(s, f, e, l), referenceMean(s, f, e, l), 2e-4);
  }
}

TEST(GrooveAreaSampling, RidgeOverCutAgreesWithReference) {
  // A ridge crossing a cut: H is the sum where they overlap, the material the one with the larger |h|.
  const GrooveScene s = sceneWith(line("ridge", "green", {0.5, 0.1}, {0.5, 0.9}) + ", " +
                                  line("v", "red", {0.1, 0.45}, {0.9, 0.55}));
  const Footprint f = squareFootprint({0.5, 0.5}, 0.04);
  const double theta = 35 * kPi / 180;
  const Vec3 e{std::sin(theta), 0.2 * std::sin(theta), std::cos(theta)};
  const Lighting l = lightTowards({-0.4, 0.3, 0.6});
  expectNearReference(sample(s, f, e, l), referenceMean(s, f, e, l), 2e-4);
}

TEST(GrooveAreaSampling, WrappingSceneMatchesTheSameGeometryInside) {
  // A T-junction across the domain's edge u = 1 of a repeating scene (each primitive straightened at
  // the copy of the footprint centre nearest it, as the shader passes them) equals the same T-junction
  // moved inside the domain.
  const GrooveScene wrapped = sceneWith(line("box", "red", {0.995, 0.1}, {0.995, 0.9}) + ", " +
                                            line("v", "shiny", {0.2, 0.5}, {0.995, 0.5}),
                                        1, true);
  const GrooveScene inside = sceneWith(line("box", "red", {0.495, 0.1}, {0.495, 0.9}) + ", " +
                                       line("v", "shiny", {-0.3 + 0.5, 0.5}, {0.495, 0.5}));
  const Footprint atEdge{{0.002, 0.503}, {0.02, 0.003}, {-0.004, 0.018}};
  Footprint moved = atEdge;
  moved.centre = {0.502, 0.503};
  std::vector<LocalGroove> grooves;
  for (std::uint32_t p = 0; p < wrapped.primitives.size(); ++p)
    grooves.push_back(localGroove(wrapped, p, {atEdge.centre.u + 1, atEdge.centre.v}));  // the copy at u + 1
  const double theta = 50 * kPi / 180;
  const Vec3 e{-std::sin(theta) * 0.8, std::sin(theta) * 0.6, std::cos(theta)};
  const Lighting l = lightTowards({0.4, 0.3, 0.6});
  AreaSampleStats stats;
  const Rgb a = areaSampleWithStats(wrapped, grooves, atEdge, e, l, stats);
  const Rgb b = sample(inside, moved, e, l);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9);
  EXPECT_GT(stats.surface.walls, 0u);
}

// Every pixel of small views whose pixel edges fall on the grooves' centre lines and crest lines
// (clip lines through polygon vertices): the image agrees with the reference within its noise floor
// (RMSE against one render no larger than between two renders; no pixel off by more than twice the
// largest difference between two renders).
TEST(GrooveAreaSampling, ViewsWithPixelEdgesOnPieceEdgesAgreeWithReference) {
  const std::vector<std::string> scenes = {
      line("ridge", "green", {0.5, 0.1}, {0.5, 0.9}) + ", " + line("v", "red", {0.1, 0.45}, {0.9, 0.55}),
      line("v", "red", {0.1, 0.5}, {0.9, 0.5}) + ", " + line("box", "shiny", {0.5, 0.5}, {0.5, 0.9}),
      polyline("box", "red", {{0.2, 0.4}, {0.5, 0.5}, {0.6, 0.8}})};
  const Lighting l = lightTowards({-0.3, 0.5, 0.7});
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const GrooveScene s = sceneWith(scenes[k]);
    for (const double theta : {0.0, 0.6}) {
      SCOPED_TRACE(testing::Message() << "scene " << k << " theta " << theta);
      const View view = windowView({0.475, 0.475}, {0.525, 0.525}, 10, theta, 0.7);
      Image image = rgbImage(view.width, view.height);
      for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) setRgb(image, x, y, sample(s, view.pixel(x, y), view.toViewer, l));
      ReferenceSettings settings;
      settings.samplesPerPixel = 64;  // a sweep for robustness: the closed forms above test accuracy
      settings.threads = 1;
      const Image first = renderReference(s, view, l, settings);
      settings.seed = 2;
      const Image second = renderReference(s, view, l, settings);
      const ImageError error = imageError(image, first), noise = imageError(second, first);
      EXPECT_LE(error.rmse, noise.rmse);
      EXPECT_LE(error.max, 2 * noise.max);
    }
  }
}

// The surface is built only over a working region around each footprint (the footprint swept along
// the view and the light over the grooves' height range), so the sample must not depend on that
// region: a footprint's value is the area-weighted mean of its quarters' values (each quarter has its
// own, smaller region), and a groove beyond the region's reach changes nothing. Views, lights and
// scenes with ridges over cuts, walls and crossings.
TEST(GrooveAreaSampling, SampleDoesNotDependOnTheWorkingRegion) {
  const std::vector<std::string> scenes = {
      line("ridge", "green", {0.5, 0.1}, {0.5, 0.9}) + ", " + line("v", "red", {0.1, 0.45}, {0.9, 0.55}),
      line("v", "red", {0.1, 0.5}, {0.9, 0.5}) + ", " + line("box", "shiny", {0.5, 0.5}, {0.5, 0.9}),
      line("v", "shiny", {0.5, 0.1}, {0.5, 0.9}) + ", " + line("box", "red", {0.1, 0.3}, {0.9, 0.7})};
  const std::string far = line("box", "green", {0.2, 0.1}, {0.2, 0.9});  // 0.3 away: out of reach
  const Footprint f{{0.497, 0.503}, {0.012, 0.003}, {-0.002, 0.014}};
  for (std::size_t k = 0; k < scenes.size(); ++k)
    for (const double theta : {0.0, 0.5, 1.1})
      for (const Vec3 toLight : {Vec3{-0.3, 0.5, 0.7}, Vec3{0.6, -0.2, 0.3}, Vec3{0.1, 0.2, 0.9}}) {
        SCOPED_TRACE(testing::Message() << "scene " << k << " theta " << theta << " light " << toLight.u);
        const GrooveScene s = sceneWith(scenes[k]);
        const Vec3 e{std::sin(theta) * std::cos(0.7), std::sin(theta) * std::sin(0.7), std::cos(theta)};
        const Lighting l = lightTowards(toLight);
        const Rgb whole = sample(s, f, e, l);
        Rgb quarters{0, 0, 0};
        const Vec2 h1{0.5 * f.axis1.u, 0.5 * f.axis1.v}, h2{0.5 * f.axis2.u, 0.5 * f.axis2.v};
        for (const double s1 : {-0.5, 0.5})
          for (const double s2 : {-0.5, 0.5}) {
            const Footprint q{{f.centre.u + s1 * h1.u + s2 * h2.u, f.centre.v + s1 * h1.v + s2 * h2.v}, h1, h2};
            const Rgb v = sample(s, q, e, l);
            for (int c = 0; c < 3; ++c) quarters[c] += 0.25 * v[c];
          }
        const GrooveScene withFar = sceneWith(scenes[k] + ", " + far);
        const Rgb farAdded = sample(withFar, f, e, l);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(quarters[c], whole[c], 1e-12);
          EXPECT_NEAR(farAdded[c], whole[c], 1e-14);
        }
      }
}

}  // namespace
}  // namespace bake::grooves
