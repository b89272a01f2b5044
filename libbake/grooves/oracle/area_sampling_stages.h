// Internal to the area sampling of seed 000 §6 and §7 (area_sampling.cpp, area_reflections.cpp): how
// the sampler sees the local surface's pieces (projected onto a screen along the view and onto a plane
// across the light), the visibility and shadow stages both files run, and the beams of mirror pieces
// whose reflections area_reflections.cpp traces.
#pragma once

#include <array>
#include <vector>

#include "grooves/oracle/area_surface.h"
#include "grooves/oracle/polygon.h"
#include "grooves/oracle/render.h"

namespace bake::grooves::area_stages {

inline double dot(const Vec3& a, const Vec3& b) { return a.u * b.u + a.v * b.v + a.w * b.w; }

// A piece as the sampler sees it: its projection along the view onto the base plane ("screen") and
// along the light onto a plane perpendicular to L.
struct Projected {
  const SurfacePiece* piece = nullptr;
  double facingViewer = 0;  // N . E
  double facingLight = 0;   // N . L
  ConvexPolygon screen;
  Box2 screenBox;
  ConvexPolygon lightView;  // point samples only
  Box2 lightBox;
};

struct Frame {
  Vec3 toViewer, toLight;
  Vec3 lightAxis1, lightAxis2;  // orthonormal, perpendicular to L
  // The screen the view lines are projected onto: the base plane for the eye's view (the footprint
  // lives there), the plane through the origin perpendicular to the view for a reflected beam (whose
  // direction may be horizontal or point down).
  bool baseScreen = true;
  Vec3 screenAxis1{1, 0, 0}, screenAxis2{0, 1, 0};  // orthonormal, perpendicular to toViewer
  double minArea = 0, depthTolerance = 0;
  bool lightAllOccluders = false;  // light near or below the horizon: back faces occlude too
};

// The half-planes of a piece's screen image: they clip the footprint and every overlap with it.
struct ScreenEdges {
  std::array<HalfPlane, kPolygonMaxVertices> edge;
  int count = 0;
};

// What every (sub-)footprint of one sample shares.
struct Job {
  const GrooveScene& scene;
  const std::vector<StraightGroove>& grooves;
  const Lighting& lighting;
  bool traceReflections = true;
  Frame frame;
  double height = 0, depth = 0, lengthScale = 0;  // the grooves' extent above and below the base plane
};

Vec2 toScreen(const Frame& f, const Vec3& p);
void perpendicularAxes(const Vec3& d, Vec3& a, Vec3& b);
// `withLightView`: the point sample tests containment in the light's view; area samples need only its
// box.
Projected project(const Frame& f, const SurfacePiece& piece, bool withLightView);
// The point of piece p seen at screen point x.
Vec3 seenPoint(const Frame& f, const Projected& p, Vec2 x);
// The visible part of piece all[i] inside the footprint: its projection minus the pieces in front.
void visiblePart(const Frame& f, const std::vector<Projected>& all, std::size_t i, const ConvexPolygon& footprint,
                 const ScreenEdges& meEdges, FragmentSet& visible);
// The lit part of `part` (visible fragments of piece me), shadowed by the pieces `casters` but `self`
// (the piece me was cut from, or me).
void litPart(const Frame& f, const Projected& me, const std::vector<Projected>& casters, const SurfacePiece* self,
             const ScreenEdges& meEdges, FragmentSet& part);
bool isBlack(const Rgb& c);
// The horizontal shift per unit of height along d (d / d_w, bounded like the query box's reach).
Vec2 shiftPerHeight(const Vec3& d);
// The box `start`, grown by e, swept by h a for h in aRange, then by k b for k in bRange: the
// rectangle around it.
ConvexPolygon sweptBox(const Box2& start, double e, Vec2 a, const double (&aRange)[2], Vec2 b,
                       const double (&bRange)[2]);
// The pieces of the surface over `region`; false when a cap was reached.
bool buildPiecesOver(const Job& job, const ConvexPolygon& region, double minArea, bool stopAtCap,
                     std::vector<SurfacePiece>& pieces, AreaSampleStats& stats);

// --- Inter-reflections (seed 000 §7) in area-sampled footprints ------------------------------------
// A beam is the visible part of a mirror piece (convex fragments on its plane, with their weights)
// and the share of the footprint it covers. Its rays leave along R, the view mirrored about the piece's
// normal, so the beam is sampled as a footprint of its own: the view becomes -R, the screen the plane
// perpendicular to R, the footprint the beam's fragments projected onto it. The pieces it can reach lie
// in front of the mirror's plane (those are cut to that half-space) within the region its rays cross
// over the grooves' height range; what each piece facing -R shows of the beam is found as for the eye
// (visiblePart), lit as for the eye (litPart, against every piece, cut or not). A piece caught adds
// weight x (lit share) x its direct radiance seen from -R, and, while bounces remain, a mirror piece's
// caught part becomes a beam in turn. Rays no piece catches leave the surface when R points up and see
// the environment (1 - Σ r_i of the beam). Affine maps between planes keep area ratios, so a share of
// the beam's projected area is the same share of its part of the footprint. Beams live on a stack of
// kMaxBeams entries and at most 4 kMaxBeams are followed per mirror piece seen by the eye, as in the
// line-sampled sections (interreflection.cpp); a beam carrying less than 1e-12 of the pixel is dropped.

struct Polygon3 {
  std::array<Vec3, kPolygonMaxVertices> vertex;
  int count = 0;
  double weight = 1;
};

struct AreaBeam {
  std::vector<Polygon3> fragments;  // on the mirror's plane
  Vec3 normal;                      // the mirror's
  std::size_t material = 0;
  Vec3 toViewer;                    // what looks at the mirror: E, then back along the previous ray
  Rgb weight{1, 1, 1};              // product of the mirror reflectances already applied
  double share = 0;                 // of the footprint
  int bounce = 0;                   // reflections made before this one
};

// The fragments of `set` (on the screen of frame f) lifted onto piece p's plane, each weight scaled.
void liftFragments(const Frame& f, const Projected& p, const FragmentSet& set, double scale,
                   std::vector<Polygon3>& out);

// What the reflection of a mirror piece seen by the eye adds: its beam and every beam it leads to.
Rgb traceReflections(const Job& job, AreaBeam first, AreaSampleStats& stats);

}  // namespace bake::grooves::area_stages
