// Stroke generators: strokes grown on a mesh (fur and grass, seed 002's furry models) and a small
// branching tree (fine branches and twigs), both deterministic for a given seed. A stroke list
// (formats/paintstroke-input.md) names them in its "generators" array; strokebake also grows on a
// mesh given directly as its input. grow.cpp and tree.cpp implement them; generators.cpp reads their
// JSON objects.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "bake/core/limits.h"
#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "bake/paintstrokes/model.h"

namespace bake::paintstrokes {

// Strokes grown on a mesh: `count` roots scattered over the surface with probability proportional to
// triangle area (barycentric sampling), each grown along the interpolated normal and bent towards
// `bendDirection` by `bend` (0 straight, 1: the tip is displaced by the whole length), radius tapering
// from `radius` to `radius * tipRadius`. Length, radius and colour are scaled by vertex attributes
// (glTF COLOR_0, scalar attributes such as _LENGTH, and _RADIUS when present; other mesh formats carry none) or sampled from textures at the root's
// TEXCOORD_0 when asked. Global normal = the root's normal, depth = 1 at the root falling to 0 at the tip.
struct GrowSettings {
  std::string mesh;                 // .obj .ply .off .stl .gltf .glb
  std::size_t count = 10000;
  double length = 0.05;             // model units
  double radius = 0.002;            // at the root, model units
  double tipRadius = 0.25;          // tip radius / root radius
  double bend = 0.3;
  Vec3d bendDirection{0, -1, 0};
  int pointsPerStroke = 5;          // >= 2
  Vec3d rootColour{0.35, 0.22, 0.12};
  Vec3d tipColour{0.8, 0.62, 0.4};
  double jitter = 0.2;              // relative random variation of length and direction
  std::string lengthFrom;           // "", "vertex:NAME" (a scalar attribute) or "texture:PATH" (red channel)
  std::string colourFrom;           // "", "vertex" (COLOR_0 / vertex colours) or "texture:PATH"
  std::size_t style = 0;
  std::uint64_t seed = 1;
};

// A small tree: a trunk that splits recursively into `depth` levels of branches (each a stroke of a
// few control points with a gentle random curve, radius shrinking by `radiusRatio` per level), with
// twigs at the last level; `crown` sets global normals and depths for self-shadowing from the crown's
// bounding sphere (normal = away from its centre, depth = 1 - distance / crown radius).
struct TreeSettings {
  int depth = 6;
  int branching = 3;                // children per branch
  double height = 1.0;              // trunk length, model units
  double trunkRadius = 0.04;
  double lengthRatio = 0.72;
  double radiusRatio = 0.62;
  double spreadDegrees = 35;
  int pointsPerStroke = 5;
  Vec3d barkColour{0.30, 0.22, 0.15};
  Vec3d twigColour{0.35, 0.45, 0.20};
  Vec3d origin{0, 0, 0};            // the foot of the trunk, which grows along +y
  std::size_t style = 0;
  std::uint64_t seed = 1;
};

// The most strokes one generator may make (a count check before anything is allocated: a typo of a
// few zeros must fail at once, not exhaust memory).
inline constexpr std::uint64_t kMaxGeneratedStrokes = 10'000'000;

// The settings' own checks (bad values are invalid input whose element is the field's name, as in
// the JSON: "count", "tipRadius", ...). growOnMesh and growTree's callers run them; runGenerator
// names the entry as well ("generators[2].count").
Status checkGrowSettings(const GrowSettings& settings);
Status checkTreeSettings(const TreeSettings& settings);
// Strokes of a tree: the trunk and branching^level branches at each level 1..depth.
std::uint64_t treeStrokeCount(const TreeSettings& settings);

Result<StrokeSet> growOnMesh(const GrowSettings& settings, const Budgets& budgets, glb::Mesh* grownOn = nullptr);
// `settings` must pass checkTreeSettings.
StrokeSet growTree(const TreeSettings& settings);

// One entry of an input's "generators" array: {"type": "grow", "mesh": PATH (relative to the input
// file), ...GrowSettings fields} or {"type": "tree", ...TreeSettings fields}; the strokes it makes are
// appended to `into` (styles by index into into.styles). `where` names the entry in messages; the mesh
// read is appended to `inputs` (for the depfile) and, when `grownOn` is given, returned there.
Status runGenerator(const nlohmann::json& entry, const std::filesystem::path& inputDirectory, const Location& where,
                    const Budgets& budgets, StrokeSet& into, std::vector<std::string>& inputs,
                    std::optional<glb::Mesh>* grownOn);

// The files an entry reads (a grow entry's mesh and textures, resolved as runGenerator resolves them),
// without reading them: the inputs --print-inputs and the cache key name. None for an invalid entry.
std::vector<std::string> generatorFiles(const nlohmann::json& entry, const std::filesystem::path& inputDirectory);

}  // namespace bake::paintstrokes
