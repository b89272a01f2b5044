// The intrinsic triangulation the robust heat method works on (Sharp and Crane 2020, "A Laplacian for
// Nonmanifold Triangle Meshes", sections 4-5; Sharp, Soliman and Crane 2019, "Navigating Intrinsic
// Triangulations"). A triangulation is stored as edge lengths over a halfedge complex: faces are
// implicit (halfedges 3f, 3f+1, 3f+2 go round face f), each halfedge knows its tail vertex, its twin
// and its edge. Vertices are the surface's own vertices, so a scalar per vertex means the same thing
// on the surface and on the triangulation. The complex may glue a face to itself or join two faces
// along several edges (a Delta-complex): nothing below assumes a simplicial complex.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "bake/geodesic/surface.h"

namespace bake::geodesic {

struct IntrinsicTriangulation {
  std::vector<std::uint32_t> tail;   // per halfedge: the vertex it leaves
  std::vector<std::uint32_t> twin;   // per halfedge: the halfedge glued to it (opposite direction)
  std::vector<std::uint32_t> edgeOf; // per halfedge
  std::vector<std::uint32_t> edgeHalfedge;  // per edge: one of its two halfedges
  std::vector<double> length;        // per edge

  std::size_t faceCount() const { return tail.size() / 3; }
  std::size_t edgeCount() const { return length.size(); }
  static std::uint32_t next(std::uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static std::uint32_t prev(std::uint32_t h) { return h - h % 3 + (h % 3 + 2) % 3; }
  static std::uint32_t faceOf(std::uint32_t h) { return h / 3; }
  double lengthOf(std::uint32_t h) const { return length[edgeOf[h]]; }
};

struct IntrinsicBuildStats {
  std::size_t nonManifoldEdges = 0;  // edges with three or more faces, glued in a cycle
  bool doubled = false;              // true when the cover holds both sides of every face
  double mollifyEpsilon = 0.0;       // length added to every edge
  std::size_t edgeFlips = 0;
};

// The tufted cover (section 4.2): every face is taken twice, once per side, and around each edge the
// sides are glued pairwise in their cyclic order about the edge, so the cover is a closed manifold
// complex even where the surface has boundary, non-manifold edges or non-manifold vertices. A closed,
// consistently oriented manifold surface needs only one side; then each face is taken once.
IntrinsicTriangulation buildTuftedCover(const Surface& surface, IntrinsicBuildStats& stats);

// Mollification (section 4.5): adds the smallest epsilon to every edge length such that each
// triangle satisfies the strict triangle inequality with margin delta. Returns epsilon.
double mollify(IntrinsicTriangulation& mesh, double delta);

// Flips edges, as long as any is not Delaunay (opposite angles summing to more than pi), until the
// triangulation is intrinsic Delaunay (Fisher et al. 2007; Sharp et al. 2019 section 3). Lengths of
// flipped edges come from laying the two triangles out in the plane. Returns the number of flips.
std::size_t flipToDelaunay(IntrinsicTriangulation& mesh);

// Geometry of one intrinsic triangle from its three edge lengths (lij opposite corner k, etc.).
double triangleArea(double a, double b, double c);
// Cotangent of the angle opposite side a in a triangle with sides a, b, c and the given area.
double cotangentOpposite(double a, double b, double c, double area);

}  // namespace bake::geodesic
