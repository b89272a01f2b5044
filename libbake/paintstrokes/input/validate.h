// Checks and repairs a stroke set before it is baked (strokebake; formats/paintstroke-input.md,
// "What the reader refuses and repairs"). Errors (exit 3) name the file, the stroke and the control
// point; harmless degeneracies are repaired deterministically, with a warning, and counted.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/limits.h"
#include "bake/core/status.h"
#include "bake/paintstrokes/model.h"

namespace bake::paintstrokes {

struct ValidationCounts {
  std::size_t droppedPoints = 0;      // coincident with the point before them
  std::size_t normalisedNormals = 0;  // global normals that were not unit
};

// Relative distance below which consecutive control points count as coincident (x the stroke's extent).
inline constexpr double kCoincidentRelative = 1e-9;
// Positions and radii beyond this are refused: the package stores fp32 boxes.
inline constexpr double kLargestValue = 1e30;

// `file` names the input in messages. The control-points budget is checked first.
Result<ValidationCounts> validateStrokes(StrokeSet& set, const std::string& file, Diagnostics& diagnostics);

// The names of the styles no stroke uses, in style order.
std::vector<std::string> unusedStyles(const StrokeSet& set);
// Removes the styles no stroke uses, renumbering the strokes' style indices (a set without strokes
// keeps its first style: a package holds at least one); returns the names removed.
std::vector<std::string> dropUnusedStyles(StrokeSet& set);

}  // namespace bake::paintstrokes
