// Scene checks (formats/groove-scene.md "Validation"): profile geometry and its bounds (seed 000
// §4.1: wmax, hmax, dmax), perturbation bounds, groove ends and closure, and the merging of
// duplicate grooves (same profile, material, perturbation and chain, possibly reversed when the
// profile is symmetric), which would otherwise be found twice in every cell they cross.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "grooves/input/scene.h"
#include "bake/core/vector_text.h"

namespace bake::grooves {
namespace {

bool near(Vec2 a, Vec2 b, double eps) { return std::abs(a.u - b.u) <= eps && std::abs(a.v - b.v) <= eps; }

bool samePrimitive(const Primitive& p, const Primitive& q, bool reversed, double eps) {
  if (p.kind != q.kind) return false;
  if (!reversed) {
    if (!near(p.a, q.a, eps) || !near(p.b, q.b, eps)) return false;
    if (p.kind == Primitive::Kind::Arc)
      return near(p.centre, q.centre, eps) && std::abs(p.radius - q.radius) <= eps && std::abs(p.sweep - q.sweep) <= eps;
    return true;
  }
  if (!near(p.a, q.b, eps) || !near(p.b, q.a, eps)) return false;
  if (p.kind == Primitive::Kind::Arc)
    return near(p.centre, q.centre, eps) && std::abs(p.radius - q.radius) <= eps && std::abs(p.sweep + q.sweep) <= eps;
  return true;
}

std::string grooveLabel(const GrooveScene& scene, std::size_t g) {
  std::string label = "groove " + std::to_string(g);
  if (!scene.grooves[g].name.empty()) label += " (\"" + scene.grooves[g].name + "\")";
  return label;
}

}  // namespace

Status validateProfile(Profile& profile, const std::string& source) {
  const std::string where = "profile \"" + profile.name + "\"";
  auto fail = [&](std::size_t segment, const std::string& message) {
    return invalidInput(where + ", segment " + std::to_string(segment) + ": " + message, {source, "/profiles/" + profile.name});
  };
  const auto& pts = profile.points;
  if (pts.size() < 3) return invalidInput(where + ": needs at least 3 points (2 segments)", {source, "/profiles/" + profile.name});
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!std::isfinite(pts[i].u) || !std::isfinite(pts[i].v)) return fail(i == 0 ? 0 : i - 1, "point " + std::to_string(i) + " is not finite");
  if (pts.front().v != 0) return fail(0, "the first point must be on the surface (h = 0), h is " + numberText(pts.front().v, 9));
  if (pts.back().v != 0) return fail(pts.size() - 2, "the last point must be on the surface (h = 0), h is " + numberText(pts.back().v, 9));
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 a = pts[i], b = pts[i + 1];
    if (b.u < a.u)
      return fail(i, "b decreases from " + numberText(a.u, 9) + " to " + numberText(b.u, 9) + " (an undercut: the surface would not be a height field)");
    if (a.u == b.u && a.v == b.v) return fail(i, "coincident consecutive points (self-intersection)");
    // Two vertical walls in opposite directions at the same b overlap each other.
    if (i + 2 < pts.size() && a.u == b.u && b.u == pts[i + 2].u && (b.v - a.v) * (pts[i + 2].v - b.v) < 0)
      return fail(i + 1, "folds back onto segment " + std::to_string(i) + " (self-intersection)");
  }
  profile.wmax = profile.hmax = profile.dmax = 0;
  for (const Vec2& p : pts) {
    profile.wmax = std::max(profile.wmax, std::abs(p.u));
    profile.hmax = std::max(profile.hmax, p.v);
    profile.dmax = std::max(profile.dmax, -p.v);
  }
  if (!(profile.wmax > 0)) return invalidInput(where + ": zero width", {source, "/profiles/" + profile.name});
  profile.symmetric = true;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 m = pts[pts.size() - 1 - i];
    if (std::abs(pts[i].u + m.u) > 1e-12 || std::abs(pts[i].v - m.v) > 1e-12) profile.symmetric = false;
  }
  return Status::ok();
}

void grooveBounds(const Profile& profile, const Perturbation& perturbation, double& wmax, double& hmax, double& dmax) {
  wmax = profile.wmax;
  hmax = profile.hmax;
  dmax = profile.dmax;
  if (perturbation.kind == Perturbation::Kind::Scale) {
    // b and h scaled by 1 + a sin(...), at most 1 + a.
    wmax *= 1 + perturbation.amplitude;
    hmax *= 1 + perturbation.amplitude;
    dmax *= 1 + perturbation.amplitude;
  } else if (perturbation.kind == Perturbation::Kind::Offset) {
    wmax += perturbation.amplitude;  // shifted across by at most a
  }
}

Status finishScene(GrooveScene& scene) {
  const double closeEps = 1e-9 * std::max(scene.domain[0], scene.domain[1]);
  // Ends and closure.
  for (std::size_t g = 0; g < scene.grooves.size(); ++g) {
    Groove& groove = scene.grooves[g];
    if (groove.primitiveCount == 0) return invalidInput(grooveLabel(scene, g) + ": empty path", {scene.source, ""});
    Primitive& first = scene.primitives[groove.firstPrimitive];
    Primitive& last = scene.primitives[groove.firstPrimitive + groove.primitiveCount - 1];
    groove.closed = near(first.a, last.b, closeEps);
    if (groove.closed) {
      const Vec2 t0 = last.tangentAt(1), t1 = first.tangentAt(0);
      first.cornerAtStart = std::abs(std::atan2(t0.u * t1.v - t0.v * t1.u, t0.u * t1.u + t0.v * t1.v)) > 1e-6;
    } else {
      first.endAtStart = true;
      last.endAtEnd = true;
    }
  }
  // Duplicates (seed 000 §4: one groove per reference in the grid).
  // Candidates are found by the smaller u of the chain's two end points, which a duplicate (forward or
  // reversed) matches within the same 1e-9: a sorted window instead of all pairs.
  const std::size_t count = scene.grooves.size();
  std::vector<double> key(count);
  for (std::size_t g = 0; g < count; ++g) {
    const Groove& groove = scene.grooves[g];
    key[g] = std::min(scene.primitives[groove.firstPrimitive].a.u,
                      scene.primitives[groove.firstPrimitive + groove.primitiveCount - 1].b.u);
  }
  std::vector<std::size_t> order(count);
  for (std::size_t g = 0; g < count; ++g) order[g] = g;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
  std::vector<bool> drop(count, false);
  for (std::size_t j = 0; j < count; ++j) {
    const Groove& gj = scene.grooves[j];
    auto lo = std::lower_bound(order.begin(), order.end(), key[j] - 1e-9, [&](std::size_t g, double k) { return key[g] < k; });
    for (auto it = lo; it != order.end() && key[*it] <= key[j] + 1e-9 && !drop[j]; ++it) {
      const std::size_t i = *it;
      if (i >= j || drop[i]) continue;
      const Groove& gi = scene.grooves[i];
      if (gi.profile != gj.profile || gi.material != gj.material || !(gi.perturbation == gj.perturbation) ||
          gi.primitiveCount != gj.primitiveCount)
        continue;
      const std::size_t n = gi.primitiveCount;
      bool same = true;
      for (std::size_t k = 0; k < n && same; ++k)
        same = samePrimitive(scene.primitives[gi.firstPrimitive + k], scene.primitives[gj.firstPrimitive + k], false, 1e-9);
      bool reversed = false;
      if (!same && scene.profiles[gi.profile].symmetric && gi.perturbation.kind == Perturbation::Kind::None) {
        reversed = true;
        for (std::size_t k = 0; k < n && reversed; ++k)
          reversed = samePrimitive(scene.primitives[gi.firstPrimitive + k], scene.primitives[gj.firstPrimitive + n - 1 - k], true, 1e-9);
      }
      if (same || reversed) {
        drop[j] = true;
        scene.warnings.push_back(grooveLabel(scene, j) + " duplicates " + grooveLabel(scene, i) +
                                 (reversed ? " (reversed)" : "") + ": merged into it");
      }
    }
  }
  std::vector<Groove> grooves;
  std::vector<Primitive> primitives;
  for (std::size_t g = 0; g < scene.grooves.size(); ++g) {
    if (drop[g]) continue;
    Groove groove = scene.grooves[g];
    const std::size_t first = primitives.size();
    for (std::size_t k = 0; k < groove.primitiveCount; ++k) {
      Primitive p = scene.primitives[groove.firstPrimitive + k];
      p.groove = grooves.size();
      primitives.push_back(p);
    }
    groove.firstPrimitive = first;
    grooves.push_back(groove);
  }
  scene.grooves = std::move(grooves);
  scene.primitives = std::move(primitives);
  scene.wmax = scene.hmax = scene.dmax = 0;
  for (const Groove& g : scene.grooves) {
    scene.wmax = std::max(scene.wmax, g.wmax);
    scene.hmax = std::max(scene.hmax, g.hmax);
    scene.dmax = std::max(scene.dmax, g.dmax);
  }
  return Status::ok();
}

}  // namespace bake::grooves
