// Helpers shared by the groove tests: a grid that must build, a light towards a direction, a
// scene's material by name.
#pragma once

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"

namespace bake::grooves {

inline GrooveGrid buildGridOk(const GrooveScene& scene, GridSettings settings = {}) {
  Result<GrooveGrid> grid = buildGrooveGrid(scene, settings);
  EXPECT_TRUE(grid.isOk()) << grid.status().describe();
  return grid.isOk() ? grid.value() : GrooveGrid{};
}

// A unit light direction towards d, following `bounces` mirror reflections.
inline Lighting lightTowards(Vec3 d, int bounces = 0) {
  const double n = std::sqrt(d.u * d.u + d.v * d.v + d.w * d.w);
  Lighting l;
  l.toLight = {d.u / n, d.v / n, d.w / n};
  l.maxBounces = bounces;
  return l;
}

inline const Material& materialNamed(const GrooveScene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return scene.materials.front();
}

}  // namespace bake::grooves
