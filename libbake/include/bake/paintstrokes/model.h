// 3D paintstrokes (seed 002, Neulander & van de Panne, Graphics Interface 1998): a stroke is a list of
// control points; its path and radius are Catmull-Rom splines through them, its colour, opacity and
// reflectance linear between them. Each control point also carries the "global normal" and "depth"
// of the seed's self-shadowing (the normal of the overall shape the point belongs to, and its
// relative depth below that shape's surface, 0 at the surface, 1 deepest). Strokes share styles
// (breadthwise and volume opacity, specular). This is the in-memory model every stage works on:
// input.cpp reads it, grow.cpp makes it from a mesh, validate.cpp checks and repairs it,
// shadow.cpp bakes the self-shadowing, package.cpp packs it (formats/paintstrokes.md).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bake/core/vec.h"

namespace bake::paintstrokes {


struct StrokePoint {
  Vec3d position{0, 0, 0};
  double radius = 0.01;
  Vec3d colour{0.5, 0.5, 0.5};  // linear RGB in [0, 1]
  double opacity = 1;           // [0, 1]
  double reflectance = 1;       // [0, 1], scales the lit colour
  Vec3d globalNormal{0, 0, 0};  // unit, or zero when unknown (no self-shadowing for this point)
  double depth = 0;             // [0, 1]: 0 at the global surface, 1 deepest
};

struct StrokeStyle {
  std::string name = "default";
  double centreOpacity = 1;    // breadthwise opacity at the centreline ...
  double edgeOpacity = 1;      // ... and at the silhouette edges
  double volumeAcross = 1;     // volume opacity factor with the view orthogonal to the path ...
  double volumeAlong = 1;      // ... and along it (seed 002: largest along the path)
  Vec3d specular{0, 0, 0};
  double shininess = 32;
  double ambient = 0.15;
  double edgeSoftness = 1;     // antialiasing ramp at the silhouette, pixels
};

struct Stroke {
  std::vector<StrokePoint> points;
  std::size_t style = 0;
};

struct StrokeSet {
  std::string units;            // informative
  std::vector<StrokeStyle> styles;  // at least one
  std::vector<Stroke> strokes;
};

}  // namespace bake::paintstrokes
