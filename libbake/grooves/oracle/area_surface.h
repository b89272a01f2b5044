// Internal to the area sampling of seed 000 §6 (area_sampling.cpp, area_surface.cpp, area_walls.cpp):
// the local surface under a footprint as planar convex pieces. The grooves under the footprint are
// straightened (shade_local.h), so the height field H = min(cuts) + max(ridges) of
// formats/groove-scene.md is piecewise planar: one piece per region where one facet (or one cut facet
// plus one ridge facet) decides H, plus vertical walls where H jumps (open-end cuts, vertical profile
// segments). Coordinates are relative to the footprint centre.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "grooves/oracle/polygon.h"
#include "grooves/oracle/render.h"
#include "grooves/oracle/shade_local.h"

namespace bake::grooves {

// A primitive straightened at the footprint, in coordinates relative to the footprint centre.
struct StraightGroove {
  std::size_t order = 0;      // position in the list: the earlier one wins material ties
  std::uint32_t primitive = 0;
  std::size_t material = 0;
  Vec2 foot, tangent, binormal;
  std::vector<Vec2> profile;  // (b, h) with b measured from the foot along the binormal; split where h
                              // changes sign, so every facet is a cut (h <= 0) or a ridge (h >= 0)
  HalfPlane joint[2];         // the region's side of the start and end joint lines
  Vec2 jointPoint[2];
  bool openEnd[2] = {false, false};

  double across(Vec2 x) const { return binormal.u * (x.u - foot.u) + binormal.v * (x.v - foot.v); }
  // The strip b in [b0, b1] as two half-planes.
  HalfPlane atLeast(double b) const;
  HalfPlane atMost(double b) const;
};

// `grooves` as seen from the footprint centre `centre` (for a wrapping scene each primitive is moved by
// the domain period that brings it nearest).
std::vector<StraightGroove> straighten(const GrooveScene& scene, const std::vector<LocalGroove>& grooves,
                                       Vec2 centre);
// The same into `out`, reusing its storage (no allocation once it has grown).
void straighten(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, Vec2 centre,
                std::vector<StraightGroove>& out);

// A plane h = h0 + gu u + gv v over the base plane.
struct HeightPlane {
  double h0 = 0, gu = 0, gv = 0;
  double at(Vec2 x) const { return h0 + gu * x.u + gv * x.v; }
};

// One planar convex piece of the surface, in 3D: a facet piece (normal up) or a wall (horizontal normal).
struct SurfacePiece {
  // Only the first `count` vertices are set and copied (pieces are made per footprint, mostly with far
  // fewer vertices than the cap), as in ConvexPolygon.
  union {
    std::array<Vec3, kPolygonMaxVertices> vertex;
  };
  int count = 0;
  Vec3 normal;             // unit, pointing out of the solid
  double planeOffset = 0;  // normal . p on the piece
  std::size_t material = 0;
  bool wall = false;

  SurfacePiece() {}
  SurfacePiece(const SurfacePiece& o) { *this = o; }
  SurfacePiece& operator=(const SurfacePiece& o) {
    count = o.count;
    for (int i = 0; i < o.count; ++i) vertex[i] = o.vertex[i];
    normal = o.normal;
    planeOffset = o.planeOffset;
    material = o.material;
    wall = o.wall;
    return *this;
  }
};

// Caps (a shader would hold the same in fixed arrays): pieces of H and walls kept per footprint.
constexpr std::size_t kMaxSurfacePieces = 512;
constexpr std::size_t kMaxWalls = 128;

struct SurfaceBuildStats {
  std::uint32_t cells = 0, walls = 0;
  std::uint32_t overflows = 0;  // pieces or walls dropped for lack of room
  bool truncated = false;       // some polygon lost a vertex for lack of room
};

// The pieces of H over `region` (area_surface.cpp): the base plane's pieces, cut facets, ridge
// facets and their sums; pieces of area <= minArea are left out. With `stopAtCap` the build stops at
// the first overflow (the caller will split the footprint), else it keeps what fits.
void buildHeightPieces(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial,
                       const ConvexPolygon& region, double minArea, bool stopAtCap, std::vector<SurfacePiece>& out,
                       SurfaceBuildStats& stats);

// The vertical walls where H jumps inside `region` (area_walls.cpp): at open-end cuts and vertical
// profile segments, between the limits of H on both sides of the line.
void buildWalls(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, const ConvexPolygon& region,
                double lengthScale, bool stopAtCap, std::vector<SurfacePiece>& out, SurfaceBuildStats& stats);

// H and its material at x, the limit from the side `side` (a direction on the base plane) when x lies
// on a line where H jumps (area_walls.cpp; also used by the point sample and the tests).
struct SurfacePoint {
  double height = 0;
  std::size_t material = 0;
};
SurfacePoint surfaceLimit(const std::vector<StraightGroove>& grooves, std::size_t baseMaterial, Vec2 x, Vec2 side,
                          double tolerance);

}  // namespace bake::grooves

namespace bake::grooves {

// What one area sample did (for tests and benchmarks).
struct AreaSampleStats {
  SurfaceBuildStats surface;
  std::uint32_t visiblePieces = 0;  // pieces with a visible part in the footprint
  std::uint32_t fragmentOverflows = 0;  // subtractions that scaled a fragment's weight for lack of room
  std::uint32_t splits = 0;  // footprints split in four because their pieces overflowed the caps
  std::uint32_t incomplete = 0;  // (sub-)footprints sampled with pieces dropped: the value is approximate
  bool pointSample = false;
};

// areaSample (shade_local.h) with its statistics.
Rgb areaSampleWithStats(const GrooveScene& scene, const std::vector<LocalGroove>& grooves, const Footprint& footprint,
                        const Vec3& toViewer, const Lighting& lighting, AreaSampleStats& stats,
                        bool traceReflections = true);

}  // namespace bake::grooves
