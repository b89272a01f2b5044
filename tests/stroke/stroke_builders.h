// Small builders of control points and straight strokes shared by the paintstroke tests.
#pragma once

#include "bake/stroke/paintstroke.h"

namespace bake::stroke::test {

inline ControlPoint point(double x, double y, double radius = 0.5, double opacity = 1) {
  ControlPoint p;
  p.x = x, p.y = y, p.radius = radius, p.opacity = opacity;
  return p;
}

inline Paintstroke line(double x0, double y0, double x1, double y1, double radius, double opacity = 1) {
  Paintstroke s;
  s.points = {point(x0, y0, radius, opacity), point(x1, y1, radius, opacity)};
  return s;
}

}  // namespace bake::stroke::test
