// Baked self-shadowing of paintstrokes (seed 002, last paragraph): per control point and per light
// direction, the scale of the point's reflectance from its global normal and depth.
#pragma once

#include <vector>

#include "bake/paintstrokes/model.h"

namespace bake::paintstrokes {

// The runtime's default light, (0.4, 0.8, 0.45) normalised: the direction baked when none is given.
Vec3d defaultLightDirection();

// The reflectance scale of one point for light from unit direction `d` (towards the light).
double shadowScale(const StrokePoint& point, const Vec3d& d, double density, double minimum);

// shadows[point * directions.size() + k] for every control point in stroke order.
std::vector<double> bakeShadows(const StrokeSet& set, const std::vector<Vec3d>& directions, double density, double minimum);

}  // namespace bake::paintstrokes
