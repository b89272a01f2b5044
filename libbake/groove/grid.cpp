// PLACEHOLDER (replaced by the grid build): keeps the library linking meanwhile.
#include "groove/grid.h"
namespace bake::groove {
Result<GrooveGrid> buildGrooveGrid(const GrooveScene&, const GridSettings&) { return internalError("grid: not yet"); }
void GrooveGrid::primitivesInBox(Vec2, Vec2, std::vector<std::uint32_t>& out) const { out.clear(); }
void GrooveGrid::recordsInBox(Vec2, Vec2, std::vector<std::uint32_t>& out) const { out.clear(); }
GridStats gridStats(const GrooveGrid&) { return {}; }
}  // namespace bake::groove
