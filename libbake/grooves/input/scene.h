// The groove scene (formats/groove-scene.md): profiles, materials, and grooves whose paths are
// flattened into a chain of primitives (segments and exact circular arcs), after seed 000 §3-§4.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "io/planar_path.h"

namespace bake::grooves {

using Vec2 = planar::Vec2;

// A polyline cross-section: points [b, h] from the right edge (b < 0) to the left edge (b > 0).
struct Profile {
  std::string name;
  std::vector<Vec2> points;  // u = b (across, left positive), v = h (height, negative below)
  double wmax = 0;           // half-width: max |b| (seed §4.1)
  double hmax = 0;           // highest h >= 0
  double dmax = 0;           // deepest -h >= 0
  bool symmetric = false;    // mirror image of itself about b = 0
};

struct Material {
  std::string name;
  double albedo[3] = {0.5, 0.5, 0.5};
  double specular[3] = {0, 0, 0};
  double shininess = 1;
  bool hasMirror = false;
  double mirror[3] = {0, 0, 0};
};

struct Perturbation {
  enum class Kind { None, Scale, Offset };
  Kind kind = Kind::None;
  double amplitude = 0;
  double wavelength = 1;
  double phase = 0;
  bool operator==(const Perturbation&) const = default;
};

struct Primitive {
  enum class Kind { Segment, Arc };
  Kind kind = Kind::Segment;
  Vec2 a, b;               // segment end points; for an arc, its start and end points
  Vec2 centre;             // arc only
  double radius = 0;       // arc only
  double startAngle = 0;   // arc only, radians
  double sweep = 0;        // arc only, radians, counter-clockwise positive
  std::size_t groove = 0;
  double arcStart = 0;     // arc length along the groove at the start of this primitive
  double length = 0;
  bool cornerAtStart = false;  // the tangent turns at the start joint (never for the first primitive)
  bool endAtStart = false;     // the groove ends (open cut) at the start of this primitive
  bool endAtEnd = false;

  Vec2 pointAt(double t) const;    // t in [0, 1] along the primitive
  Vec2 tangentAt(double t) const;  // unit tangent
};

struct Groove {
  std::string name;
  std::size_t profile = 0;
  std::size_t material = 0;
  Perturbation perturbation;
  std::size_t firstPrimitive = 0;
  std::size_t primitiveCount = 0;
  bool closed = false;
  double wmax = 0, hmax = 0, dmax = 0;  // the profile's bounds enlarged by the perturbation
};

struct GrooveScene {
  std::string units;
  double domain[2] = {1, 1};
  bool wrapRepeat = false;
  double flatteningTolerance = 0;
  std::vector<Profile> profiles;
  std::vector<Material> materials;
  std::size_t baseMaterial = 0;
  std::vector<Groove> grooves;
  std::vector<Primitive> primitives;
  double wmax = 0, hmax = 0, dmax = 0;  // over the scene, perturbation included
  std::vector<std::string> warnings;
  std::string source;
  std::vector<std::string> files;  // other files the scene read (SVG drawings), for depfiles
};

Result<GrooveScene> readGrooveScene(const std::string& path);
// `directory`: the folder the scene's relative file names (svgFile) are resolved against; null for a
// scene that did not come from a file, which then may not name any.
Result<GrooveScene> parseGrooveScene(const std::string& jsonText, const std::string& source,
                                     const std::filesystem::path* directory = nullptr);

// Stages (one file each); used by the reader and by the tests.

// A groove's path before flattening: a list of pieces, each a curve of one kind.
using PathPiece = planar::PathPiece;

// Profile checks and derived bounds (validate.cpp). `where` names the profile for messages.
Status validateProfile(Profile& profile, const std::string& source);
// Bounds of a groove: the profile's enlarged by its perturbation (validate.cpp).
void grooveBounds(const Profile& profile, const Perturbation& perturbation, double& wmax, double& hmax, double& dmax);

// Flattens pieces into primitives appended to `out` (flatten.cpp). Curvature radius below
// `minRadius` is an error naming the piece index and (u, v); `label` names the groove.
Status flattenPath(const std::vector<PathPiece>& pieces, double tolerance, double minRadius, std::size_t grooveIndex,
                   const std::string& label, const std::string& source, std::vector<Primitive>& out);

// Checks chains (zero length) and merges duplicate grooves with a warning (validate.cpp).
Status finishScene(GrooveScene& scene);

}  // namespace bake::grooves
