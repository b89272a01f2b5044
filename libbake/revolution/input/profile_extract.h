// Profiles from inputs that are not vector profiles: a coverage image (its 0.5 iso-contour, for the
// projection choice and the ray-march reference) and a mesh of revolution (its axis found from the
// normals, its profile taken from a half-plane section, and how far it is from a true surface of
// revolution).
#pragma once

#include <array>
#include <string>

#include "bake/core/status.h"
#include "bake/io/mesh.h"
#include "bake/revolution/profile.h"
#include "bake/revolution/shape_map.h"

namespace bake::revolution {

// An image file as a coverage image: luminance (or alpha when the image has one) in [0, 1], row 0
// of the result at the image's bottom (hMin = 0), column 0 at the axis; `texelSize` object units
// per pixel (0: 1 / image height, so the object is one unit tall).
Result<CoverageImage> readCoverageImage(const std::string& path, double texelSize);

// The 0.5 iso-contour of the coverage (marching squares, edge points by linear interpolation),
// as closed contours plus open ones ending on the image's left edge (the axis), in object units.
Profile contourOfCoverage(const CoverageImage& image);

// The axis of a surface of revolution: every normal line of such a surface meets the axis, so the
// normal lines lie in a linear line complex of pitch 0 (Pottmann & Randrup, "Rotational and helical
// surface approximation for reverse engineering", Computing 1998). The complex is the eigenvector of
// the smallest eigenvalue of the 6x6 moment matrix of the normals' Pluecker coordinates.
struct AxisFit {
  std::array<double, 3> point{0, 0, 0};      // on the axis, nearest the vertex centroid
  std::array<double, 3> direction{0, 1, 0};  // unit
  double pitch = 0;                          // of the fitted complex (0 for a true rotation)
};
Result<AxisFit> fitRevolutionAxis(const TriangleMesh& mesh, const std::string& name);

struct MeshProfile {
  Profile profile;
  AxisFit axis;
  double maxDeviation = 0;   // largest |distance| of a vertex's (r, h) to the section profile
  double rmsDeviation = 0;
  double objectSize = 0;     // bounding-box diagonal, for relative figures
  std::size_t vertices = 0;
};
// Fits the axis, cuts the mesh with the half-plane through it, chains the cut into contours and
// measures every vertex against them.
Result<MeshProfile> profileOfMesh(const TriangleMesh& mesh, const std::string& name);

}  // namespace bake::revolution
