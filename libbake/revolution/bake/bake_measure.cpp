// The measuring stages of revolbake. Thin features: from points along the profile, rays along the
// inward and outward normal find the opposite surface by stepping with the exact distance; the
// shortest chord is the thinnest flange or gap, and below a texel the shape map cannot hold it (the
// bake warns with the figure in texels). Encoding: the stored distance is decoded back and compared
// with the field at every texel centre, and the safety margin the shader must subtract is measured
// (bilinear overestimate + quantisation). March: the CPU march, identical to the shader, against the
// analytic intersection for every iteration budget; the smallest budget within --target-error of
// silhouette mismatch is recorded.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bake_formats/revolution.h"
#include "revolution/bake/bake_stages.h"
#include "revolution/input/profile_geometry.h"
#include "revolution/reference/exact_reference.h"

namespace bake::revolution {
namespace {

using nlohmann::json;

// Distance along `direction` from `start` (just past the surface) to the next sign change of the
// signed distance, or -1 when none is found within `limit`.
double chordLength(const Profile& profile, Point2 start, Point2 direction, double startSign, double limit, double step0) {
  double t = step0;
  while (t < limit) {
    const Point2 p{start.r + t * direction.r, start.h + t * direction.h};
    const double d = signedDistance(profile, p).distance;
    if (d * startSign <= 0) return t;
    t += std::max(std::abs(d), 0.25 * step0);
  }
  return -1;
}

struct ThinFeatures {
  double flange = -1, gap = -1;  // object units; -1: none found
};

ThinFeatures thinnestFeatures(const Profile& profile, double texel, double extent) {
  ThinFeatures thin;
  const int samplesPerContour = 256;
  const double offset = 1e-4 * texel;
  for (const Contour& contour : profile.contours) {
    double length = 0;
    for (const Segment& s : contour.segments) length += s.onAxis ? 0 : std::hypot(s.b.r - s.a.r, s.b.h - s.a.h);
    if (length <= 0) continue;
    for (const Segment& s : contour.segments) {
      if (s.onAxis) continue;
      const double chord = std::hypot(s.b.r - s.a.r, s.b.h - s.a.h);
      const int n = std::max(1, int(std::ceil(samplesPerContour * chord / length)));
      for (int k = 0; k < n; ++k) {
        const Point2 p = pointAt(s, (k + 0.5) / n);
        const Point2 tangent = tangentAt(s, (k + 0.5) / n);
        // Which side of the piece is inside follows from the field, not from the contour's orientation.
        Point2 normal{tangent.h, -tangent.r};
        const Point2 probe{p.r + 4 * offset * normal.r, p.h + 4 * offset * normal.h};
        if (signedDistance(profile, probe).distance < 0) normal = {-normal.r, -normal.h};  // now outward
        const Point2 inStart{p.r - offset * normal.r, p.h - offset * normal.h};
        const Point2 outStart{p.r + offset * normal.r, p.h + offset * normal.h};
        const double flange = chordLength(profile, inStart, {-normal.r, -normal.h}, -1, extent, 0.01 * texel);
        const double gap = chordLength(profile, outStart, normal, +1, extent, 0.01 * texel);
        if (flange > 0 && (thin.flange < 0 || flange < thin.flange)) thin.flange = flange;
        if (gap > 0 && (thin.gap < 0 || gap < thin.gap)) thin.gap = gap;
      }
    }
  }
  return thin;
}

}  // namespace

void warnAboutThinFeatures(const BakeState& state, Diagnostics& diagnostics) {
  const double texel = state.field.grid.texelSize;
  const double extent = texel * std::max(state.field.grid.width, state.field.grid.height);
  const ThinFeatures thin = thinnestFeatures(state.profile, texel, extent);
  auto warn = [&](const char* kind, double size) {
    if (size < 0 || size >= texel) return;
    char text[200];
    std::snprintf(text, sizeof text, "the thinnest %s is %.3g texels wide; the shape map cannot resolve it (raise --resolution)",
                  kind, size / texel);
    diagnostics.warning(std::string("thin-") + kind, text);
  };
  warn("flange", thin.flange);
  warn("gap", thin.gap);
}

void encodeAndMeasure(const Settings& settings, BakeState& state, Report& report, Diagnostics& diagnostics) {
  state.encoded = encodeShapeMap(state.field, settings.encoding);
  const ShapeField decoded = decodeShapeMap(state.encoded, state.field.grid);
  state.margin = measureSafetyMargin(decoded, &state.profile);
  const double texel = state.field.grid.texelSize;
  state.hitEpsilon = format::revolution::kHitEpsilonTexels * texel;

  // What the package stores, decoded, against the independent exact reference (sign and distance at
  // every texel centre; reference/exact_reference.h shares no code with the map's filling), and
  // against the field before encoding.
  const ShapeGrid& grid = state.field.grid;
  double maxStored = 0;
  for (std::size_t k = 0; k < decoded.distance.size(); ++k)
    maxStored = std::max(maxStored, double(std::abs(decoded.distance[k] - state.field.distance[k])));
  state.storedErrorTexels = maxStored / texel;
  const reference::FieldCheck check = reference::checkField(state.profile, grid, decoded.distance, settings.common.threads);
  const std::string source = state.exactReference ? "the vector profile" : "the 0.5 iso-contour of the coverage image";
  report.addAccuracy("stored shape map signed distance at every texel centre (texels)",
                     "exact signed distance to " + source +
                         " (even-odd rule by exact predicates: CGAL orientation, rational circle test)",
                     {{"texels", check.texels},
                      {"signErrors", check.signErrors},
                      {"mean", check.meanError},
                      {"max", check.maxError},
                      {"worstTexelColumn", check.worstI},
                      {"worstTexelRow", check.worstJ},
                      {"nearSurfaceTexels", check.nearTexels},
                      {"nearSurfaceMean", check.nearMeanError},
                      {"nearSurfaceMax", check.nearMaxError},
                      {"encodingMaxError", state.storedErrorTexels}});
  report.setStatistic("safetyMargin", {{"bilinear", state.margin.bilinearOverestimate},
                                       {"quantisation", state.margin.quantisation},
                                       {"total", state.margin.total()},
                                       {"totalTexels", state.margin.total() / texel}});
  if (check.signErrors > 0) {
    diagnostics.warning("self-check", std::to_string(check.signErrors) +
                                          " texels of the shape map have the wrong sign against the exact reference (worst at texel " +
                                          std::to_string(check.worstI) + ", " + std::to_string(check.worstJ) + ")");
  }
}

void measureMarch(const Settings& settings, BakeState& state, Report& report, Diagnostics& diagnostics) {
  state.bands = buildProxyBands(state.field, settings.proxyBands, state.margin.total());
  // A band over rows without solid bounds nothing; the package (and so the shader) leaves it out,
  // and the march measured here uses exactly the package's bands.
  std::erase_if(state.bands, [](const ProxyBand& band) { return !(band.rMax > 0); });
  MarchSettings march;
  march.safetyMargin = state.margin.total();
  march.overRelaxation = settings.overRelaxation;
  march.hitEpsilon = state.hitEpsilon;
  march.useProxy = true;
  MarchErrorSettings sweep;
  sweep.threads = settings.common.threads;
  state.marchCurve = measureMarchError(state.profile, state.encoded, state.field.grid, state.bands, march, sweep);
  state.iterations = iterationsForTarget(state.marchCurve, settings.targetError);

  json curve = json::array();
  const MarchErrorPoint* chosen = nullptr;
  for (const MarchErrorPoint& point : state.marchCurve) {
    curve.push_back({{"iterations", point.iterations},
                     {"silhouetteMismatch", point.silhouetteMismatch},
                     {"meanHitError", point.meanHitError},
                     {"maxHitError", point.maxHitError},
                     {"meanFetches", point.meanFetches}});
    if (point.iterations == state.iterations) chosen = &point;
  }
  const std::string reference = state.exactReference
                                    ? "analytic ray / revolved-profile intersection (cones, cylinders, tori)"
                                    : "ray / revolved 0.5 iso-contour of the image";
  json metrics = {{"rays", sweep.raysPerView * sweep.views}, {"targetError", settings.targetError},
                  {"iterations", state.iterations}};
  if (chosen) {
    metrics["silhouetteMismatch"] = chosen->silhouetteMismatch;
    metrics["meanHitError"] = chosen->meanHitError;
    metrics["maxHitError"] = chosen->maxHitError;
  }
  report.addAccuracy("ray-march silhouette mismatch at the recorded iteration budget", reference, metrics);
  report.setStatistic("marchErrorCurve", curve);
  if (chosen && chosen->silhouetteMismatch > settings.targetError) {
    diagnostics.warning("target-error", "no iteration budget up to " + std::to_string(state.iterations) +
                                            " reaches the target silhouette error; the largest is recorded");
  }
  if (chosen && !diagnostics.quiet()) {
    std::fprintf(stderr, "revolbake: %d iterations: silhouette mismatch %.3g %% (target %.3g %%), mean hit error %.3g texels\n",
                 state.iterations, 100 * chosen->silhouetteMismatch, 100 * settings.targetError,
                 chosen->meanHitError / state.field.grid.texelSize);
  }
}

}  // namespace bake::revolution
