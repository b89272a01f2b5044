// The far level of the groove grid: what a footprint that covers more primitives than the runtime's
// shader can hold (bake_formats/grooves.h kMaxFoundPerFootprint) is shaded from, instead of dropping
// the grooves past the cap. Seen from far enough that a pixel covers many grooves, the seed's line
// sample of the footprint (§5) tends to the area average of the surface's radiance; grooves whose
// bands do not overlap and that rise nowhere above the base plane do not see each other, so that
// average is the flat base plus, per groove, its band's share of the footprint times the difference
// between its band's own line-sampled radiance (its walls' masking, shadowing and bounces, §5 and §7)
// and the flat base.
//
// The level keeps, per class of grooves (profile, material and direction, binned), a summed-area
// table of the band area (centre-line length times 2 wmax) over a uniform grid of the domain, so the
// share of every class under any axis-aligned box costs four lookups whatever the number of grooves
// under it. Not in the seed; the approximations are stated in formats/grooves.md ("The far level").
#pragma once

#include <cstdint>
#include <vector>

#include "grooves/input/scene.h"

namespace bake::grooves {

struct FarClass {
  std::uint32_t profile = 0, material = 0;
  std::uint32_t representative = 0;  // a primitive of the class (a segment where there is one)
  Vec2 direction;                    // unit: the band-area weighted mean tangent of the class
  double halfWidth = 0;              // the profile's wmax
};

struct FarLevel {
  std::uint32_t cells[2] = {0, 0};  // columns (u), rows (v) over the domain
  Vec2 cellSize;
  std::vector<FarClass> classes;
  // Per class, (cells[0] + 1) x (cells[1] + 1) nodes (u fastest): the band area of the class in the
  // cells below and left of the node, in domain units squared.
  std::vector<double> table;

  bool empty() const { return classes.empty(); }
  std::size_t nodesPerClass() const { return std::size_t(cells[0] + 1) * (cells[1] + 1); }
  // The band area of class `c` in the box [lower, upper] (domain coordinates; beyond the domain the
  // pattern repeats when `wrapRepeat`, else there is none), bilinear within cells.
  double bandArea(std::size_t c, Vec2 lower, Vec2 upper, bool wrapRepeat) const;
};

// Direction bins per half turn; a class of an asymmetric profile also keeps its orientation.
inline constexpr int kFarDirectionBins = 16;
// Classes kept (more are merged by coarser direction bins first) and table entries over all classes
// (512 KiB: the example scene's 25 classes on its 203 x 203 grid would take 8.3 MB, and the tables
// at 2^18 and 2^22 entries gave the same far-level errors in the tests and bench/groove).
inline constexpr std::size_t kMaxFarClasses = 32;
inline constexpr std::uint64_t kMaxFarTableEntries = std::uint64_t(1) << 16;

// The far level of a scene, on a grid of at most `maxCells` columns and rows (the groove grid's).
FarLevel buildFarLevel(const GrooveScene& scene, const std::uint32_t maxCells[2]);

}  // namespace bake::grooves
