// Shared by the area sampling tests: small scenes, the sampler over every primitive of a scene, and
// the ray-traced reference's mean over one footprint with its noise floor.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bake/core/vec.h"
#include "grooves/groove_support.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/area_surface.h"
#include "grooves/oracle/shade_local.h"
#include "grooves/reference/reference.h"

namespace bake::grooves::area_test {
constexpr double kW = 0.01, kD = 0.005;  // the V-groove's half-width and depth

inline std::string num(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Profiles "v" (V-groove), "box" (vertical walls), "ridge" (a V standing up); materials "ground" (the
// base), "red", "green", "shiny" (with a specular lobe).
inline GrooveScene sceneWith(const std::string& grooves, double domain = 1, bool wrap = false) {
  const std::string w = num(kW), d = num(kD);
  const std::string text = R"({"version": 1, )" + std::string(wrap ? R"("wrap": "repeat", )" : "") +
                           R"("domain": {"size": [)" + num(domain) + ", " + num(domain) + R"(]}, "profiles": {"v": {"points": [[-)" + w + ", 0], [0, -" + d + "], [" + w +
                           R"(, 0]]}, "box": {"points": [[-)" + w + ", 0], [-" + w + ", -" + d + "], [" + w + ", -" +
                           d + "], [" + w + R"(, 0]]}, "ridge": {"points": [[-)" + w + ", 0], [0, " + d + "], [" +
                           w + R"(, 0]]}},
    "materials": {"ground": {"albedo": [0.2, 0.4, 0.6]}, "red": {"albedo": [0.9, 0.1, 0.05]},
                  "green": {"albedo": [0.1, 0.8, 0.2]},
                  "shiny": {"albedo": [0.3, 0.3, 0.3], "specular": [0.6, 0.6, 0.6], "shininess": 12}},
    "base": "ground", "grooves": [)" + grooves + "]}";
  Result<GrooveScene> scene = parseGrooveScene(text, "scene.json");
  EXPECT_TRUE(scene.isOk()) << scene.status().describe();
  return scene.isOk() ? scene.value() : GrooveScene{};
}

inline std::string line(const std::string& profile, const std::string& material, Vec2 a, Vec2 b) {
  return R"({"profile": ")" + profile + R"(", "material": ")" + material + R"(", "path": {"line": [[)" + num(a.u) +
         ", " + num(a.v) + "], [" + num(b.u) + ", " + num(b.v) + "]]}}";
}

inline std::string polyline(const std::string& profile, const std::string& material, const std::vector<Vec2>& points) {
  std::string s = R"({"profile": ")" + profile + R"(", "material": ")" + material + R"(", "path": {"polyline": [)";
  for (std::size_t i = 0; i < points.size(); ++i) s += (i ? ", [" : "[") + num(points[i].u) + ", " + num(points[i].v) + "]";
  return s + "]}}";
}

inline Footprint squareFootprint(Vec2 centre, double side) { return {centre, {side, 0}, {0, side}}; }

// Every primitive of the scene, straightened at the footprint centre (the scenes are small).
inline std::vector<LocalGroove> allGrooves(const GrooveScene& scene, Vec2 centre) {
  std::vector<LocalGroove> out;
  for (std::uint32_t p = 0; p < scene.primitives.size(); ++p) out.push_back(localGroove(scene, p, centre));
  return out;
}

inline Rgb sample(const GrooveScene& scene, const Footprint& f, const Vec3& e, const Lighting& l,
                  AreaSampleStats* stats = nullptr) {
  AreaSampleStats local;
  return areaSampleWithStats(scene, allGrooves(scene, f.centre), f, e, l, stats ? *stats : local);
}

// The reference's footprint mean over `seeds` independent renders of `spp` samples, and 3 times the
// noise floor of one such render (the standard deviation of the renders) per channel: the mean itself
// is sqrt(seeds) times less noisy than that.
struct ReferenceValue {
  Rgb mean{0, 0, 0};
  Rgb tolerance{0, 0, 0};
};
inline ReferenceValue referenceMean(const GrooveScene& scene, const Footprint& f, const Vec3& e, const Lighting& l,
                                    int spp = 256, int seeds = 8) {
  View view;
  view.toViewer = e;
  view.origin = {f.centre.u - 0.5 * f.axis1.u - 0.5 * f.axis2.u, f.centre.v - 0.5 * f.axis1.v - 0.5 * f.axis2.v};
  view.axisX = f.axis1;
  view.axisY = f.axis2;
  view.width = view.height = 1;
  std::vector<Rgb> values;
  for (int s = 0; s < seeds; ++s) {
    ReferenceSettings settings;
    settings.samplesPerPixel = spp;
    settings.seed = 1 + s;
    settings.threads = 1;
    values.push_back(rgbAt(renderReference(scene, view, l, settings), 0, 0));
  }
  ReferenceValue r;
  for (int c = 0; c < 3; ++c) {
    double sum = 0, squares = 0;
    for (const Rgb& v : values) sum += v[c];
    r.mean[c] = sum / seeds;
    for (const Rgb& v : values) squares += (v[c] - r.mean[c]) * (v[c] - r.mean[c]);
    r.tolerance[c] = 3 * std::sqrt(squares / (seeds - 1));
  }
  return r;
}

// Expects agreement within the reference's noise floor (plus a floor for float images and a seed whose
// renders happen to agree closely).
inline void expectNearReference(const Rgb& value, const ReferenceValue& reference, double floor) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(value[c], reference.mean[c], std::max(reference.tolerance[c], floor))
        << "channel " << c << " noise floor " << reference.tolerance[c];
}

inline Vec3 facetNormal(double gu, double gv) {  // of the plane h = gu u + gv v + c
  const double n = std::sqrt(gu * gu + gv * gv + 1);
  return {-gu / n, -gv / n, 1 / n};
}

}  // namespace bake::grooves::area_test
