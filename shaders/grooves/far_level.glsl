// The far level (libbake/grooves/bake/far_level.h; the CPU's far_shade.cpp): a footprint over more
// primitives than MAX_FOUND is shaded from the package's per-class band areas instead of dropping the
// grooves past the cap. The pixel is the flat base plus, per class, the share of the footprint's
// bounding box its bands cover (a summed-area table, read in double) times the difference between
// the class's groove shaded alone across its band and the flat base. line_sampling.glsl runs the
// classes through its one shadeClass call (gFarMode). Also the per-frame counts bakeplay reports.
#ifndef BAKE_GROOVES_FAR_LEVEL_GLSL
#define BAKE_GROOVES_FAR_LEVEL_GLSL

#include "lookup.glsl"

// render/grooves.cpp statistics(): fragments shaded from the far level, fragments over more than
// MAX_FOUND primitives in a package without a far level (the rest dropped), fragments with more
// classes of grooves than MAX_CLASSES (the rest dropped). No effect in helper invocations.
layout(std430, binding = 14) buffer FrameCounts { uint frameCounts[]; };
const int kCountFar = 0, kCountTruncated = 1, kCountClassesDropped = 2;
void countFragment(int which) { atomicAdd(frameCounts[which], 1u); }

bool hasFarLevel() { return uFarCells.z > 0; }
int farClassCount() { return uFarCells.z; }

// The footprint's bounding box (domain coordinates) and its area, set by setFarBox.
dvec2 gFarLower, gFarUpper;
double gFarArea;

// Without wrap, the box's part over the domain (far_shade.cpp says why).
void setFarBox(vec2 centre, vec2 axis1, vec2 axis2) {
  dvec2 extent = 0.5lf * (abs(dvec2(axis1)) + abs(dvec2(axis2)));
  gFarLower = dvec2(centre) - extent;
  gFarUpper = dvec2(centre) + extent;
  if (!wrapRepeat()) {
    gFarLower = max(gFarLower, dvec2(0.0lf));
    gFarUpper = min(gFarUpper, dvec2(domainSize()));
  }
  dvec2 size = gFarUpper - gFarLower;
  gFarArea = size.x > 0.0lf && size.y > 0.0lf ? size.x * size.y : 0.0lf;
}

// Class c's table at a point in far cells inside [0, columns] x [0, rows], bilinear within the cell.
double farInside(int c, dvec2 x) {
  int columns = uFarCells.x, rows = uFarCells.y;
  int i = clamp(int(floor(x.x)), 0, columns - 1), j = clamp(int(floor(x.y)), 0, rows - 1);
  double s = x.x - double(i), t = x.y - double(j);
  int at = c * (columns + 1) * (rows + 1) + j * (columns + 1) + i;
  int above = at + columns + 1;
  return (1.0lf - s) * (1.0lf - t) * farTable[at] + s * (1.0lf - t) * farTable[at + 1] +
         (1.0lf - s) * t * farTable[above] + s * t * farTable[above + 1];
}

// The band area of class c below and left of a domain point; a repeating pattern adds whole periods.
double farSummed(int c, dvec2 point) {
  dvec2 size = dvec2(uFarCells.xy);
  dvec2 x = point * size / dvec2(domainSize());
  if (!wrapRepeat()) return farInside(c, clamp(x, dvec2(0.0lf), size));
  dvec2 q = floor(x / size);
  x -= q * size;
  return q.x * q.y * farInside(c, size) + q.x * farInside(c, dvec2(size.x, x.y)) + q.y * farInside(c, dvec2(x.x, size.y)) +
         farInside(c, x);
}

// The share of the footprint's box covered by class c's bands.
float farCover(int c) {
  if (!(gFarArea > 0.0lf)) return 0.0;
  double band = farSummed(c, gFarUpper) - farSummed(c, dvec2(gFarLower.x, gFarUpper.y)) -
                farSummed(c, dvec2(gFarUpper.x, gFarLower.y)) + farSummed(c, gFarLower);
  return float(band / gFarArea);
}

// Class c's groove, straight through F, as gGrooves[0] (the only one), and a footprint exactly across
// its band (a uniform density over [-wmax, wmax] on its section).
void prepareFarGroove(int c, out vec2 axis1, out vec2 axis2) {
  FarClass farClass = farClasses[c];
  GrooveProfile profile = profiles[farClass.info.x];
  LocalGroove g;
  g.primitive = farClass.info.z;
  g.groove = int(primitives[farClass.info.z].header.z);
  g.profileFirst = int(profile.points.x);
  g.profileCount = int(profile.points.y);
  g.material = int(farClass.info.y);
  g.foot = vec2(0.0);
  g.tangent = farClass.direction.xy;
  g.binormal = vec2(-g.tangent.y, g.tangent.x);
  g.offset = 0.0;
  g.scale = 1.0;
  g.offsetRate = 0.0;
  g.scaleRate = 0.0;
  g.offsetAccel = 0.0;
  g.scaleAccel = 0.0;
  g.startPoint = vec2(0.0);
  g.endPoint = vec2(0.0);
  g.startNormal = g.tangent;
  g.endNormal = -g.tangent;
  g.width = profile.bounds.x;
  g.arcCentre = vec2(0.0);
  g.arcRadius = 0.0;
  gGrooves[0] = g;
  gGrooveCount = 1;
  float width = 2.0 * farClass.direction.z;
  axis1 = g.binormal * width;
  axis2 = g.tangent * width;
}

#endif
