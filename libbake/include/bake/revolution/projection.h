// Texture projection chosen by measured distortion (seed 001, "Texturing function", Eq. 10-17: the
// paper picks cylindrical or spherical per object by eye; we measure). For each candidate map
// (cylindrical (u, v) = (angle, h), spherical about a centre on the axis optimised for least
// distortion, and arc length along the profile) the Jacobian of the map from the revolved surface to
// texture space gives, per surface area element, the singular values s1 >= s2: angle distortion
// s1/s2, area distortion s1 s2 relative to the surface mean, and the share of area where the map is
// degenerate (s2 ~ 0, e.g. a cylindrical map on a cap). The best scores win.
#pragma once

#include <string>
#include <vector>

#include "bake/revolution/profile.h"

namespace bake::revolution {

enum class Projection { Cylindrical, Spherical, ArcLength };
const char* projectionName(Projection projection);  // the format's names

struct ProjectionScore {
  Projection projection = Projection::Cylindrical;
  double degenerateArea = 0;      // share of surface area with a degenerate map
  double meanAngleDistortion = 1;  // area-weighted mean of s1/s2 (1: conformal)
  double meanAreaDistortion = 1;   // area-weighted mean of max(a, 1/a), a = s1 s2 / mean(s1 s2)
  double score = 0;                // lower is better; combines the three
  double sphereCentreH = 0;        // spherical: the optimised centre on the axis
  double repeatRatio = 1;          // recommended u:v repeat so texels are square on average
};

struct ProjectionChoice {
  Projection chosen = Projection::Cylindrical;
  std::vector<ProjectionScore> scores;  // all three, in enum order
};

ProjectionChoice chooseProjection(const Profile& profile);

// Texture coordinates of a surface point (object space, axis +y) under a projection; `v` of the
// arc-length map comes from the profile's cumulative length (the runtime reads it from a 1D table).
struct ArcLengthTable {
  std::vector<float> hSamples;  // not used for lookups by h alone; see formats/revolution.md
};

}  // namespace bake::revolution
